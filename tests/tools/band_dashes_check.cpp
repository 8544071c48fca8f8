// band_dashes_check WHOLE.trace BANDED.trace: does a banded plot draw the whole-model plot's
// strokes? Written from the trace format alone (docs/formats.md, text version 2), sharing nothing
// with the code that plots: each trace is replayed move by move (a `b` line is one straight move
// of the carriage; its `s` lines only time it), and the moves made with the pen down are kept,
// in plot steps.
//
// A banded plot cuts strokes at the bands' borders and a whole-model plot may cut them where the
// pieces of an edge meet, so neither trace's moves are the picture's strokes as such. Both sets
// are cut at every stroke end of either trace that lies on a move (within a step of it, more
// than a step from its ends): the two are then the same pieces, each with a piece of the other
// trace whose ends lie within one step of its own, one to one (a largest matching). A dash that
// starts or ends elsewhere in one plot (a short dash, a long gap, a phase restarted at a border)
// leaves a piece without its partner, and so does a stroke drawn twice or left out. Where an
// edge runs within a step of a nearly parallel one, the cuts can leave a few pieces whose ends
// lie a little over a step apart; those must then be the same ink on both sides (unpaired()
// and first_uncovered(), below).
//
// "A step" is a plot step, or a motor step where that is coarser (`steps 1/4`): the motors put
// the pen on their own whole steps only, and an end a plot step away in the other plot may round
// to the next motor step.
//
// Prints the counts and the worst end distance; exit status 1 when the drawings differ.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace {

struct Pt {
  double x, y;
};
struct Seg {
  Pt a, b;
};

struct Drawing {
  std::vector<Seg> moves;  // pen-down moves, in plot steps
  uint32_t pen_downs = 0;
  int64_t steps_num = 1, steps_den = 1;  // the `steps` line: motor steps per plot step
  std::string error;
};

Drawing read_trace(const std::string& path) {
  Drawing d;
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line) || line != "haloplot-trace 2") {
    d.error = path + ": not a text trace, version 2";
    return d;
  }
  bool corexy = false, pen = false, in_move = false;
  int64_t num = 1, den = 1;
  int64_t m[2] = {0, 0};
  int dom = 0, dir[2] = {1, 1};
  int64_t major = 0, minor = 0, events = 0;
  auto plot = [&](const int64_t* p) {
    double x = double(p[0]), y = double(p[1]);
    if (corexy) {  // motor 0 = x + y, motor 1 = x - y
      x = double(p[0] + p[1]) / 2;
      y = double(p[0] - p[1]) / 2;
    }
    return Pt{x * double(den) / double(num), y * double(den) / double(num)};
  };
  auto finish = [&]() {
    if (!in_move) return;
    in_move = false;
    if (events != major) d.error = path + ": a move's events do not add up to MAJOR";
    const Pt from = plot(m);
    m[dom] += dir[dom] * major;
    m[1 - dom] += dir[1 - dom] * minor;
    const Pt to = plot(m);
    if (pen && (from.x != to.x || from.y != to.y)) d.moves.push_back({from, to});
  };
  while (std::getline(in, line)) {
    std::istringstream f(line);
    std::string k;
    f >> k;
    if (k == "b") {
      finish();
      std::string dirs;
      f >> dom >> major >> minor >> dirs;
      if (!f || dom < 0 || dom > 1 || dirs.size() != 2) d.error = path + ": bad line: " + line;
      dir[0] = dirs[0] == '-' ? -1 : 1;
      dir[1] = dirs[1] == '-' ? -1 : 1;
      events = 0;
      in_move = true;
    } else if (k == "s") {
      int64_t count = 0;
      f >> count;
      events += count;
    } else if (k == "p") {
      finish();
      std::string tick, state;
      f >> tick >> state;
      pen = state == "down";
      if (pen) ++d.pen_downs;
    } else if (k == "kinematics") {
      std::string v;
      f >> v;
      corexy = v == "corexy";
    } else if (k == "steps") {
      char slash = 0;
      f >> num >> slash >> den;
      if (num < 1 || den < 1 || slash != '/') d.error = path + ": bad steps line";
      d.steps_num = num;
      d.steps_den = den;
    } else if (k == "backlash") {
      int64_t a = 0, b = 0;
      f >> a >> b;
      if (a != 0 || b != 0) d.error = path + ": backlash take-ups are not replayed here";
    } else if (k == "end") {
      finish();
    }
  }
  finish();
  // With `finish home` the plot ends at the origin: a check on this replay.
  if (m[0] != 0 || m[1] != 0) d.error = path + ": the replay does not end at the origin";
  return d;
}

double dist(Pt p, Pt q) { return std::hypot(p.x - q.x, p.y - q.y); }

// How far apart two stroke ends are, as a plotter places them: the larger of the x and y
// distances. Each axis puts the pen on its own steps, so "within a step" is within a step in x
// and in y; a stroke end one plot cuts where the other plot's stroke runs on (a border beside
// the end of a nearly parallel edge) can lie a step away in x and most of a step in y.
double apart(Pt p, Pt q) { return std::max(std::fabs(p.x - q.x), std::fabs(p.y - q.y)); }

// A step, in plot steps: 1, or den / num with `steps num/den` below 1 (main sets it from the
// traces). Two ends a plot step apart can round to positions a motor step apart on each motor:
// on CoreXY both motors one step over moves the pen den / num plot steps in x or in y. The
// tolerances, in steps:
double step = 1.0;
double end_tol = 1.0;   // one step
double cell_size = 16;  // the grid of stroke ends: 16 steps
double bend_tol = 1.5;  // joined(), below

int64_t cell_key(double x, double y) {
  const int64_t cx = int64_t(std::floor(x / cell_size)), cy = int64_t(std::floor(y / cell_size));
  return (cx + (int64_t{1} << 30)) * (int64_t{1} << 31) + (cy + (int64_t{1} << 30));
}

// Stroke ends, by grid cell.
struct Ends {
  std::vector<Pt> points;
  std::unordered_map<int64_t, std::vector<uint32_t>> cells;
  void add(Pt p) {
    points.push_back(p);
    cells[cell_key(p.x, p.y)].push_back(uint32_t(points.size() - 1));
  }
  bool near(Pt p) const {
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        const auto c = cells.find(cell_key(p.x + dx * cell_size, p.y + dy * cell_size));
        if (c == cells.end()) continue;
        for (uint32_t j : c->second)
          if (dist(points[j], p) <= end_tol) return true;
      }
    return false;
  }
};

Ends move_ends(const std::vector<Seg>& moves) {
  Ends e;
  for (const Seg& m : moves) {
    e.add(m.a);
    e.add(m.b);
  }
  return e;
}

// A drawing's strokes: its moves joined where exactly two of them meet, the other drawing has no
// move ending within a step (a vertex both have stays a stroke end however straight the edges
// run on through it), and the point, with every point joined before, lies within bend_tol (1.5
// steps) of the joined stroke's chord (a border's cut, rounded to a step: each end is within
// half a step of the true line in x and y).

double off_chord(Pt a, Pt b, Pt p) {
  const double len = dist(a, b);
  if (len == 0) return dist(a, p);
  return std::fabs((p.y - a.y) * (b.x - a.x) - (p.x - a.x) * (b.y - a.y)) / len;
}

std::vector<Seg> joined(const std::vector<Seg>& moves, const Ends& other) {
  struct Stroke {
    Pt a, b;
    std::vector<Pt> inside;
    bool alive = true;
  };
  std::vector<Stroke> st;
  std::map<std::pair<double, double>, std::vector<uint32_t>> at;  // strokes ending there
  for (const Seg& m : moves) {
    st.push_back({m.a, m.b, {}, true});
    at[{m.a.x, m.a.y}].push_back(uint32_t(st.size() - 1));
    at[{m.b.x, m.b.y}].push_back(uint32_t(st.size() - 1));
  }
  for (auto& [key, ids] : at) {
    const Pt p{key.first, key.second};
    if (ids.size() != 2 || ids[0] == ids[1] || other.near(p)) continue;
    Stroke &s = st[ids[0]], &t = st[ids[1]];
    const Pt from = s.a.x == p.x && s.a.y == p.y ? s.b : s.a;
    const Pt to = t.a.x == p.x && t.a.y == p.y ? t.b : t.a;
    bool straight = off_chord(from, to, p) <= bend_tol &&
                    (to.x - p.x) * (p.x - from.x) + (to.y - p.y) * (p.y - from.y) > 0;
    for (const Pt& q : s.inside) straight = straight && off_chord(from, to, q) <= bend_tol;
    for (const Pt& q : t.inside) straight = straight && off_chord(from, to, q) <= bend_tol;
    if (!straight) continue;
    const uint32_t gone = ids[1], kept = ids[0];
    s.inside.insert(s.inside.end(), t.inside.begin(), t.inside.end());
    s.inside.push_back(p);
    s.a = from;
    s.b = to;
    t.alive = false;
    for (uint32_t& id : at[{to.x, to.y}])  // t's far end is s's now
      if (id == gone) id = kept;
    ids.clear();
  }
  std::vector<Seg> out;
  for (const Stroke& s : st)
    if (s.alive) out.push_back({s.a, s.b});
  return out;
}

// The moves cut at every stroke end within a step of them (more than a step from their ends).
std::vector<Seg> cut(const std::vector<Seg>& moves, const Ends& ends) {
  std::vector<Seg> out;
  std::vector<uint32_t> stamp(ends.points.size(), UINT32_MAX);
  for (uint32_t i = 0; i < moves.size(); ++i) {
    const Seg& s = moves[i];
    const double len = dist(s.a, s.b), ux = (s.b.x - s.a.x) / len, uy = (s.b.y - s.a.y) / len;
    std::vector<double> at;
    const int samples = int(len / cell_size) + 1;
    for (int k = 0; k <= samples; ++k) {
      const double u = len * k / samples;
      const double x = s.a.x + ux * u, y = s.a.y + uy * u;
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy) {
          const auto c = ends.cells.find(cell_key(x + dx * cell_size, y + dy * cell_size));
          if (c == ends.cells.end()) continue;
          for (uint32_t j : c->second) {
            if (stamp[j] == i) continue;
            stamp[j] = i;
            const Pt p = ends.points[j];
            const double along = (p.x - s.a.x) * ux + (p.y - s.a.y) * uy;
            const double off = std::fabs((p.y - s.a.y) * ux - (p.x - s.a.x) * uy);
            if (off <= end_tol && along > end_tol && along < len - end_tol) at.push_back(along);
          }
        }
    }
    // One cut for a run of ends each within a step of the next, at their mean: where one
    // drawing's end lies beside another stroke's end (a border beside a dash end, a step
    // apart), the mean is within a step of both, wherever the stroke comes from.
    std::sort(at.begin(), at.end());
    Pt from = s.a;
    for (size_t k = 0; k < at.size();) {
      size_t e = k + 1;
      double sum = at[k];
      while (e < at.size() && at[e] - at[e - 1] <= end_tol) sum += at[e++];
      const double u = sum / double(e - k);
      k = e;
      const Pt p{s.a.x + ux * u, s.a.y + uy * u};
      out.push_back({from, p});
      from = p;
    }
    out.push_back({from, s.b});
  }
  return out;
}

// The pieces of two drawings paired one to one, each with a piece of the other whose ends lie
// within a step of its own (either way round); the unpaired ones of each listed, the worst paired
// distance in *worst. The pairing is a largest one (augmenting paths, Kuhn's method), not the
// nearest partner first: where two strokes run within a step of each other (an edge beside a
// nearly parallel dashed edge), a piece may pair with either, and taking the nearer one can leave
// the other drawing's piece without the partner it had. A piece no longer than a step (a dot: a
// band's sliver of an edge by a vertex) may go unpaired if both its ends lie within a step of a
// stroke end of the other drawing; *dots counts those.
struct Unpaired {
  std::vector<Seg> a, b;
};

double end_distance(const Seg& s, const Seg& t) {
  return std::min(std::max(apart(s.a, t.a), apart(s.b, t.b)),
                  std::max(apart(s.a, t.b), apart(s.b, t.a)));
}

// For each piece of `a`, the pieces of `b` whose ends lie within a step of its own, nearest
// first.
std::vector<std::vector<uint32_t>> partners(const std::vector<Seg>& a, const std::vector<Seg>& b) {
  std::unordered_map<int64_t, std::vector<uint32_t>> by_end;
  for (uint32_t j = 0; j < b.size(); ++j) {
    by_end[cell_key(b[j].a.x, b[j].a.y)].push_back(j);
    by_end[cell_key(b[j].b.x, b[j].b.y)].push_back(j);
  }
  std::vector<std::vector<uint32_t>> out(a.size());
  for (uint32_t i = 0; i < a.size(); ++i) {
    const Seg& s = a[i];
    std::vector<std::pair<double, uint32_t>> near;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        const auto c = by_end.find(cell_key(s.a.x + dx * cell_size, s.a.y + dy * cell_size));
        if (c == by_end.end()) continue;
        for (uint32_t j : c->second) {
          const double d = end_distance(s, b[j]);
          if (d <= end_tol) near.push_back({d, j});
        }
      }
    std::sort(near.begin(), near.end());
    for (const auto& [d, j] : near)
      if (out[i].empty() || std::find(out[i].begin(), out[i].end(), j) == out[i].end())
        out[i].push_back(j);
  }
  return out;
}

// One augmenting path from piece i of `a` (depth-first; `seen` marks the pieces of `b` tried).
bool augment(uint32_t i, const std::vector<std::vector<uint32_t>>& cand,
             std::vector<uint32_t>& owner, std::vector<uint32_t>& seen, uint32_t round) {
  for (uint32_t j : cand[i]) {
    if (seen[j] == round) continue;
    seen[j] = round;
    if (owner[j] == UINT32_MAX || augment(owner[j], cand, owner, seen, round)) {
      owner[j] = i;
      return true;
    }
  }
  return false;
}

Unpaired unpaired(const std::vector<Seg>& a, const std::vector<Seg>& b, const Ends& a_ends,
                  const Ends& b_ends, double* worst, size_t* dots) {
  const std::vector<std::vector<uint32_t>> cand = partners(a, b);
  std::vector<uint32_t> owner(b.size(), UINT32_MAX), seen(b.size(), UINT32_MAX);
  for (uint32_t i = 0; i < a.size(); ++i) augment(i, cand, owner, seen, i);
  std::vector<bool> paired_a(a.size(), false);
  for (uint32_t j = 0; j < b.size(); ++j)
    if (owner[j] != UINT32_MAX) {
      paired_a[owner[j]] = true;
      *worst = std::max(*worst, end_distance(a[owner[j]], b[j]));
    }
  Unpaired left;
  auto leftover = [dots](const Seg& s, bool paired, const Ends& other_ends, std::vector<Seg>* out) {
    if (paired) return;
    if (dist(s.a, s.b) <= end_tol && other_ends.near(s.a) && other_ends.near(s.b))
      ++*dots;
    else
      out->push_back(s);
  };
  for (uint32_t i = 0; i < a.size(); ++i) leftover(a[i], paired_a[i], b_ends, &left.a);
  for (uint32_t j = 0; j < b.size(); ++j) leftover(b[j], owner[j] != UINT32_MAX, a_ends, &left.b);
  return left;
}

// The unpaired pieces of one drawing joined where two meet within a step and run on straight
// (each far end within bend_tol of the joined chord). A border's cut rounds both sides of a
// stroke to a step, so a stroke the other plot draws whole can be left here in pieces with a
// sub-step gap between them (and a cut at that gap, from a nearby end in the other plot); such
// pieces are one stroke. A gap of more than a step (a dash restarted at a border) stays a gap.
std::vector<Seg> rejoined(std::vector<Seg> left) {
  for (bool merged = true; merged;) {
    merged = false;
    for (size_t i = 0; i < left.size() && !merged; ++i)
      for (size_t j = i + 1; j < left.size() && !merged; ++j) {
        const Seg &s = left[i], &t = left[j];
        // Try the four ways round: s's end `p` meets t's end `q`.
        for (int k = 0; k < 4 && !merged; ++k) {
          const Pt from = k & 1 ? s.a : s.b, p = k & 1 ? s.b : s.a;
          const Pt q = k & 2 ? t.b : t.a, to = k & 2 ? t.a : t.b;
          if (apart(p, q) > end_tol) continue;
          const bool onward = (to.x - q.x) * (p.x - from.x) + (to.y - q.y) * (p.y - from.y) > 0;
          if (!onward || off_chord(from, to, p) > bend_tol || off_chord(from, to, q) > bend_tol)
            continue;
          left[i] = {from, to};
          left.erase(left.begin() + std::ptrdiff_t(j));
          merged = true;
        }
      }
  }
  return left;
}

// How far p lies from the segment s.
double to_segment(Pt p, const Seg& s) {
  const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y, len2 = dx * dx + dy * dy;
  double u = len2 == 0 ? 0 : ((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / len2;
  u = std::clamp(u, 0.0, 1.0);
  return dist(p, Pt{s.a.x + u * dx, s.a.y + u * dy});
}

// The first piece of `a` with a point (every half step along it, ends included) more than a
// step from every piece of `b`; `a`'s size when there is none.
size_t first_uncovered(const std::vector<Seg>& a, const std::vector<Seg>& b) {
  for (size_t i = 0; i < a.size(); ++i) {
    const Seg& s = a[i];
    const int n = int(dist(s.a, s.b) / (step / 2)) + 1;
    for (int k = 0; k <= n; ++k) {
      const Pt p{s.a.x + (s.b.x - s.a.x) * k / n, s.a.y + (s.b.y - s.a.y) * k / n};
      bool near = false;
      for (const Seg& t : b) near = near || to_segment(p, t) <= end_tol;
      if (!near) return i;
    }
  }
  return a.size();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: band_dashes_check WHOLE.trace BANDED.trace\n");
    return 2;
  }
  const Drawing w = read_trace(argv[1]), b = read_trace(argv[2]);
  for (const Drawing* d : {&w, &b})
    if (!d->error.empty()) {
      std::fprintf(stderr, "band_dashes_check: %s\n", d->error.c_str());
      return 2;
    }
  if (w.steps_num * b.steps_den != b.steps_num * w.steps_den) {
    std::fprintf(stderr, "band_dashes_check: the traces' motor steps per plot step differ\n");
    return 2;
  }
  step = std::max(1.0, double(w.steps_den) / double(w.steps_num));
  end_tol = step;
  cell_size = 16 * step;
  bend_tol = 1.5 * step;
  const std::vector<Seg> sw = joined(w.moves, move_ends(b.moves)),
                         sb = joined(b.moves, move_ends(w.moves));
  Ends ends;
  for (const auto* strokes : {&sw, &sb})
    for (const Seg& s : *strokes) {
      ends.add(s.a);
      ends.add(s.b);
    }
  const std::vector<Seg> pw = cut(sw, ends), pb = cut(sb, ends);
  double worst = 0;
  size_t dots = 0;
  const Ends ends_w = move_ends(sw), ends_b = move_ends(sb);
  Unpaired left = unpaired(pw, pb, ends_w, ends_b, &worst, &dots);
  // The leftovers, each side's joined across sub-step gaps, paired once more.
  const size_t first_w = left.a.size(), first_b = left.b.size();
  if (!left.a.empty() || !left.b.empty())
    left = unpaired(rejoined(left.a), rejoined(left.b), ends_w, ends_b, &worst, &dots);
  const std::vector<Seg>&lw = left.a, &lb = left.b;
  // What is left unpaired must be the same ink in both, cut differently: where an edge runs
  // within a step of a nearly parallel one, the cuts at each other's ends can leave pieces whose
  // ends lie a little over a step apart. Each side's leftovers within a step of the other's,
  // every half step along them. A dash moved, a stroke left out or drawn twice leaves ink on one
  // side only.
  const size_t bare_w = first_uncovered(lw, lb), bare_b = first_uncovered(lb, lw);
  const bool same_ink = bare_w == lw.size() && bare_b == lb.size();
  std::printf(
      "whole: %zu pen-down moves in %u pen-downs, %zu strokes; banded: %zu moves in %u "
      "pen-downs, %zu strokes joined; %zu and %zu pieces cut at each other's ends (%zu dots); "
      "unpaired: %zu whole, %zu banded (%zu and %zu before joining leftovers across sub-step "
      "gaps), %s; worst end distance %.2f plot steps (a step: %g)\n",
      w.moves.size(), w.pen_downs, sw.size(), b.moves.size(), b.pen_downs, sb.size(), pw.size(),
      pb.size(), dots, lw.size(), lb.size(), first_w, first_b,
      same_ink ? "the same ink within a step" : "not the same ink", worst, step);
  int shown = 0;
  for (const auto* list : {&lw, &lb})
    for (size_t i = list == &lw ? bare_w : bare_b; i < list->size(); ++i)
      if (shown++ < 8)
        std::printf("  only in the %s plot: (%.1f, %.1f) - (%.1f, %.1f)\n",
                    list == &lw ? "whole-model" : "banded", (*list)[i].a.x, (*list)[i].a.y,
                    (*list)[i].b.x, (*list)[i].b.y);
  return same_ink ? 0 : 1;
}
