#include "motion/stroke_clean.h"

#include "memory/carve.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

// A span on its line: the line is (a, b) (primitive, a > 0 or a == 0 < b) through offset
// c = b*x - a*y; along it, position t = a*x + b*y, from lo to hi.
struct LineKey {
  int64_t c, lo, hi;
  int32_t a, b;  // |a|, |b| < 2^(kCleanCoordBits + 1)
  uint32_t span;
  uint32_t hi_end;  // which end of the span (0: (x0, y0), 1: (x1, y1)) lies at hi
};

bool is_dot(const Segment2& s) { return s.x0 == s.x1 && s.y0 == s.y1; }

constexpr int64_t kCleanLimit = int64_t{1} << kCleanCoordBits;

bool in_budget(const Segment2& s) {
  const int32_t v[4] = {s.x0, s.y0, s.x1, s.y1};
  for (int32_t x : v)
    if (x <= -kCleanLimit || x >= kCleanLimit) return false;
  return true;
}

int64_t gcd(int64_t a, int64_t b) {
  while (b != 0) {
    const int64_t t = a % b;
    a = b;
    b = t;
  }
  return a;
}

LineKey key_of(const Segment2& s, uint32_t span) {
  int64_t a = int64_t{s.x1} - s.x0, b = int64_t{s.y1} - s.y0;
  const int64_t g = gcd(a < 0 ? -a : a, b < 0 ? -b : b);
  a /= g, b /= g;
  if (a < 0 || (a == 0 && b < 0)) a = -a, b = -b;
  LineKey k{b * s.x0 - a * s.y0,
            a * s.x0 + b * s.y0,
            a * s.x1 + b * s.y1,
            int32_t(a),
            int32_t(b),
            span,
            1};
  if (k.lo > k.hi) {
    const int64_t t = k.lo;
    k.lo = k.hi, k.hi = t, k.hi_end = 0;
  }
  return k;
}

bool key_less(const LineKey& p, const LineKey& q) {
  if (p.a != q.a) return p.a < q.a;
  if (p.b != q.b) return p.b < q.b;
  if (p.c != q.c) return p.c < q.c;
  if (p.lo != q.lo) return p.lo < q.lo;
  return p.span < q.span;
}

bool same_line(const LineKey& p, const LineKey& q) {
  return p.a == q.a && p.b == q.b && p.c == q.c;
}

void end_of(const Segment2& s, uint32_t end, int32_t* x, int32_t* y) {
  *x = end ? s.x1 : s.x0;
  *y = end ? s.y1 : s.y0;
}

// One run of overlapping spans on a line, keys[first, last): the union goes in the place of
// its first span (in input order), kept in that span's direction; the others become dots,
// which the compaction drops.
void merge_run(const LineKey* keys, uint32_t first, uint32_t last, uint32_t hi_span,
               uint32_t hi_end, Segment2* out, PathStats* st) {
  const LineKey* kept = keys + first;
  for (uint32_t k = first + 1; k < last; ++k) kept = keys[k].span < kept->span ? keys + k : kept;
  int32_t lx, ly, hx, hy;
  end_of(out[keys[first].span], 1 - keys[first].hi_end, &lx, &ly);
  end_of(out[hi_span], hi_end, &hx, &hy);
  for (uint32_t k = first; k < last; ++k) {
    Segment2& s = out[keys[k].span];
    if (keys[k].span != kept->span) s.x1 = s.x0, s.y1 = s.y0, ++st->overlaps_merged;
  }
  // In the kept span's direction: from lo to hi when its own (x0, y0) was its lo end.
  out[kept->span] = kept->hi_end == 1 ? Segment2{lx, ly, hx, hy} : Segment2{hx, hy, lx, ly};
}

// The length of an overlap of extent t along the line, in steps (rounded down): position
// differences of lattice points are multiples of a^2 + b^2.
uint64_t overlap_steps(const LineKey& line, int64_t t) {
  const int64_t a = line.a, b = line.b, k = t / (a * a + b * b);
  return length_floor(a * k, b * k);
}

void merge_overlaps(LineKey* keys, uint32_t m, Segment2* out, PathStats* st) {
  sort_total(keys, m, &key_less);
  for (uint32_t i = 0; i < m;) {
    int64_t hi = keys[i].hi;
    uint32_t hi_span = keys[i].span, hi_end = keys[i].hi_end, j = i + 1;
    // Strict overlap: a span starting where the run ends only touches it.
    while (j < m && same_line(keys[i], keys[j]) && keys[j].lo < hi) {
      // What this span draws again: from its start to the run's end or its own.
      st->overlap_length +=
          overlap_steps(keys[i], (keys[j].hi < hi ? keys[j].hi : hi) - keys[j].lo);
      if (keys[j].hi > hi) hi = keys[j].hi, hi_span = keys[j].span, hi_end = keys[j].hi_end;
      ++j;
    }
    if (j - i > 1) merge_run(keys, i, j, hi_span, hi_end, out, st);
    i = j;
  }
}

}  // namespace

size_t stroke_clean_bytes(uint32_t n) { return carve_round(size_t{n} * sizeof(LineKey)); }

Status clean_spans(Segment2* spans, uint32_t n, void* workspace, size_t workspace_bytes,
                   PathStats* st) {
  if (buffer_misaligned(workspace)) return Status::kMisalignedBuffer;
  Carver carve(workspace, workspace_bytes);
  LineKey* keys = carve.take<LineKey>(n);
  if (carve.short_) return Status::kWorkspaceTooSmall;
  uint32_t m = 0;
  for (uint32_t i = 0; i < n; ++i) {
    if (is_dot(spans[i]))
      ++st->dots_dropped;
    else if (in_budget(spans[i]))
      keys[m++] = key_of(spans[i], i);
  }
  merge_overlaps(keys, m, spans, st);
  return Status::kOk;
}

}  // namespace haloplot
