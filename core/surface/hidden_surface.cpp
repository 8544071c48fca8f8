#include "haloplot/surface/hidden_surface.h"

#include "memory/carve.h"

namespace haloplot {
namespace {

// Collects the visible pieces as segments, and passes runs of equal visibility on.
struct Collector {
  RegionSegment* segments;
  uint32_t capacity, count;
  FranklinSink lines;
  FranklinPiece run;
  bool have;

  Status flush() {
    if (!have) return Status::kOk;
    have = false;
    return lines.emit ? lines.emit(lines.context, run) : Status::kOk;
  }

  static Status emit(void* context, const FranklinPiece& p) {
    Collector& c = *static_cast<Collector*>(context);
    if (!p.hidden) {
      if (c.count < c.capacity)
        c.segments[c.count] = RegionSegment{{p.edge, p.t0, p.t1}, p.from, p.to};
      ++c.count;
    }
    if (c.have && c.run.edge == p.edge && c.run.hidden == p.hidden && c.run.t1 == p.t0) {
      c.run.t1 = p.t1;
      c.run.to = p.to;
      return Status::kOk;
    }
    const Status s = c.flush();
    c.run = p;
    c.have = true;
    return s;
  }
};

}  // namespace

size_t hidden_surface_bytes(const SolidInput& in, const FranklinParams& fp,
                            uint32_t crossing_capacity, uint32_t incidence_capacity,
                            uint32_t segment_capacity) {
  ByteCounter c;
  c.take<RegionSegment>(segment_capacity);
  const size_t f = franklin_bytes(in, fp, crossing_capacity, incidence_capacity);
  const size_t r = regions_bytes(in, segment_capacity);
  return c.total + (f > r ? f : r) + 16;
}

Status hidden_surface(const SolidInput& in, const FranklinParams& fp, const HatchParams& hp,
                      uint32_t crossing_capacity, uint32_t incidence_capacity,
                      uint32_t segment_capacity, void* buffer, size_t bytes, FranklinSink lines,
                      HatchSink hatch, HiddenSurfaceStats* stats) {
  if (buffer_misaligned(buffer)) return Status::kMisalignedBuffer;
  HiddenSurfaceStats st;
  Carver carve(buffer, bytes);
  // Short of what the capacities take: the query's bytes are what a run needs.
  auto asked = [&] {
    return hidden_surface_bytes(in, fp, crossing_capacity, incidence_capacity, segment_capacity);
  };
  RegionSegment* segments = carve.take<RegionSegment>(segment_capacity);
  if (carve.short_) {
    st.bytes_needed = asked();
    if (stats) *stats = st;
    return Status::kWorkspaceTooSmall;
  }
  FranklinParams every = fp;
  every.every_piece = true;
  Collector col{segments, segment_capacity, 0, lines, FranklinPiece{}, false};
  Status s = franklin_hidden_lines(in, every, crossing_capacity, incidence_capacity, carve.next,
                                   carve.left, FranklinSink{&Collector::emit, &col}, &st.franklin);
  if (s == Status::kOk) s = col.flush();
  st.segments = col.count;
  if (s == Status::kOk && col.count > segment_capacity) s = Status::kSegmentCapacity;
  if (s == Status::kWorkspaceTooSmall) st.bytes_needed = asked();
  if (s != Status::kOk) {
    if (stats) *stats = st;
    return s;
  }
  // Franklin's workspace is free again: the regions, then the hatching, take it.
  Regions regions;
  const size_t rb = regions_bytes(in, col.count);
  uint8_t* rmem = carve.take<uint8_t>(rb);
  if (rmem == nullptr) {
    st.bytes_needed = bytes - carve.left + rb + region_hatch_bytes(in, Regions{}, hp) + 64;
    if (stats) *stats = st;
    return Status::kWorkspaceTooSmall;
  }
  s = build_regions(in, segments, col.count, rmem, rb, &regions, &st.regions);
  if (s == Status::kOk && hatch.emit != nullptr) {
    const size_t hb = region_hatch_bytes(in, regions, hp);
    if (hb > carve.left) {
      st.bytes_needed = bytes - carve.left + hb + 16;
      s = Status::kWorkspaceTooSmall;
    } else {
      s = hatch_regions(in, regions, hp, carve.next, carve.left, hatch, &st.hatch);
    }
  }
  if (stats) *stats = st;
  return s;
}

Status HiddenSurfaceStage::run(const StageNeeds& needs, void* buffer, size_t bytes,
                               StageNeeds* want) {
  const Status s = hidden_surface(*in, franklin, hatch_params, needs.crossings, needs.incidences,
                                  needs.segments, buffer, bytes, lines, hatch, stats);
  if (s == Status::kCrossingCapacity) want->crossings = need_count(stats->franklin.crossings);
  if (s == Status::kIncidenceCapacity) want->incidences = stats->franklin.incidences;
  if (s == Status::kSegmentCapacity) want->segments = stats->segments;
  if (s == Status::kWorkspaceTooSmall) want->bytes = stats->bytes_needed;
  return s;
}

}  // namespace haloplot
