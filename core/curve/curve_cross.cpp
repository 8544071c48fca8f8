#include "haloplot/curve/curve_cross.h"

#include "memory/carve.h"
#include "sort/in_place_sort.h"

namespace haloplot {

namespace {

// ---- 128-bit helpers (budgets in curve/bezier.h) ----

Wide cross_w(int64_t ux, int64_t uy, int64_t vx, int64_t vy) {
  return mul_i64(ux, vy) - mul_i64(uy, vx);
}
int sign_w(Wide v) { return v.negative() ? -1 : (v.is_zero() ? 0 : 1); }
Wide abs_w(Wide v) { return v.negative() ? -v : v; }
Wide shl1(Wide v) {
  Wide r;
  r.hi = (v.hi << 1) | (v.lo >> 63);
  r.lo = v.lo << 1;
  return r;
}
uint64_t abs_u(int64_t v) { return v < 0 ? 0 - static_cast<uint64_t>(v) : uint64_t(v); }

// num / den as Q0.32 (floor, or ceiling) for 0 <= num, 0 < den < 2^126; 2^32 when num >= den.
// Restoring division: the remainder stays below den, so doubling it stays below 2^127.
uint64_t q32(Wide num, Wide den, bool ceiling) {
  if (!(num < den)) return kCurveParamOne;
  uint64_t q = 0;
  Wide rem = num;
  for (int i = 0; i < kCurveParamBits; ++i) {
    rem = shl1(rem);
    q <<= 1;
    if (!(rem < den)) {
      rem = rem - den;
      q |= 1;
    }
  }
  return (ceiling && !rem.is_zero()) ? q + 1 : q;
}

// a + floor(d * f / 2^32) for a coordinate a, |d| < 2^62 and f <= 2^32: the product is below
// 2^94, so the shifted value fits int64_t.
int64_t lerp_fix(int64_t a, int64_t d, uint64_t f) {
  const Wide p = mul_i64(d, static_cast<int64_t>(f));
  return a + static_cast<int64_t>((p.hi << 32) | (p.lo >> 32));
}

uint64_t clamp62(uint64_t v) {
  const uint64_t cap = uint64_t{1} << 62;
  return v > cap ? cap : v;
}

// ---- the run ----

struct PiecePair {
  CurvePiece a, b;
};
inline constexpr uint32_t kPairStack = 2 * kCurveMaxDepth + 2;
inline constexpr uint32_t kSelfStack = kCurveMaxDepth + 2;

struct Run {
  CurveCrossParams params;
  CurveHit* hits;
  uint32_t capacity;
  CurveCrossStats* stats;
  PiecePair* stack;        // kPairStack entries
  CurvePiece* self_stack;  // kSelfStack entries
};

// Ties: a chord end exactly on the other chord's line (or on the edge of a fat line) is
// decided by Simulation of Simplicity: one of the two curves is moved by an infinitesimal
// delta * w, w = (1, epsilon) with epsilon infinitesimal against delta. The moved one is the
// higher-numbered curve, or on one curve the piece later along it (so the pieces around one
// self-crossing all move the same way). Moving a whole curve is a real configuration, so the
// four pieces around a crossing at piece ends on both curves see it exactly once, and two
// collinear chords (an overlap) become parallel: no crossing.
// sign(cross(d, w)) = -sign(d.y), or sign(d.x) when d.y = 0 (0 for a zero chord).
int tie_sign(int64_t dx, int64_t dy) {
  if (dy != 0) return dy > 0 ? -1 : 1;
  return (dx > 0) - (dx < 0);
}
// +1 when b is the moved piece of the pair, -1 when a is.
int moved(const CurvePiece& a, const CurvePiece& b) {
  if (a.curve != b.curve) return a.curve < b.curve ? 1 : -1;
  return a.t_lo() < b.t_lo() ? 1 : -1;
}

// Pieces that meet at an end point V (a's end ia, b's end jb: 0 the start, 1 the end) where
// V is either curve's own end (curves joined end to start, a curve ending on another) or the
// same point of one curve (consecutive pieces). The meeting at V is never a crossing, but the
// pieces may still cross elsewhere (a curve folding back alongside a segment it ends on, a
// loop over consecutive pieces): such a pair is settled when the path through V is monotone,
// else halved until it is, or dropped at max_depth. Other meetings are left to the tie rule.
struct Shared {
  bool found = false;
  int ia = 0, jb = 0;
};
Shared shared_end(const CurvePiece& a, const CurvePiece& b) {
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const FixPoint3 &pa = a.p[3 * i], &pb = b.p[3 * j];
      if (pa.x != pb.x || pa.y != pb.y) continue;
      const bool a_end = i == 0 ? a.starts_curve() : a.ends_curve();
      const bool b_end = j == 0 ? b.starts_curve() : b.ends_curve();
      const uint64_t ta = i == 0 ? a.t_lo() : a.t_hi(), tb = j == 0 ? b.t_lo() : b.t_hi();
      if (a_end || b_end || (a.curve == b.curve && ta == tb)) return Shared{true, i, j};
    }
  }
  return Shared{};
}

// True when the path along a to its end ia, then along b from its end jb, is strictly monotone
// along the direction w from the path's first point to its last: every control vector
// P[i+1] - P[i] of both hodographs, taken in the path's direction, has a positive dot product
// with w (the derivative is a convex combination of them), so the path cannot cross itself.
// monotone_path(q, q, 1, 0) asks it of one piece.
bool monotone_path(const CurvePiece& a, const CurvePiece& b, int ia, int jb) {
  const FixPoint3& from = ia == 1 ? a.p[0] : a.p[3];
  const FixPoint3& to = jb == 0 ? b.p[3] : b.p[0];
  const int64_t wx = to.x - from.x, wy = to.y - from.y;
  const CurvePiece* both[2] = {&a, &b};
  const int64_t dir[2] = {ia == 1 ? 1 : -1, jb == 0 ? 1 : -1};
  for (int k = 0; k < 2; ++k) {
    const CurvePiece& p = *both[k];
    for (int i = 0; i < 3; ++i) {
      const int64_t dx = p.p[i + 1].x - p.p[i].x, dy = p.p[i + 1].y - p.p[i].y;
      if (p.straight && dx == 0 && dy == 0) continue;  // a segment's repeated points
      const Wide d = mul_i64(dir[k] * dx, wx) + mul_i64(dir[k] * dy, wy);
      if (d.negative() || d.is_zero()) return false;
    }
  }
  return true;
}

// True when every control point of b lies strictly on one side of a's fat line: the strip
// parallel to a's chord that holds all of a's control points. `shift` (+1 or -1) says how b
// moves against a under the tie rule.
bool fat_line_apart(const CurvePiece& a, const CurvePiece& b, int shift) {
  const int64_t dx = a.p[3].x - a.p[0].x, dy = a.p[3].y - a.p[0].y;
  if (dx == 0 && dy == 0) return false;
  const int tie = shift * tie_sign(dx, dy);
  Wide lo, hi;  // the chord's ends are at 0
  for (int i = 1; i < 3; ++i) {
    const Wide d = cross_w(dx, dy, a.p[i].x - a.p[0].x, a.p[i].y - a.p[0].y);
    if (d < lo) lo = d;
    if (hi < d) hi = d;
  }
  bool all_above = true, all_below = true;
  for (int i = 0; i < 4; ++i) {
    const Wide d = cross_w(dx, dy, b.p[i].x - a.p[0].x, b.p[i].y - a.p[0].y);
    if (!(hi < d || (d == hi && tie > 0))) all_above = false;
    if (!(d < lo || (d == lo && tie < 0))) all_below = false;
  }
  return all_above || all_below;
}

// The side of a chord end from the other chord's line, ties broken by the tie rule (`tie`),
// except at the curve's own end, where a zero is no side at all: a curve ending on another is
// a T-junction, not a crossing.
int side_of(Wide v, bool curve_end, int tie) {
  const int s = sign_w(v);
  return s != 0 ? s : (curve_end ? 0 : tie);
}

struct ChordCrossing {
  uint64_t s = 0, u = 0;            // along the pieces, Q0.32 (floor)
  uint64_t ds = 0, du = 0;          // the bounds |s* - s'|, |u* - u'|, Q0.32 (ceiling, saturated)
  int64_t za = 0, zb = 0;           // depth chords at s, u (Q20.42)
  int8_t sense = 0;                 // sign of cross(dA, dB): which way B crosses A
  uint64_t zerr_a = 0, zerr_b = 0;  // their error bounds
};

bool chord_cross(const CurvePiece& a, const CurvePiece& b, const Flatness& fa, const Flatness& fb,
                 ChordCrossing* c) {
  const FixPoint3 &a0 = a.p[0], &a1 = a.p[3], &b0 = b.p[0], &b1 = b.p[3];
  const int64_t dax = a1.x - a0.x, day = a1.y - a0.y, dbx = b1.x - b0.x, dby = b1.y - b0.y;
  const Wide sa0 = cross_w(dbx, dby, a0.x - b0.x, a0.y - b0.y);
  const Wide sa1 = cross_w(dbx, dby, a1.x - b0.x, a1.y - b0.y);
  // b moves by shift * delta * w against a: a's ends, seen from b's line, move the other way.
  const int shift = moved(a, b);
  const int tie_a = -shift * tie_sign(dbx, dby), tie_b = shift * tie_sign(dax, day);
  if (side_of(sa0, a.starts_curve(), tie_a) * side_of(sa1, a.ends_curve(), tie_a) >= 0)
    return false;
  const Wide sb0 = cross_w(dax, day, b0.x - a0.x, b0.y - a0.y);
  const Wide sb1 = cross_w(dax, day, b1.x - a0.x, b1.y - a0.y);
  if (side_of(sb0, b.starts_curve(), tie_b) * side_of(sb1, b.ends_curve(), tie_b) >= 0)
    return false;
  // The side value falls linearly from sa0 to sa1 along A: s' = sa0 / (sa0 - sa1). Both
  // denominators are +/- cross(dA, dB), nonzero here.
  const Wide den_a = abs_w(sa0 - sa1), den_b = abs_w(sb0 - sb1);
  c->s = q32(abs_w(sa0), den_a, false);
  c->u = q32(abs_w(sb0), den_b, false);
  const uint64_t rx = fa.ex + fb.ex, ry = fa.ey + fb.ey;  // each < 2^63: the sum fits
  c->ds = q32(mul_u64(rx, abs_u(dby)) + mul_u64(ry, abs_u(dbx)), den_a, true);
  c->du = q32(mul_u64(rx, abs_u(day)) + mul_u64(ry, abs_u(dax)), den_b, true);
  const int64_t daz = a1.z - a0.z, dbz = b1.z - b0.z;
  c->za = lerp_fix(a0.z, daz, c->s);
  c->zb = lerp_fix(b0.z, dbz, c->u);
  // |dz| (Q20.42) times a Q0.32 bound, shifted back: below 2^62, plus the floor of s' (one
  // Q0.32 unit of dz, and one more for the floor in lerp_fix).
  const auto slope_err = [](int64_t dz, uint64_t d) {
    const Wide p = mul_u64(abs_u(dz), d);
    return ((p.hi << 32) | (p.lo >> 32)) + (abs_u(dz) >> 32) + 2;
  };
  c->zerr_a = clamp62(fa.ez + slope_err(daz, c->ds + 1));
  c->zerr_b = clamp62(fb.ez + slope_err(dbz, c->du + 1));
  c->sense = static_cast<int8_t>(sign_w(cross_w(dax, day, dbx, dby)));
  return true;
}

// A piece-local Q0.32 value on the whole curve's parameter.
uint64_t global_t(const CurvePiece& p, uint64_t s) { return p.t_lo() + (s >> p.level); }
uint64_t global_err(const CurvePiece& p, uint64_t ds) {
  return ((ds + (uint64_t{1} << p.level) - 1) >> p.level) + 2;
}

// Raw records keep (curve, t) <= (other, other_t).
CurveHit normalized(const CurveHit& h) {
  if (!(h.other < h.curve || (h.other == h.curve && h.other_t < h.t))) return h;
  CurveHit m = h;
  m.curve = h.other;
  m.other = h.curve;
  m.t = h.other_t;
  m.other_t = h.t;
  m.t_err = h.other_err;
  m.other_err = h.t_err;
  m.front = static_cast<int8_t>(-h.front);
  m.sense = static_cast<int8_t>(-h.sense);
  return m;
}

// Store a raw record, counting past capacity.
void store(Run& run, const CurveHit& h) {
  if (run.stats->raw < run.capacity) run.hits[run.stats->raw] = normalized(h);
  ++run.stats->raw;
}

void record_crossing(Run& run, const CurvePiece& a, const CurvePiece& b, const ChordCrossing& c) {
  CurveHit h;
  h.kind = CurveHitKind::kCrossing;
  h.curve = a.curve;
  h.other = b.curve;
  h.t = global_t(a, c.s);
  h.other_t = global_t(b, c.u);
  h.t_err = global_err(a, c.ds);
  h.other_err = global_err(b, c.du);
  const int64_t dz = c.za - c.zb;  // both in [0, 2^62): no overflow
  const uint64_t margin = c.zerr_a + c.zerr_b;
  h.front = abs_u(dz) <= margin ? 0 : (dz > 0 ? 1 : -1);
  h.sense = c.sense;
  store(run, h);
}

bool intervals_meet(uint64_t t1, uint64_t e1, uint64_t t2, uint64_t e2) {
  const uint64_t lo1 = t1 > e1 ? t1 - e1 : 0, lo2 = t2 > e2 ? t2 - e2 : 0;
  return lo1 <= t2 + e2 && lo2 <= t1 + e1;
}

// The interval t +/- e widened to hold t2 +/- e2 (both with t >= e: touches).
void hull(uint64_t* t, uint64_t* e, uint64_t t2, uint64_t e2) {
  const uint64_t lo1 = *t - *e, hi1 = *t + *e, lo2 = t2 - e2, hi2 = t2 + e2;
  const uint64_t lo = lo1 < lo2 ? lo1 : lo2, hi = hi1 > hi2 ? hi1 : hi2;
  *t = lo + (hi - lo) / 2;
  *e = hi - *t;
}

// The part of straight piece `seg` (as global parameters [lo, hi]) that the other piece's
// control points project onto: a touch with a long segment covers the segment only there.
void straight_span(const CurvePiece& seg, const CurvePiece& other, uint64_t* lo, uint64_t* hi) {
  const int64_t dx = seg.p[3].x - seg.p[0].x, dy = seg.p[3].y - seg.p[0].y;
  const Wide len2 = mul_i64(dx, dx) + mul_i64(dy, dy);
  *lo = kCurveParamOne;
  *hi = 0;
  for (int i = 0; i < 4; ++i) {
    const Wide d = mul_i64(dx, other.p[i].x - seg.p[0].x) + mul_i64(dy, other.p[i].y - seg.p[0].y);
    const uint64_t f = d.negative() || len2.is_zero() ? 0 : q32(d, len2, false);
    const uint64_t t = global_t(seg, f);
    *lo = t < *lo ? t : *lo;
    *hi = t + 1 > *hi ? t + 1 : *hi;
  }
}

// The interval a piece covers in a touch: all of a curve piece (at max_depth), or the span of
// a straight piece next to the other piece.
void touch_interval(const CurvePiece& p, const CurvePiece& other, uint64_t* t, uint64_t* e) {
  uint64_t lo = p.t_lo(), hi = p.t_hi();
  if (p.straight) straight_span(p, other, &lo, &hi);
  *t = lo + (hi - lo) / 2;
  *e = hi - *t;
}

// A touch covers both pieces' parameter intervals. A touch next to the previous raw touch of
// the same two curves extends it instead (a tangency met piece after piece).
void record_touch(Run& run, const CurvePiece& a, const CurvePiece& b) {
  CurveHit h;
  h.kind = CurveHitKind::kTouch;
  h.curve = a.curve;
  h.other = b.curve;
  touch_interval(a, b, &h.t, &h.t_err);
  touch_interval(b, a, &h.other_t, &h.other_err);
  h = normalized(h);
  const uint64_t raw = run.stats->raw;
  if (raw > 0 && raw <= run.capacity) {
    CurveHit& last = run.hits[raw - 1];
    if (last.kind == CurveHitKind::kTouch && last.curve == h.curve && last.other == h.other &&
        intervals_meet(last.t, last.t_err, h.t, h.t_err) &&
        intervals_meet(last.other_t, last.other_err, h.other_t, h.other_err)) {
      hull(&last.t, &last.t_err, h.t, h.t_err);
      hull(&last.other_t, &last.other_err, h.other_t, h.other_err);
      return;
    }
  }
  store(run, h);
}

bool can_split(const Run& run, const CurvePiece& p) {
  return !p.straight && p.level < run.params.max_depth;
}

// Pieces meeting at V (shared_end): settled when the path through V is monotone; else the less
// flat one is halved, so only the sub-pair at V stays a meeting pair, and the others are tested
// as usual. At max_depth a meeting pair is dropped: a fold or loop within a max_depth piece of
// V is not resolved.
bool shared_step(Run& run, const CurvePiece& a, const CurvePiece& b, const Shared& v,
                 bool* halve_a) {
  if (monotone_path(a, b, v.ia, v.jb)) return false;
  const bool split_a = can_split(run, a), split_b = can_split(run, b);
  if (!split_a && !split_b) return false;
  const Flatness fa = flatness(a), fb = flatness(b);
  const uint64_t wa = fa.ex > fa.ey ? fa.ex : fa.ey, wb = fb.ex > fb.ey ? fb.ex : fb.ey;
  *halve_a = split_a && (!split_b || wa >= wb);
  return true;
}

// One refinement step on (a, b): false when the pair is settled (nothing, a crossing or a
// touch recorded), true when it must be halved (*halve_a says which piece).
bool refine_step(Run& run, const CurvePiece& a, const CurvePiece& b, bool* halve_a) {
  ++run.stats->pair_visits;
  if (!overlap(box_of(a), box_of(b))) return false;
  const Shared shared = shared_end(a, b);
  if (shared.found) return shared_step(run, a, b, shared, halve_a);
  const int shift = moved(a, b);
  if (fat_line_apart(a, b, shift) || fat_line_apart(b, a, -shift)) return false;
  const Flatness fa = flatness(a), fb = flatness(b);
  const bool split_a = can_split(run, a), split_b = can_split(run, b);
  ChordCrossing c;
  if (chord_cross(a, b, fa, fb, &c)) {
    const bool tight =
        global_err(a, c.ds) <= run.params.t_tol && global_err(b, c.du) <= run.params.t_tol;
    if (tight || (!split_a && !split_b)) {
      record_crossing(run, a, b, c);
      return false;
    }
  } else if (!split_a && !split_b) {
    record_touch(run, a, b);
    return false;
  }
  const uint64_t wa = fa.ex > fa.ey ? fa.ex : fa.ey, wb = fb.ex > fb.ey ? fb.ex : fb.ey;
  *halve_a = split_a && (!split_b || wa >= wb);
  return true;
}

// Depth-first over the pair tree with an explicit stack (in scratch, not on the call stack):
// every halving raises one piece's level, so a path has at most 2 * max_depth halvings and
// the stack never holds more than kPairStack pairs.
void refine(Run& run, const CurvePiece& a, const CurvePiece& b) {
  PiecePair* stack = run.stack;
  uint32_t top = 0;
  stack[top++] = PiecePair{a, b};
  while (top > 0) {
    const PiecePair pair = stack[--top];
    bool halve_a = false;
    if (!refine_step(run, pair.a, pair.b, &halve_a)) continue;
    CurvePiece l, r;
    if (halve_a) {
      halve(pair.a, &l, &r);
      stack[top++] = PiecePair{r, pair.b};
      stack[top++] = PiecePair{l, pair.b};
    } else {
      halve(pair.b, &l, &r);
      stack[top++] = PiecePair{pair.a, r};
      stack[top++] = PiecePair{pair.a, l};
    }
  }
}

// A piece flat within flat_tol may still hold a loop smaller than that. A piece that is not
// monotone along its chord is halved, its halves refined as consecutive pieces, and each half
// checked the same way (depth first, on a stack of kSelfStack pieces in scratch).
void refine_self(Run& run, const CurvePiece& piece) {
  CurvePiece* stack = run.self_stack;
  uint32_t top = 0;
  stack[top++] = piece;
  while (top > 0) {
    const CurvePiece q = stack[--top];
    if (q.straight || monotone_path(q, q, 1, 0) || !can_split(run, q)) continue;
    CurvePiece l, r;
    halve(q, &l, &r);
    refine(run, l, r);
    stack[top++] = r;
    stack[top++] = l;
  }
}

// ---- pieces ----

template <typename Emit>
void flatten(const CurvePiece& p, const CurveCrossParams& params, Emit& emit) {
  const Flatness f = flatness(p);
  if (p.straight || p.level >= params.max_depth ||
      (f.ex <= params.flat_tol && f.ey <= params.flat_tol)) {
    emit(p);
    return;
  }
  CurvePiece l, r;
  halve(p, &l, &r);
  flatten(l, params, emit);
  flatten(r, params, emit);
}

template <typename Emit>
void for_each_piece(const BezierEdge3* curves, uint32_t nc, const Edge3* segments, uint32_t ns,
                    const CurveCrossParams& params, Emit& emit) {
  for (uint32_t i = 0; i < nc; ++i) flatten(whole_piece(curves[i], i), params, emit);
  for (uint32_t i = 0; i < ns; ++i) emit(segment_piece(segments[i], nc + i));
}

template <typename Carve>
void carve(Carve& c, uint32_t pieces, CurvePiece** p, FixBox** box, uint32_t** order,
           PiecePair** stack, CurvePiece** self_stack) {
  *p = c.template take<CurvePiece>(pieces);
  *box = c.template take<FixBox>(pieces);
  *order = c.template take<uint32_t>(pieces);
  *stack = c.template take<PiecePair>(kPairStack);
  *self_stack = c.template take<CurvePiece>(kSelfStack);
}

// Pair boxes by a sweep in x: each piece meets the pieces whose left edge is not past its
// right edge.
void sweep(Run& run, const CurvePiece* p, const FixBox* box, const uint32_t* order, uint32_t n) {
  // A piece flat within flat_tol may still hold a loop smaller than that: one that is not
  // monotone along its chord is halved and its halves refined as consecutive pieces.
  for (uint32_t i = 0; i < n; ++i) refine_self(run, p[i]);
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t a = order[i];
    for (uint32_t j = i + 1; j < n && box[order[j]].x0 <= box[a].x1; ++j) {
      const uint32_t b = order[j];
      if (!overlap(box[a], box[b]) || (p[a].straight && p[b].straight && !run.params.segment_pairs))
        continue;
      ++run.stats->box_pairs;
      refine(run, p[a], p[b]);
    }
  }
}

bool hit_less(const CurveHit& x, const CurveHit& y) {
  if (x.curve != y.curve) return x.curve < y.curve;
  if (x.t != y.t) return x.t < y.t;
  if (x.other != y.other) return x.other < y.other;
  return x.other_t < y.other_t;
}
bool pair_less(const CurveHit& x, const CurveHit& y) {
  if (x.curve != y.curve) return x.curve < y.curve;
  if (x.other != y.other) return x.other < y.other;
  if (x.t != y.t) return x.t < y.t;
  return x.other_t < y.other_t;
}

// The clusters of step 4, as they close. Crossing records are taken in order along the first
// curve; one with the same sense as the previous one is the same crossing seen again (two
// distinct crossings of two curves next to each other cross opposite ways), so only a change
// of sense counts a new crossing.
struct Cluster {
  uint64_t lo_a = 0, hi_a = 0, lo_b = 0, hi_b = 0;
  uint32_t crossings = 0;
  int8_t last_sense = 0;
  bool fronts_agree = true;
  CurveHit rep;  // the crossing with the smallest bound, or the first touch

  void start(const CurveHit& h) {
    *this = Cluster();
    rep = h;
    lo_a = h.t > h.t_err ? h.t - h.t_err : 0;
    hi_a = h.t + h.t_err;
    lo_b = h.other_t > h.other_err ? h.other_t - h.other_err : 0;
    hi_b = h.other_t + h.other_err;
    crossings = h.kind == CurveHitKind::kCrossing ? 1 : 0;
    last_sense = h.kind == CurveHitKind::kCrossing ? h.sense : 0;
  }
  bool takes(const CurveHit& h) const {
    return h.curve == rep.curve && h.other == rep.other && h.t <= hi_a + h.t_err &&
           lo_a <= h.t + h.t_err && h.other_t <= hi_b + h.other_err &&
           lo_b <= h.other_t + h.other_err;
  }
  void add(const CurveHit& h) {
    const uint64_t la = h.t > h.t_err ? h.t - h.t_err : 0;
    const uint64_t lb = h.other_t > h.other_err ? h.other_t - h.other_err : 0;
    lo_a = la < lo_a ? la : lo_a;
    hi_a = h.t + h.t_err > hi_a ? h.t + h.t_err : hi_a;
    lo_b = lb < lo_b ? lb : lo_b;
    hi_b = h.other_t + h.other_err > hi_b ? h.other_t + h.other_err : hi_b;
    if (h.kind != CurveHitKind::kCrossing) return;
    if (crossings == 0 || h.sense != last_sense) ++crossings;
    last_sense = h.sense;
    if (rep.kind != CurveHitKind::kCrossing) {
      rep = h;
      return;
    }
    if (h.front != rep.front) fronts_agree = false;
    const uint64_t eh = h.t_err > h.other_err ? h.t_err : h.other_err;
    const uint64_t er = rep.t_err > rep.other_err ? rep.t_err : rep.other_err;
    if (eh < er) rep = h;
  }
  CurveHit close() const {
    CurveHit out = rep;
    if (crossings % 2 == 1) {
      // One crossing: its parameter, with a bound that covers the whole cluster.
      const auto widen = [](uint64_t t, uint64_t e, uint64_t lo, uint64_t hi) {
        const uint64_t w = t - lo > hi - t ? t - lo : hi - t;
        return w > e ? w : e;
      };
      out.t_err = widen(out.t, out.t_err, lo_a, hi_a);
      out.other_err = widen(out.other_t, out.other_err, lo_b, hi_b);
      if (!fronts_agree) out.front = 0;
      // A crossing that may be at either curve's own end is an end-point meeting (a curve
      // ending on the other, or on itself): never a crossing, as at CUT's end points.
      if (out.t > out.t_err && out.t + out.t_err < kCurveParamOne && out.other_t > out.other_err &&
          out.other_t + out.other_err < kCurveParamOne)
        return out;
    }
    out.kind = CurveHitKind::kTouch;
    out.front = 0;
    out.sense = 0;
    out.t = lo_a + (hi_a - lo_a) / 2;
    out.t_err = hi_a - out.t;
    out.other_t = lo_b + (hi_b - lo_b) / 2;
    out.other_err = hi_b - out.other_t;
    return out;
  }
};

uint32_t cluster(CurveHit* hits, uint32_t n) {
  sort_in_place(hits, n, pair_less);
  uint32_t out = 0;
  Cluster c;
  for (uint32_t i = 0; i < n; ++i) {
    if (i > 0 && c.takes(hits[i])) {
      c.add(hits[i]);
      continue;
    }
    if (i > 0) hits[out++] = c.close();
    c.start(hits[i]);
  }
  if (n > 0) hits[out++] = c.close();
  return out;
}

}  // namespace

Status plan_curve_cross(const BezierEdge3* curves, uint32_t n_curves, const Edge3* segments,
                        uint32_t n_segments, const CurveCrossParams& params, CurveCrossPlan* plan) {
  *plan = CurveCrossPlan();
  if (params.max_depth > kCurveMaxDepth || params.t_tol == 0) return Status::kBadParameter;
  if (uint64_t{n_curves} + n_segments > kMaxCurveCount) return Status::kTooManyEdges;
  for (uint32_t i = 0; i < n_curves; ++i)
    if (!in_range(curves[i])) return Status::kCoordinateOutOfRange;
  for (uint32_t i = 0; i < n_segments; ++i)
    if (!in_range(segments[i])) return Status::kCoordinateOutOfRange;
  uint64_t pieces = 0;
  auto count = [&pieces](const CurvePiece&) { ++pieces; };
  for_each_piece(curves, n_curves, segments, n_segments, params, count);
  // The scratch size must fit size_t on a 32-bit target too.
  const uint64_t per_piece = sizeof(CurvePiece) + sizeof(FixBox) + sizeof(uint32_t) + 24;
  if (pieces > kMaxCurveCount || pieces > (SIZE_MAX - (uint64_t{1} << 16)) / per_piece)
    return Status::kTooManyEdges;
  plan->n_curves = n_curves;
  plan->n_segments = n_segments;
  plan->pieces = static_cast<uint32_t>(pieces);
  plan->params = params;
  ByteCounter bytes;
  CurvePiece* p;
  FixBox* box;
  uint32_t* order;
  PiecePair* stack;
  CurvePiece* self_stack;
  carve(bytes, plan->pieces, &p, &box, &order, &stack, &self_stack);
  plan->scratch_bytes = bytes.total;
  return Status::kOk;
}

Status run_curve_cross(const CurveCrossPlan& plan, const BezierEdge3* curves, const Edge3* segments,
                       void* scratch, size_t scratch_bytes, CurveHit* hits, uint32_t capacity,
                       uint32_t* n_hits, CurveCrossStats* stats) {
  *n_hits = 0;
  *stats = CurveCrossStats();
  Carver carver(scratch, scratch_bytes);
  CurvePiece* p;
  FixBox* box;
  uint32_t* order;
  PiecePair* stack;
  CurvePiece* self_stack;
  carve(carver, plan.pieces, &p, &box, &order, &stack, &self_stack);
  if (carver.short_) return Status::kWorkspaceTooSmall;
  uint32_t n = 0;
  auto keep = [&](const CurvePiece& piece) {
    box[n] = box_of(piece);
    order[n] = n;
    p[n++] = piece;
  };
  for_each_piece(curves, plan.n_curves, segments, plan.n_segments, plan.params, keep);
  stats->pieces = n;
  sort_in_place(order, n, [box](uint32_t a, uint32_t b) {
    return box[a].x0 != box[b].x0 ? box[a].x0 < box[b].x0 : a < b;
  });
  Run run{plan.params, hits, capacity, stats, stack, self_stack};
  sweep(run, p, box, order, n);
  if (stats->raw > capacity) {
    stats->needed = stats->raw;
    return Status::kCrossingCapacity;
  }
  const uint32_t c = cluster(hits, static_cast<uint32_t>(stats->raw));
  if (uint64_t{2} * c > capacity) {
    stats->needed = uint64_t{2} * c;
    return Status::kCrossingCapacity;
  }
  for (uint32_t i = 0; i < c; ++i) {
    CurveHit& m = hits[c + i];
    m = hits[i];
    m.curve = hits[i].other;
    m.other = hits[i].curve;
    m.t = hits[i].other_t;
    m.other_t = hits[i].t;
    m.t_err = hits[i].other_err;
    m.other_err = hits[i].t_err;
    m.front = static_cast<int8_t>(-hits[i].front);
    m.sense = static_cast<int8_t>(-hits[i].sense);
    if (hits[i].kind == CurveHitKind::kCrossing)
      ++stats->crossings;
    else
      ++stats->touches;
  }
  sort_in_place(hits, size_t{2} * c, hit_less);
  *n_hits = 2 * c;
  return Status::kOk;
}

}  // namespace haloplot
