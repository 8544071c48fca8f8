// The two jobs the motion tests plot (speed_jumps, pause): the README's demo machine (the
// defaults, CoreXY, haloed with the paper's gap, scenes/demo.job), and the pair of cubes drawn
// hidden-dashed with outlines on a machine with backlash, as a job file gives it (the strokes
// are decided on the host and drawn whole).
#pragma once
#include <fstream>
#include <string>
#include <vector>

#include "../check.h"
#include "cli/job_file.h"
#include "cli/scene_input.h"
#include "haloplot/job/job.h"

namespace haloplot::test {

inline JobSpec demo_job_spec() {
  JobSpec demo;
  demo.drawing = DrawingEffect::kHaloed;
  demo.draw.halo = 50;
  demo.draw.mode = HaloMode::kPaper;
  demo.machine.kinematics = Kinematics::kCoreXY;
  return demo;
}

// Writes the job file at `job_path` (in the test's folder) and loads it: the spec, *strokes.
inline JobSpec cubes_with_backlash_job(const std::string& job_path, std::vector<Edge3>* strokes) {
  std::ofstream(job_path) << "scene " HALOPLOT_SOURCE_DIR "/scenes/pair_of_cubes.obj\n"
                          << "drawing hidden-dashed\noutline on\nkinematics corexy\n"
                          << "effects acceleration pen-servo backlash\nbacklash 7 3\n";
  host::JobFile jf;
  const host::InputError e = host::read_job_file(job_path, &jf);
  CHECK_MSG(!e.failed(), e.message());
  std::string error;
  JobSpec spec = jf.spec;
  CHECK_MSG(host::load_job_scene(jf, strokes, &error, nullptr, &spec.layers), error);
  spec.drawing = DrawingEffect::kAllEdges;  // the strokes, decided on the host, drawn whole
  CHECK(spec.effects.backlash && spec.machine.backlash[0] == 7);
  return spec;
}

}  // namespace haloplot::test
