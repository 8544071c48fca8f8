#include "cli/shells_note.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace haloplot::host {
namespace {

// A distance to two digits ("0.0004", "2.5e-05"); a coordinate to six, as files print them.
std::string number(double x, int digits = 2) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, x);
  return text;
}

// "its shell is WHAT", "all 3 shells are WHAT", "4 of 18 shells are WHAT".
std::string of_shells(uint32_t n, uint32_t shells, const std::string& what) {
  if (shells == 1) return "its shell is " + what;
  return (n == shells ? "all " : std::to_string(n) + " of ") + std::to_string(shells) + " shells " +
         (n == 1 ? "is " : "are ") + what;
}

// "1 side", "3 sides".
std::string count(uint32_t n, const std::string& one, const std::string& more) {
  return std::to_string(n) + " " + (n == 1 ? one : more);
}

// What welding at the hint's EPS would do instead of closing the gaps.
std::string trial_harm(const WeldHint& h) {
  const WeldTrial &b = h.before, &a = h.after;
  if (a.nonmanifold_sides > b.nonmanifold_sides)
    return "put " + count(a.nonmanifold_sides - b.nonmanifold_sides, "more side", "more sides") +
           " on 3+ faces";
  if (a.unorientable_shells > b.unorientable_shells)
    return "leave " +
           count(a.unorientable_shells - b.unorientable_shells, "more shell", "more shells") +
           " that cannot be oriented";
  return "close no open side";
}

const char* const kRight = "faces hide from both sides, so the hidden lines are right";

// The open shells' sentence.
std::string open_words(const std::string& path, const RepairReport& r, uint32_t open) {
  const std::string head = path + ": " + of_shells(open, r.shells, "open");
  if (!r.measured) return head + "; faces hide from both sides";
  const WeldHint& h = r.weld;
  const std::string eps = number(h.eps), weld = "--weld " + eps;
  const std::string near = count(h.within, "open corner lies", "open corners lie") + " within " +
                           eps + " of another open side's";
  const uint32_t dropped =
      h.after.dropped_faces - std::min(h.after.dropped_faces, h.before.dropped_faces);
  if (h.suggest)
    return head + ": " + weld + " would close " +
           (h.after.open_sides == 0 ? "all " + std::to_string(h.before.open_sides)
                                    : std::to_string(h.before.open_sides - h.after.open_sides) +
                                          " of their " + std::to_string(h.before.open_sides)) +
           " open sides (" + near +
           (dropped > 0 ? "; it drops " + count(dropped, "face", "faces") + " narrower than that"
                        : "") +
           ")";
  if (h.gaps)
    return head + ": " + near + ", but " + weld + " would " + trial_harm(h) + "; left as made, " +
           kRight;
  const std::string made = path + ": " + of_shells(open, r.shells, "open as made");
  if (h.near == 0)
    return made + ": no other open side's corner lies within 1/" +
           std::to_string(int(kGapBelowSide)) + " of a side's length, so no weld closes " +
           (open == 1 ? "it; " : "them; ") + kRight;
  return made + " (no common gap: " + weld + " would " + trial_harm(h) + "); " + kRight;
}

// Where the first shell that cannot be oriented shows it.
// `said`: the open shells' line said already that faces hide from both sides.
std::string unorientable_words(const std::string& path, const RepairReport& r, bool said) {
  const ShellProblem& p = r.problem;
  const uint32_t n = r.unorientable_shells;
  const std::string s =
      path + ": " +
      (r.shells == 1   ? "its shell"
       : n == r.shells ? "all " + std::to_string(n) + " shells"
                       : std::to_string(n) + " of " + std::to_string(r.shells) + " shells") +
      " cannot be oriented";
  const std::string what = p.faces_on_side > 2
                               ? "a side on " + std::to_string(p.faces_on_side) + " faces"
                               : "a twist (two faces wound the same way along "
                                 "their side)";
  // To the decimal place a world unit reaches (the file's digits, give or take the last).
  const int decimals = std::max(0, std::min(9, int(std::floor(-std::log10(p.unit)))));
  auto point = [&](const double q[3]) {
    std::string t = "(";
    for (int k = 0; k < 3; ++k) {
      char text[48];
      std::snprintf(text, sizeof text, "%.*f", decimals, q[k]);
      std::string c = text;
      if (c.find('.') != std::string::npos) c.erase(c.find_last_not_of('0') + 1);
      if (c.back() == '.') c.pop_back();
      if (c == "-0") c = "0";
      t += c + (k < 2 ? ", " : ")");
    }
    return t;
  };
  return s + ": " + what + " from " + point(p.from) + " to " + point(p.to) +
         (p.line > 0 ? ", of the face on line " + std::to_string(p.line) : "") +
         (said ? "" : "; faces hide from both sides");
}

// With --weld EPS given: what it did worse than the default weld, if anything.
std::string weld_words(const std::string& path, const RepairReport& r, const std::string& weld) {
  const WeldTrial &g = r.with_given, &d = r.with_default;
  std::string worse;
  auto add = [&](uint32_t given, uint32_t by_default, const std::string& one,
                 const std::string& more) {
    if (given <= by_default) return;
    worse += (worse.empty() ? "" : ", ") + count(given, one, more) +
             " (the default: " + std::to_string(by_default) + ")";
  };
  add(g.nonmanifold_sides, d.nonmanifold_sides, "side on 3+ faces", "sides on 3+ faces");
  add(g.unorientable_shells, d.unorientable_shells, "shell that cannot be oriented",
      "shells that cannot be oriented");
  add(g.open_sides, d.open_sides, "open side", "open sides");
  if (!r.compared || worse.empty()) return "";
  return path + ": --weld " + weld +
         " leaves more to mend than the default weld (no --weld): " + worse;
}

}  // namespace

std::string shells_note(const std::string& path, const RepairReport& r, const std::string& weld) {
  const uint32_t open = r.shells - r.closed_shells - r.unorientable_shells;
  std::string note;
  if (open > 0) note = open_words(path, r, open);
  if (r.unorientable_shells > 0)
    note += (note.empty() ? "" : "\nhaloplot: ") + unorientable_words(path, r, !note.empty());
  const std::string worse = weld_words(path, r, weld);
  if (!worse.empty()) note += (note.empty() ? "" : "\nhaloplot: ") + worse;
  return note;
}

std::string shells_stats(const RepairReport& r, double scale) {
  if (!r.measured) return "";
  const OpenSides& o = r.open;
  const WeldHint& h = r.weld;
  char text[640];
  const std::vector<double>& g = o.gaps;
  std::snprintf(text, sizeof text,
                "open_sides=%u\nopen_corners=%u\nnonmanifold_sides=%u\ntypical_side=%.6g\n"
                "partnered_corners=%zu\nnear_corners=%u\nnearest_gap=%.6g\nmedian_gap=%.6g\n"
                "weld_hint=%s\n",
                o.sides, o.corners, o.nonmanifold_sides, o.typical_side / scale, g.size(), h.near,
                g.empty() ? 0.0 : g.front() / scale, g.empty() ? 0.0 : g[g.size() / 2] / scale,
                h.tried ? number(h.eps).c_str() : "none");
  std::string s = text;
  if (h.tried) {
    std::snprintf(text, sizeof text,
                  "weld_hint_corners=%u\nweld_hint_gap_scale=%d\nweld_hint_suggested=%d\nweld_hint_"
                  "open_sides=%u\n"
                  "weld_hint_nonmanifold_sides=%u\nweld_hint_shells=%u\n"
                  "weld_hint_closed_shells=%u\nweld_hint_unorientable_shells=%u\n"
                  "weld_hint_dropped_faces=%u\n",
                  h.within, h.gaps ? 1 : 0, h.suggest ? 1 : 0, h.after.open_sides,
                  h.after.nonmanifold_sides, h.after.shells, h.after.closed_shells,
                  h.after.unorientable_shells, h.after.dropped_faces);
    s += text;
  }
  return s;
}

}  // namespace haloplot::host
