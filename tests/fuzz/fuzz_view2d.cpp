// The polygon reader and the 2-D visibility walk under arbitrary text: the input is a polygon
// file whose first line is the vantage point. Whatever the bytes, the reader and view2d must
// return (no crash, no sanitizer report); for small valid polygons the walk must agree exactly
// with the brute-force ray caster.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "haloplot/view2d/polygon_view.h"
#include "io/polygon_file.h"
#include "reference/view2d_reference.h"

using namespace haloplot;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::vector<Point2> pts;
  if (host::read_polygon(in, "fuzz", &pts).failed() || pts.size() < 4) return 0;
  const Point2 eye = pts[0];
  pts.erase(pts.begin());
  std::vector<uint8_t> scratch(view2d_scratch_bytes(uint32_t(pts.size())));
  std::vector<VisibleSpan> got;
  const Status s = view2d(pts.data(), uint32_t(pts.size()), eye, scratch.data(), scratch.size(),
                          VisibleSink{[](void* c, const VisibleSpan& v) {
                                        static_cast<std::vector<VisibleSpan>*>(c)->push_back(v);
                                        return Status::kOk;
                                      },
                                      &got},
                          nullptr);
  if (s == Status::kVisibilityInconsistent) std::abort();  // a bug, never valid input's fault
  if (!ok(s) || pts.size() > 24) return 0;
  // Exact agreement with the brute force, after merging touching pieces of one edge.
  std::vector<reference::Pt> p;
  for (const Point2& q : pts) p.push_back({q.x, q.y});
  const auto want = reference::visible_brute(p, {eye.x, eye.y});
  std::sort(got.begin(), got.end(), [](const VisibleSpan& a, const VisibleSpan& b) {
    if (a.edge != b.edge) return a.edge < b.edge;
    return (__int128)a.s0.num * b.s0.den < (__int128)b.s0.num * a.s0.den;
  });
  std::vector<reference::Interval> merged;
  for (const VisibleSpan& v : got) {
    const reference::Frac f0{v.s0.num, v.s0.den}, f1{v.s1.num, v.s1.den};
    if (!merged.empty() && merged.back().edge == v.edge && reference::frac_eq(merged.back().s1, f0))
      merged.back().s1 = f1;
    else
      merged.push_back({v.edge, f0, f1});
  }
  if (merged.size() != want.size()) std::abort();
  for (size_t i = 0; i < want.size(); ++i)
    if (merged[i].edge != want[i].edge || !reference::frac_eq(merged[i].s0, want[i].s0) ||
        !reference::frac_eq(merged[i].s1, want[i].s1))
      std::abort();
  return 0;
}
