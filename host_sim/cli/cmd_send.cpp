// haloplot send JOB.job --port PATH: upload a job to a plotter controller and plot it, over
// the job protocol (core/protocol). Options re-plot with another halo width (DRAW only on
// the controller), damage frames on purpose (to test the link), set how long to wait for a
// reply (an emulated controller on a loaded machine answers late), and end a QEMU test image.
#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <thread>

#include "cli/cmd_plot_curves.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/job_file.h"
#include "cli/options.h"
#include "cli/scene_input.h"
#include "cli/solid_options.h"
#include "io/edges_file.h"
#include "io/line_reader.h"
#include "io/mesh_file.h"
#include "io/obj_file.h"
#include "link/job_client.h"
#include "link/serial_port.h"
#include "pipeline/triangulate.h"

namespace haloplot::host {
namespace {

void print_link_stats(std::ostream& out, const LinkStats& st) {
  out << "link: frames=" << st.frames << " resends=" << st.resends << " naks=" << st.naks
      << " timeouts=" << st.timeouts << " corrupted=" << st.corrupted
      << " truncated=" << st.truncated << "\n";
}

int send_fail(const std::string& m, const JobClient* client = nullptr) {
  fail("send: " + m);
  if (client) print_link_stats(std::cerr, client->stats());  // what the link saw, for diagnosis
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

bool hidden_line_drawing(const JobSpec& spec) {
  return spec.drawing == DrawingEffect::kHiddenRemoved ||
         spec.drawing == DrawingEffect::kHiddenDashed;
}

// The job and its scene in the form the controller takes them: an .edges scene goes as
// projected edges; an .obj model as world vertices and index pairs (and triangles for the
// hidden-line drawings), projected on the controller with the view.
struct SendScene {
  JobFile jf;
  bool obj = false;
  std::vector<Edge3> edges;
  std::vector<BezierEdge3> curves;  // an .edges scene's Bézier edges (`edges`: its straight ones)
  ObjModel model;
  std::vector<Triangle> triangles;
  View view;
  BandPlan plan;  // a job with an arena: the bands it streams in
};

bool load_obj(const std::string& job_path, SendScene* sc, std::string* error) {
  JobFile& jf = sc->jf;
  SolidOptions so;
  std::string why;
  if (!job_solid_settings(jf, &so, &sc->view, &why)) {
    *error = job_path + ": " + why;
    return false;
  }
  jf.spec.substep_bits = sc->view.substep_bits;  // the controller projects in these units
  // Read and cleaned (welded, oriented, Z-up) as `sim` and `plot` read it (scene_input.h): the
  // controller projects the same world.
  Options model_options;
  model_options.values = jf.solid_options;
  std::string model_error;
  if (jf.landscape) model_options.flags.insert("--landscape");
  model_options = with_model_defaults(model_options, jf.scene_path);  // an STL is Z-up
  // --scale: the view's area from the model, as `sim` and `plot` shrink it.
  if (!read_model(model_options, jf.scene_path, &sc->model, nullptr, &model_error) ||
      !aim_view(model_options, &sc->model, &sc->view, &model_error) ||
      !scale_view(model_options, sc->model, &sc->view, &model_error)) {
    *error = model_error.find(jf.scene_path) == 0 ? model_error : job_path + ": " + model_error;
    return false;
  }
  jf.spec.hidden = hidden_job(so);
  if (hidden_line_drawing(jf.spec)) {
    TriangulateStats ts;
    sc->triangles = triangulate(sc->model.vertices, sc->model.faces, sc->model.face_region, &ts);
    if (ts.first_not_simple >= 0) {
      *error = not_simple_message(jf.scene_path, sc->model, ts);
      return false;
    }
  }
  return true;
}

bool load_scene(const std::string& job_path, SendScene* sc, std::string* error) {
  InputError ie = read_job_file(job_path, &sc->jf);
  if (ie.failed()) {
    *error = ie.message();
    return false;
  }
  const std::string& scene = sc->jf.scene_path;
  sc->obj = is_mesh_path(scene);
  if (sc->obj) return load_obj(job_path, sc, error);
  if (edges_file_has_curves(scene)) {
    // The controller draws the curves itself (the core's curve job, as `sim` runs it).
    EdgesWithCurves with_curves;
    if (!load_curve_job(scene, sc->jf.spec, &with_curves, &sc->jf.spec.substep_bits, error))
      return false;
    sc->edges = std::move(with_curves.edges);
    sc->curves = std::move(with_curves.curves);
    return true;
  }
  ie = read_edges_file(scene, &sc->edges, &sc->jf.spec.substep_bits);
  if (ie.failed()) *error = ie.message();
  return !ie.failed();
}

// A job with an arena streams its scene in bands: plan them here with the controller's arena,
// exactly as `sim` with the same arena does, and send each band's edges as the plot needs them.
bool plan_bands(const std::string& job_path, SendScene* sc, std::string* error) {
  const JobFile& jf = sc->jf;
  if (jf.arena == 0 || !sc->curves.empty()) return true;  // curves: uploaded, drawn in bands
  if (sc->obj && !hidden_line_drawing(jf.spec)) {
    *error = job_path + ": 'arena' streams .edges scenes and hidden-line drawings of .obj models";
    return false;
  }
  Status ps = Status::kOk;
  if (sc->obj) {  // the model projected here with the core's view, as `sim` does
    SolidScene solid;
    HiddenJob hidden;
    if (!load_solid_job_scene(jf, &solid, &hidden, error)) return false;
    ps = plan_streamed_solid(solid_input(solid), model_closed(solid), band_spec(jf.spec), jf.arena,
                             &sc->plan);
  } else {
    ps = plan_streamed_bands(sc->edges, band_spec(jf.spec), jf.arena, &sc->plan);
  }
  if (ok(ps)) return true;
  *error = job_path + ": planning the bands: " + status_name(ps) +
           (ps == Status::kArenaTooSmall
                ? " (a band one row high needs " + std::to_string(sc->plan.stats.need_bytes) +
                      " bytes where the plan stopped; bands further on "
                      "may need more)"
                : std::string());
  return false;
}

// How long to wait for a reply before resending (JobClient tries 20 times): a real serial
// link answers within milliseconds, so a dead controller is given up in a minute.
constexpr int kDefaultReplyTimeoutMs = 3000;

// The link's own settings: frames damaged on purpose, a re-plot's halo width, and how long
// each reply may take.
struct LinkOptions {
  FaultPlan faults;
  uint32_t replot = 0;
  int reply_timeout_ms = kDefaultReplyTimeoutMs;
};

bool read_link_options(const Options& o, LinkOptions* lo, std::string* error) {
  uint32_t seed = 1;
  if (!read_u32(o, "--corrupt-every", &lo->faults.corrupt_every, error) ||
      !read_u32(o, "--truncate-every", &lo->faults.truncate_every, error) ||
      !read_u32(o, "--replot", &lo->replot, error) || !read_u32(o, "--seed", &seed, error))
    return false;
  lo->faults.seed = seed;
  // A lost or damaged frame is answered by a NAK (the controller's frame idle timeout ends a
  // truncated one), so a long reply timeout only waits out a controller that is slow to answer.
  const std::string timeout = o.get("--reply-timeout");
  int64_t ms = 0;
  if (!timeout.empty()) {
    if (!parse_int(timeout, 1, 600000, &ms)) {
      *error = "--reply-timeout '" + timeout + "' must be milliseconds in [1, 600000]";
      return false;
    }
    lo->reply_timeout_ms = int(ms);
  }
  return true;
}

// A socket server that still holds the previous session may close a new connection at
// once (QEMU's chardev serves one client): reconnect a few times before giving up.
std::unique_ptr<Transport> connect_to_controller(const std::string& path, int reply_timeout_ms,
                                                 std::string* error) {
  struct stat port_stat {};
  if (::stat(path.c_str(), &port_stat) != 0 && path.rfind("/dev/", 0) != 0)
    std::fprintf(stderr, "haloplot send: waiting up to 20 s for %s to appear\n", path.c_str());
  for (int attempt = 0; attempt < 20; ++attempt) {
    std::unique_ptr<Transport> port = open_port(path, 20000, error);
    if (!port) return nullptr;
    JobClient probe(*port);
    probe.timeout_ms = reply_timeout_ms;
    if (probe.sync()) return port;
    if (!port->closed()) {
      *error = "sync: " + probe.error();
      return nullptr;
    }
    port.reset();
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  }
  *error = "the controller keeps closing the link";
  return nullptr;
}

// One session with the controller, step by step. Each step returns 0, or the command's exit
// status once something failed (already reported).
struct SendSession {
  SendSession(const Options& options, const SendScene& scene, JobClient& link, uint32_t replot)
      : o(options), sc(scene), client(link), replot_halo(replot) {}

  const Options& o;
  const SendScene& sc;
  JobClient& client;
  uint32_t replot_halo = 0;
  Status s = Status::kOk;  // the controller's answer to the last request
  StatusReport r;

  int run();
  // A request that went through and was accepted; else what failed: the link (with its
  // counters) or the controller, which refused it.
  int check(bool sent, const char* what) {
    if (!sent) return send_fail(std::string(what) + ": " + client.error(), &client);
    if (!ok(s))
      return send_fail(std::string(what) + ": the controller answered: " + status_name(s));
    return 0;
  }
  int request(FrameType type, const std::vector<uint8_t>& payload, const char* what) {
    return check(client.request(type, payload, &s), what);
  }
  int status_failed() { return send_fail("status: " + client.error()); }
  // Polls the status until the plot has made `after` step events or has stopped plotting.
  bool wait_for_events(uint32_t after) {
    do {
      if (!client.query(&r)) return false;
    } while (r.state == ServerState::kPlotting && r.step_events < after);
    return true;
  }
  int stream();
  int upload_and_plot();
  int pause_and_resume();
  int stop_early();
  int wait_for_end();
  int replot();
};

int SendSession::run() {
  if (int e = check(client.sync(), "sync")) return e;
  if (o.has("--trace-digest")) {  // test images: the controller sums its traces (0x7D)
    if (int e = request(FrameType(0x7D), {}, "trace-digest")) return e;
  }
  // A curve scene is uploaded whole (its curves are few bytes): the controller draws it in
  // bands of the job's arena itself.
  if (int e = sc.jf.arena > 0 && sc.curves.empty() ? stream() : upload_and_plot()) return e;
  if (int e = pause_and_resume()) return e;
  if (int e = stop_early()) return e;
  if (int e = wait_for_end()) return e;
  if (int e = replot()) return e;
  if (o.has("--test-exit")) {
    if (int e = request(FrameType(0x7F), {}, "test-exit")) return e;
  }
  print_link_stats(std::cout, client.stats());
  return 0;
}

int SendSession::stream() {
  if (int e = check(client.stream(sc.jf.spec, sc.plan, sc.jf.arena, &s), "stream")) return e;
  std::cout << "streamed " << sc.plan.bands.size() << " bands, margin " << sc.plan.margin << "\n";
  return 0;
}

int SendSession::upload_and_plot() {
  const bool sent = sc.obj ? client.upload_indexed(sc.jf.spec, sc.view, sc.model.vertices,
                                                   sc.model.edge_pairs, &s, &sc.triangles)
                           : client.upload(sc.jf.spec, sc.edges, &s, &sc.curves, sc.jf.arena);
  if (int e = check(sent, "upload")) return e;
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
  return request(FrameType::kPlot, plot_payload, "plot");
}

// --pause-after EVENTS: feed hold once the plot has made this many step events: the
// controller brakes to rest and lifts the pen (state kPaused); then resume, and the plot goes
// on to its end.
int SendSession::pause_and_resume() {
  if (o.get("--pause-after").empty()) return 0;
  uint32_t after = 0;
  std::string error;
  if (!read_u32(o, "--pause-after", &after, &error)) return send_fail(error);
  if (!wait_for_events(after)) return status_failed();
  if (int e = request(FrameType::kPause, {}, "pause")) return e;
  do {
    if (!client.query(&r)) return status_failed();
  } while (r.state == ServerState::kPlotting);
  if (r.state != ServerState::kPaused)
    return send_fail(std::string("pause: the plot ended instead (") + status_name(r.last_error) +
                     ")");
  std::cout << "paused at rest after " << r.step_events << " step events\n";
  return request(FrameType::kResume, {}, "resume");
}

// --stop-after EVENTS: stop the plot once it has made this many step events: with an abort
// request, or (test images) by closing limit switch 0. The controller must report how the
// plot ended.
int SendSession::stop_early() {
  if (o.get("--stop-after").empty()) return 0;
  uint32_t after = 0;
  std::string error;
  if (!read_u32(o, "--stop-after", &after, &error)) return send_fail(error);
  const bool limit = o.get("--stop", "abort") == "limit";
  if (!wait_for_events(after)) return status_failed();
  const FrameType stop = limit ? FrameType(0x7E) : FrameType::kAbort;
  if (int e = request(stop, {}, "stop")) return e;
  if (!client.wait_idle(&r)) return status_failed();
  print_status("stopped", r);
  const Status want = limit ? Status::kLimitSwitch : Status::kAborted;
  if (r.last_error != want)
    return send_fail(std::string("stop: expected '") + status_name(want) +
                     "', the plot ended with '" + status_name(r.last_error) + "'");
  std::cout << "stopped by " << (limit ? "the limit switch" : "abort") << " after " << r.step_events
            << " step events (--resume " << r.step_events << " goes on from there)\n";
  return 0;
}

int SendSession::wait_for_end() {
  if (!client.wait_idle(&r)) return status_failed();
  print_status("plot", r);
  if (r.last_error != Status::kOk && o.get("--stop-after").empty())
    return send_fail(std::string("plot: ") + status_name(r.last_error));
  return 0;
}

// --replot W: the same job again with another halo width (DRAW only on the controller).
int SendSession::replot() {
  if (replot_halo == 0) return 0;
  std::vector<uint8_t> halo(kHaloBytes);
  encode_halo(DrawParams{int32_t(replot_halo), sc.jf.spec.draw.mode}, halo.data());
  if (int e = request(FrameType::kReplot, halo, "replot")) return e;
  if (!client.wait_idle(&r)) return status_failed();
  print_status("replot", r);
  if (r.last_error != Status::kOk)
    return send_fail(std::string("replot: ") + status_name(r.last_error));
  return 0;
}

}  // namespace

int cmd_send(int argc, char** argv) {
  const Options o =
      parse_options(argc, argv, 2,
                    {"--port", "--replot", "--corrupt-every", "--truncate-every", "--seed",
                     "--stop-after", "--stop", "--pause-after", "--resume", "--reply-timeout"},
                    {"--test-exit", "--trace-digest"});
  if (!o.error.empty()) return send_fail(o.error);
  if (o.positional.size() != 1 || o.get("--port").empty())
    return send_fail(
        "usage: haloplot send JOB.job --port PATH [--replot W] [--corrupt-every K] "
        "[--truncate-every K] [--pause-after EVENTS] [--stop-after EVENTS [--stop abort|limit]] "
        "[--resume EVENTS] [--reply-timeout MS] "
        "[--test-exit] [--trace-digest]");
  SendScene sc;
  LinkOptions lo;
  std::string error;
  if (!load_scene(o.positional[0], &sc, &error) || !plan_bands(o.positional[0], &sc, &error) ||
      !read_link_options(o, &lo, &error))
    return send_fail(error);
  const std::unique_ptr<Transport> port =
      connect_to_controller(o.get("--port"), lo.reply_timeout_ms, &error);
  if (!port) return send_fail(error);
  JobClient client(*port, lo.faults);
  client.timeout_ms = lo.reply_timeout_ms;
  SendSession session(o, sc, client, lo.replot);
  return session.run();
}

}  // namespace haloplot::host
