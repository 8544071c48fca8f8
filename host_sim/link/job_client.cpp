#include "link/job_client.h"

#include <algorithm>
#include <chrono>
#include <thread>

namespace haloplot::host {
namespace {

uint64_t splitmix(uint64_t* s) {
  uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Frames of at most this many payload bytes: a whole number of records of every kind.
constexpr size_t kChunk = 960;  // 40 edges, 80 vertices, 120 index pairs or 20 curves

}  // namespace

bool JobClient::read_frame(Frame* f, std::vector<uint8_t>* payload, int wait_ms) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(wait_ms);
  for (;;) {
    while (!pending_.empty()) {
      const uint8_t b = pending_.front();
      pending_.erase(pending_.begin());
      FrameDecoder::Event ev = decoder_.push(b);
      if (ev == FrameDecoder::Event::kNone) ev = decoder_.poll();
      if (ev == FrameDecoder::Event::kFrame) {
        *f = decoder_.frame();
        payload->assign(f->payload, f->payload + f->length);
        f->payload = nullptr;
        return true;
      }
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    uint8_t buf[512];
    const size_t n = t_.read(buf, sizeof buf, int(left.count()));
    if (n == 0 && t_.closed()) return false;
    pending_.insert(pending_.end(), buf, buf + n);
  }
}

bool JobClient::request(FrameType type, const std::vector<uint8_t>& payload, Status* status,
                        std::vector<uint8_t>* reply_payload, int first_wait_ms) {
  std::vector<uint8_t> frame(payload.size() + kFrameOverhead);
  const uint8_t seq = seq_;
  frame.resize(encode_frame(uint8_t(type), seq, payload.data(), uint16_t(payload.size()),
                            frame.data(), frame.size()));
  ++stats_.frames;
  for (int attempt = 0; attempt < tries; ++attempt) {
    if (attempt > 0) ++stats_.resends;
    std::vector<uint8_t> wire = frame;
    if (attempt == 0 && faults_.corrupt_every && stats_.frames % faults_.corrupt_every == 0) {
      // Flip one byte after the start byte: the length, header, payload or CRC.
      const size_t at = 1 + size_t(splitmix(&faults_.seed) % (wire.size() - 1));
      wire[at] ^= uint8_t(1 + splitmix(&faults_.seed) % 255);
      ++stats_.corrupted;
    } else if (attempt == 0 && faults_.truncate_every &&
               stats_.frames % faults_.truncate_every == 0) {
      wire.resize(wire.size() / 2);
      ++stats_.truncated;
    }
    if (!t_.write(wire.data(), wire.size()) || t_.closed()) {
      error_ = "link: closed by the other end";
      return false;
    }
    const int wait_ms = first_wait_ms > 0 && attempt < 16
                            ? std::min(timeout_ms, first_wait_ms << attempt)
                            : timeout_ms;
    for (;;) {
      Frame f;
      std::vector<uint8_t> got;
      if (!read_frame(&f, &got, wait_ms)) {
        if (t_.closed()) {
          error_ = "link: closed by the other end";
          return false;
        }
        ++stats_.timeouts;
        break;  // silence: resend
      }
      if (f.type == uint8_t(FrameType::kNak)) {
        ++stats_.naks;
        break;  // damaged or out of sequence: resend
      }
      if (got.size() < 2 || got[0] != seq) continue;  // a stale reply to an earlier frame
      if (f.type != uint8_t(FrameType::kAck) && f.type != uint8_t(FrameType::kStatus)) continue;
      *status = Status(got[1]);
      if (reply_payload) *reply_payload = got;
      ++seq_;
      return true;
    }
  }
  error_ = "link: no acknowledgement after " + std::to_string(tries) + " tries";
  return false;
}

bool JobClient::sync() {
  Status s;
  return request(FrameType::kSync, {}, &s, nullptr, 100) && ok(s);
}

bool JobClient::settings(const JobSpec& spec, Status* status) {
  std::vector<uint8_t> m(kMachineBytes), e(kEffectsBytes), h(kHaloBytes), hl(kHiddenBytes);
  encode_machine(spec, m.data());
  encode_effects(spec, e.data());
  encode_halo(spec.draw, h.data());
  encode_hidden(spec.hidden, hl.data());
  for (auto [type, payload] :
       {std::pair{FrameType::kSetMachine, &m}, std::pair{FrameType::kSetEffects, &e},
        std::pair{FrameType::kSetHalo, &h}, std::pair{FrameType::kSetHidden, &hl}}) {
    if (!request(type, *payload, status)) return false;
    if (!ok(*status)) return true;
  }
  return true;
}

bool JobClient::chunks(FrameType type, const std::vector<uint8_t>& records, size_t record_bytes,
                       Status* status) {
  const size_t per = kChunk / record_bytes * record_bytes;
  for (size_t at = 0; at < records.size(); at += per) {
    const size_t n = std::min(per, records.size() - at);
    if (!request(type,
                 std::vector<uint8_t>(records.begin() + long(at), records.begin() + long(at + n)),
                 status))
      return false;
    if (!ok(*status)) return true;
  }
  return true;
}

bool JobClient::upload(const JobSpec& spec, const std::vector<Edge3>& edges, Status* status,
                       const std::vector<BezierEdge3>* curves, uint32_t band_arena) {
  if (!settings(spec, status)) return false;
  if (!ok(*status)) return true;
  const size_t n_curves = curves ? curves->size() : 0;
  UploadBegin b{SceneFormat::kEdges, 0, uint32_t(edges.size()), 0};
  b.curves = uint32_t(n_curves);
  b.band_arena = n_curves > 0 ? band_arena : 0;
  // A straight scene sends the 13-byte form, as before curves; curves whole the 17-byte one.
  std::vector<uint8_t> begin(b.band_arena > 0 ? kUploadBeginBandsBytes
                             : n_curves > 0   ? kUploadBeginCurvesBytes
                                              : kUploadBeginBytes);
  if (b.band_arena > 0)
    encode_upload_begin_bands(b, begin.data());
  else if (n_curves > 0)
    encode_upload_begin_curves(b, begin.data());
  else
    encode_upload_begin(b, begin.data());
  if (!request(FrameType::kUploadBegin, begin, status)) return false;
  if (!ok(*status)) return true;
  if (n_curves > 0) {
    std::vector<uint8_t> curve_records(n_curves * kCurveRecordBytes);
    for (size_t i = 0; i < n_curves; ++i)
      encode_curve((*curves)[i], &curve_records[i * kCurveRecordBytes]);
    if (!chunks(FrameType::kUploadCurves, curve_records, kCurveRecordBytes, status)) return false;
    if (!ok(*status)) return true;
  }
  std::vector<uint8_t> records(edges.size() * kEdgeRecordBytes);
  for (size_t i = 0; i < edges.size(); ++i) encode_edge(edges[i], &records[i * kEdgeRecordBytes]);
  return chunks(FrameType::kUploadEdges, records, kEdgeRecordBytes, status);
}

bool JobClient::stream(const JobSpec& spec, const BandPlan& plan, uint32_t arena_bytes,
                       Status* status) {
  if (!settings(spec, status)) return false;
  if (!ok(*status)) return true;
  std::vector<uint8_t> begin(kStreamBeginBytes);
  const uint8_t flags = plan.solid ? uint8_t(kStreamSolid | (plan.closed ? kStreamClosed : 0) |
                                             (plan.turned ? kStreamTurned : 0))
                                   : uint8_t{0};
  encode_stream_begin(StreamBegin{plan.margin, arena_bytes, flags}, begin.data());
  if (!request(FrameType::kStreamBegin, begin, status)) return false;
  if (!ok(*status)) return true;
  if (!request(FrameType::kPlot, {}, status)) return false;
  if (!ok(*status)) return true;
  for (const PlannedBand& band : plan.bands) {
    std::vector<uint8_t> head(kBandBeginBytes);
    encode_band_begin(
        plan.solid ? BandBegin{band.y0, band.y1, uint32_t(band.ids.size()),
                               uint32_t(band.vertices.size()), uint32_t(band.triangles.size())}
                   : BandBegin{band.y0, band.y1, uint32_t(band.edges.size())},
        head.data());
    for (;;) {
      if (!request(FrameType::kBandBegin, head, status)) return false;
      if (*status != Status::kBusy) break;
      StatusReport r;  // the last band is still staged: wait, unless the plot has ended
      if (!query(&r)) return false;
      if (r.state != ServerState::kPlotting && r.state != ServerState::kPaused) {
        *status = r.last_error == Status::kOk ? Status::kAborted : r.last_error;
        return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    if (!ok(*status)) return true;
    if (plan.solid) {
      if (!solid_band(band, status)) return false;
      if (!ok(*status)) return true;
      continue;
    }
    std::vector<uint8_t> records(band.edges.size() * kBandEdgeRecordBytes);
    for (size_t i = 0; i < band.edges.size(); ++i) {
      put_u32(&records[i * kBandEdgeRecordBytes], band.ids[i]);
      encode_edge(band.edges[i], &records[i * kBandEdgeRecordBytes + 4]);
    }
    if (!chunks(FrameType::kBandEdges, records, kBandEdgeRecordBytes, status)) return false;
    if (!ok(*status)) return true;
  }
  return request(FrameType::kStreamEnd, {}, status);  // the last band is whole: no more
}

// A solid's band: its vertices, drawn edges and triangles, in that order.
bool JobClient::solid_band(const PlannedBand& band, Status* status) {
  std::vector<uint8_t> records(band.vertices.size() * kBandVertexRecordBytes);
  for (size_t i = 0; i < band.vertices.size(); ++i) {
    put_u32(&records[i * kBandVertexRecordBytes], band.vertex_ids[i]);
    encode_vertex(band.vertices[i], &records[i * kBandVertexRecordBytes + 4]);
  }
  if (!chunks(FrameType::kBandVertices, records, kBandVertexRecordBytes, status)) return false;
  if (!ok(*status)) return true;
  records.assign(band.ids.size() * kBandSolidEdgeRecordBytes, 0);
  for (size_t i = 0; i < band.ids.size(); ++i) {
    put_u32(&records[i * kBandSolidEdgeRecordBytes], band.ids[i]);
    put_u32(&records[i * kBandSolidEdgeRecordBytes + 4], band.pairs[2 * i]);
    put_u32(&records[i * kBandSolidEdgeRecordBytes + 8], band.pairs[2 * i + 1]);
  }
  if (!chunks(FrameType::kBandSolidEdges, records, kBandSolidEdgeRecordBytes, status)) return false;
  if (!ok(*status)) return true;
  records.assign(band.triangles.size() * kBandTriangleRecordBytes, 0);
  for (size_t i = 0; i < band.triangles.size(); ++i)
    encode_face(band.triangles[i], &records[i * kBandTriangleRecordBytes]);
  return chunks(FrameType::kBandTriangles, records, kBandTriangleRecordBytes, status);
}

bool JobClient::upload_indexed(const JobSpec& spec, const View& view,
                               const std::vector<Point3>& world, const std::vector<uint32_t>& pairs,
                               Status* status, const std::vector<Triangle>* faces) {
  if (!settings(spec, status)) return false;
  if (!ok(*status)) return true;
  std::vector<uint8_t> v(kViewBytes);
  encode_view(view, v.data());
  if (!request(FrameType::kSetView, v, status)) return false;
  if (!ok(*status)) return true;
  std::vector<uint8_t> begin(kUploadBeginBytes);
  encode_upload_begin(UploadBegin{SceneFormat::kIndexed, uint32_t(world.size()),
                                  uint32_t(pairs.size() / 2), faces ? uint32_t(faces->size()) : 0},
                      begin.data());
  if (!request(FrameType::kUploadBegin, begin, status)) return false;
  if (!ok(*status)) return true;
  std::vector<uint8_t> records(world.size() * kVertexRecordBytes);
  for (size_t i = 0; i < world.size(); ++i)
    encode_vertex(world[i], &records[i * kVertexRecordBytes]);
  if (!chunks(FrameType::kUploadVertices, records, kVertexRecordBytes, status)) return false;
  if (!ok(*status)) return true;
  records.assign(pairs.size() * 4, 0);
  for (size_t i = 0; i < pairs.size(); ++i) put_u32(&records[4 * i], pairs[i]);
  if (!chunks(FrameType::kUploadEdgeIndices, records, kIndexRecordBytes, status)) return false;
  if (!ok(*status) || faces == nullptr || faces->empty()) return true;
  records.assign(faces->size() * kFaceRecordBytes, 0);
  for (size_t i = 0; i < faces->size(); ++i)
    encode_face((*faces)[i], &records[i * kFaceRecordBytes]);
  return chunks(FrameType::kUploadFaces, records, kFaceRecordBytes, status);
}

bool JobClient::query(StatusReport* report) {
  Status s;
  std::vector<uint8_t> reply;
  if (!request(FrameType::kQueryStatus, {}, &s, &reply)) return false;
  if (!ok(decode_status(reply.data(), reply.size(), report))) {
    error_ = "link: malformed status reply";
    return false;
  }
  return true;
}

bool JobClient::wait_idle(StatusReport* report, int poll_ms) {
  for (;;) {
    if (!query(report)) return false;
    // A paused plot has not ended: it waits for kResume (or kAbort).
    if (report->state != ServerState::kPlotting && report->state != ServerState::kPaused)
      return true;
    if (poll_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(poll_ms));
  }
}

}  // namespace haloplot::host
