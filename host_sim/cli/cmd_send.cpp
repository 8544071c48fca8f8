// haloplot send JOB.job --port PATH: upload a job to a plotter controller and plot it, over
// the job protocol (core/protocol). Options re-plot with another halo width (DRAW only on
// the controller), damage frames on purpose (to test the link), and end a QEMU test image.
#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <thread>

#include "cli/options.h"
#include "cli/solid_options.h"
#include "io/edges_file.h"
#include "io/job_file.h"
#include "io/line_reader.h"
#include "io/obj_file.h"
#include "link/job_client.h"
#include "link/serial_port.h"
#include "pipeline/scene_input.h"
#include "pipeline/triangulate.h"

namespace haloplot::host {
namespace {

int send_fail(const std::string& m, const JobClient* client = nullptr) {
  std::cerr << "haloplot: send: " << m << "\n";
  if (client) {  // what the link saw, for diagnosis
    const LinkStats& st = client->stats();
    std::cerr << "link: frames=" << st.frames << " resends=" << st.resends << " naks=" << st.naks
              << " timeouts=" << st.timeouts << " corrupted=" << st.corrupted
              << " truncated=" << st.truncated << "\n";
  }
  return 1;
}

bool read_u32(const Options& o, const std::string& name, uint32_t* out, std::string* error) {
  const std::string v = o.get(name);
  if (v.empty()) return true;
  int64_t x = 0;
  if (!parse_int(v, 0, 0xFFFFF, &x)) {
    *error = name + " '" + v + "' must be an integer in [0, 1048575]";
    return false;
  }
  *out = uint32_t(x);
  return true;
}

void print_status(const char* when, const StatusReport& r) {
  std::cout << when << ": state=" << int(r.state) << " last_error=" << status_name(r.last_error)
            << " edges=" << r.edges << " crossings=" << r.crossings << " cut_runs=" << r.cut_runs
            << " draw_runs=" << r.draw_runs << " step_events=" << r.step_events
            << " bad_frames=" << r.bad_frames << " free_bytes=" << r.free_bytes << "\n";
}

}  // namespace

int cmd_send(int argc, char** argv) {
  const Options o = parse_options(argc, argv, 2,
                                  {"--port", "--replot", "--corrupt-every", "--truncate-every",
                                   "--seed", "--stop-after", "--stop", "--pause-after", "--resume"},
                                  {"--test-exit", "--trace-digest"});
  if (!o.error.empty()) return send_fail(o.error);
  if (o.positional.size() != 1 || o.get("--port").empty())
    return send_fail(
        "usage: haloplot send JOB.job --port PATH [--replot W] [--corrupt-every K] "
        "[--truncate-every K] [--pause-after EVENTS] [--stop-after EVENTS [--stop abort|limit]] "
        "[--resume EVENTS] "
        "[--test-exit] [--trace-digest]");
  JobFile jf;
  InputError ie = read_job_file(o.positional[0], &jf);
  if (ie.failed()) return send_fail(ie.message());
  // An .edges scene goes as projected edges; an .obj model as world vertices and index pairs
  // (and triangles for the hidden-line drawings), projected on the controller with the view.
  std::vector<Edge3> edges;
  ObjModel model;
  std::vector<Triangle> triangles;
  View view;
  const bool obj =
      jf.scene_path.size() > 4 && jf.scene_path.compare(jf.scene_path.size() - 4, 4, ".obj") == 0;
  if (obj) {
    SolidOptions so;
    std::string why;
    if (!job_solid_settings(jf, &so, &view, &why)) return send_fail(o.positional[0] + ": " + why);
    jf.spec.substep_bits = view.substep_bits;  // the controller projects in these units
    ie = read_obj_file(jf.scene_path, &model);
    if (ie.failed()) return send_fail(ie.message());
    {  // the world the controller projects is Z-up, as the host's (scene_input.h)
      Options up_option;
      up_option.values = jf.solid_options;
      UpAxis up;
      std::string up_error;
      if (!parse_up(up_option, &up, &up_error)) return send_fail(o.positional[0] + ": " + up_error);
      make_z_up(&model, up);
    }
    jf.spec.hidden = hidden_job(so);
    if (jf.spec.drawing == DrawingEffect::kHiddenRemoved ||
        jf.spec.drawing == DrawingEffect::kHiddenDashed) {
      TriangulateStats ts;
      triangles = triangulate(model.vertices, model.faces, &ts);
      if (ts.first_not_simple >= 0) return send_fail(not_simple_message(jf.scene_path, model, ts));
    }
  } else {
    ie = read_edges_file(jf.scene_path, &edges, &jf.spec.substep_bits);
    if (ie.failed()) return send_fail(ie.message());
  }
  // A job with an arena streams its scene in bands: plan them here with the controller's arena,
  // exactly as `sim` with the same arena does, and send each band's edges as the plot needs them.
  BandPlan plan;
  if (jf.arena > 0) {
    const bool lines = jf.spec.drawing == DrawingEffect::kHiddenRemoved ||
                       jf.spec.drawing == DrawingEffect::kHiddenDashed;
    if (obj && !lines)
      return send_fail(o.positional[0] +
                       ": 'arena' streams .edges scenes and hidden-line drawings of .obj models");
    Status ps = Status::kOk;
    if (obj) {  // the model projected here with the core's view, as `sim` does
      SolidScene solid;
      HiddenJob hidden;
      std::string why;
      if (!load_solid_job_scene(jf, &solid, &hidden, &why)) return send_fail(why);
      ps = plan_streamed_solid(solid_input(solid), model_closed(solid), band_spec(jf.spec),
                               jf.arena, &plan);
    } else {
      ps = plan_streamed_bands(edges, band_spec(jf.spec), jf.arena, &plan);
    }
    if (!ok(ps))
      return send_fail(
          o.positional[0] + ": planning the bands: " + status_name(ps) +
          (ps == Status::kArenaTooSmall
               ? " (a band one row high needs " + std::to_string(plan.stats.need_bytes) + " bytes)"
               : std::string()));
  }
  FaultPlan faults;
  uint32_t replot = 0, seed = 1;
  std::string error;
  if (!read_u32(o, "--corrupt-every", &faults.corrupt_every, &error) ||
      !read_u32(o, "--truncate-every", &faults.truncate_every, &error) ||
      !read_u32(o, "--replot", &replot, &error) || !read_u32(o, "--seed", &seed, &error))
    return send_fail(error);
  faults.seed = seed;
  // A socket server that still holds the previous session may close a new connection at
  // once (QEMU's chardev serves one client): reconnect a few times before giving up.
  std::unique_ptr<Transport> port;
  struct stat port_stat {};
  if (::stat(o.get("--port").c_str(), &port_stat) != 0 && o.get("--port").rfind("/dev/", 0) != 0)
    std::fprintf(stderr, "haloplot send: waiting up to 20 s for %s to appear\n",
                 o.get("--port").c_str());
  for (int attempt = 0; attempt < 20; ++attempt) {
    port = open_port(o.get("--port"), 20000, &error);
    if (!port) return send_fail(error);
    JobClient probe(*port);
    probe.timeout_ms = 3000;
    if (probe.sync()) break;
    if (!port->closed()) return send_fail("sync: " + probe.error());
    port.reset();
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  }
  if (!port) return send_fail("the controller keeps closing the link");
  JobClient client(*port, faults);
  client.timeout_ms = 3000;
  Status s = Status::kOk;
  auto link_or_status = [&](bool sent, const char* what) {
    if (!sent) return send_fail(std::string(what) + ": " + client.error(), &client);
    if (!ok(s))
      return send_fail(std::string(what) + ": the controller answered: " + status_name(s));
    return 0;
  };
  StatusReport r;
  if (int e = link_or_status(client.sync(), "sync")) return e;
  if (o.has("--trace-digest")) {  // test images: the controller sums its traces (0x7D)
    if (int e = link_or_status(client.request(FrameType(0x7D), {}, &s), "trace-digest")) return e;
  }
  if (jf.arena > 0) {
    if (int e = link_or_status(client.stream(jf.spec, plan, jf.arena, &s), "stream")) return e;
    std::cout << "streamed " << plan.bands.size() << " bands, margin " << plan.margin << "\n";
  } else {
    const bool sent =
        obj ? client.upload_indexed(jf.spec, view, model.vertices, model.edge_pairs, &s, &triangles)
            : client.upload(jf.spec, edges, &s);
    if (int e = link_or_status(sent, "upload")) return e;
    // --resume E: go on with a plot of this job that stopped after E step events (an abort,
    // a reset), drawing nothing twice.
    std::vector<uint8_t> plot_payload;
    if (!o.get("--resume").empty()) {
      int64_t events = 0;
      if (!parse_int(o.get("--resume"), 1, UINT32_MAX, &events))
        return send_fail("--resume needs the step events the plot stopped after: '" +
                         o.get("--resume") + "'");
      plot_payload.resize(4);
      put_u32(plot_payload.data(), uint32_t(events));
    }
    if (int e = link_or_status(client.request(FrameType::kPlot, plot_payload, &s), "plot"))
      return e;
  }
  if (!o.get("--pause-after").empty()) {
    // Feed hold once the plot has made this many step events: the controller brakes to rest
    // and lifts the pen (state kPaused); then resume, and the plot goes on to its end.
    uint32_t after = 0;
    if (!read_u32(o, "--pause-after", &after, &error)) return send_fail(error);
    do {
      if (!client.query(&r)) return send_fail("status: " + client.error());
    } while (r.state == ServerState::kPlotting && r.step_events < after);
    if (int e = link_or_status(client.request(FrameType::kPause, {}, &s), "pause")) return e;
    do {
      if (!client.query(&r)) return send_fail("status: " + client.error());
    } while (r.state == ServerState::kPlotting);
    if (r.state != ServerState::kPaused)
      return send_fail(std::string("pause: the plot ended instead (") + status_name(r.last_error) +
                       ")");
    std::cout << "paused at rest after " << r.step_events << " step events\n";
    if (int e = link_or_status(client.request(FrameType::kResume, {}, &s), "resume")) return e;
  }
  if (!o.get("--stop-after").empty()) {
    // Stop the plot once it has made this many step events: with an abort request, or (test
    // images) by closing limit switch 0. The controller must report how the plot ended.
    uint32_t after = 0;
    if (!read_u32(o, "--stop-after", &after, &error)) return send_fail(error);
    const bool limit = o.get("--stop", "abort") == "limit";
    do {
      if (!client.query(&r)) return send_fail("status: " + client.error());
    } while (r.state == ServerState::kPlotting && r.step_events < after);
    const FrameType stop = limit ? FrameType(0x7E) : FrameType::kAbort;
    if (int e = link_or_status(client.request(stop, {}, &s), "stop")) return e;
    if (!client.wait_idle(&r)) return send_fail("status: " + client.error());
    print_status("stopped", r);
    const Status want = limit ? Status::kLimitSwitch : Status::kAborted;
    if (r.last_error != want)
      return send_fail(std::string("stop: expected '") + status_name(want) +
                       "', the plot ended with '" + status_name(r.last_error) + "'");
    std::cout << "stopped by " << (limit ? "the limit switch" : "abort") << " after "
              << r.step_events << " step events (--resume " << r.step_events
              << " goes on from there)\n";
  }
  if (!client.wait_idle(&r)) return send_fail("status: " + client.error());
  print_status("plot", r);
  if (r.last_error != Status::kOk && o.get("--stop-after").empty())
    return send_fail(std::string("plot: ") + status_name(r.last_error));
  if (replot > 0) {
    std::vector<uint8_t> halo(kHaloBytes);
    encode_halo(DrawParams{int32_t(replot), jf.spec.draw.mode}, halo.data());
    if (int e = link_or_status(client.request(FrameType::kReplot, halo, &s), "replot")) return e;
    if (!client.wait_idle(&r)) return send_fail("status: " + client.error());
    print_status("replot", r);
    if (r.last_error != Status::kOk)
      return send_fail(std::string("replot: ") + status_name(r.last_error));
  }
  if (o.has("--test-exit")) {
    if (int e = link_or_status(client.request(FrameType(0x7F), {}, &s), "test-exit")) return e;
  }
  const LinkStats& st = client.stats();
  std::cout << "link: frames=" << st.frames << " resends=" << st.resends << " naks=" << st.naks
            << " timeouts=" << st.timeouts << " corrupted=" << st.corrupted
            << " truncated=" << st.truncated << "\n";
  return 0;
}

}  // namespace haloplot::host
