// haloplot demo-scene [--cubes N] -o SCENE.edges|MODEL.obj: the HALO paper's Figure 4 array of
// cubes, as edges in steps or as a solid model; with --curve, a knot or a helix (cmd_demo_curve).
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "cli/command_line.h"
#include "cli/commands.h"
#include "demo/cube_array.h"
#include "io/atomic_file.h"
#include "io/edges_file.h"

namespace haloplot::host {

int cmd_demo_scene(int argc, char** argv) {
  const Options o =
      parse_options(argc, argv, 2, {"-o", "--cubes", "--curve", "--edges", "--perspective"}, {});
  if (!o.error.empty()) return fail(o.error);
  if (!o.get("--curve").empty() || !o.get("--edges").empty() || !o.get("--perspective").empty())
    return cmd_demo_curve(o);
  if (o.get("-o").empty() || !o.positional.empty())
    return fail(std::string(o.get("-o").empty() ? "demo-scene: missing -o OUTPUT"
                                                : "demo-scene: takes no input file") +
                "\n" + usage_of(kDemoSceneUsage));
  int64_t cubes = 28;
  std::string error;
  if (!read_int_option(o, "--cubes", 1, 200, &cubes, &error)) return fail(error);
  const std::string path = o.get("-o");
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".obj") == 0) {
    // The same array as a solid model in world units (side 100, pitch 125), for the
    // hidden-line modes: six quads per cube, counter-clockwise seen from outside. Written
    // Y-up, as most OBJ files are (read back with the default --up y, the cubes stand on the
    // ground plane as the chip's own cube arrays do): world (x, y, z) is file (x, z, -y).
    error = write_atomically(path, [&](std::ostream& out) {
      out << "# haloplot demo: " << cubes << " x " << cubes
          << " cubes (HALO paper, Figure 4) as a solid model\n";
      for (int64_t i = 0; i < cubes; ++i)
        for (int64_t j = 0; j < cubes; ++j)
          for (int k = 0; k < 8; ++k)
            out << "v " << i * 125 + (k & 1) * 100 << ' ' << ((k >> 2) & 1) * 100 << ' '
                << -(j * 125 + ((k >> 1) & 1) * 100) << '\n';
      static const int kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
      for (int64_t c = 0; c < cubes * cubes; ++c)
        for (const auto& f : kFaces)
          out << "f " << c * 8 + f[0] + 1 << ' ' << c * 8 + f[1] + 1 << ' ' << c * 8 + f[2] + 1
              << ' ' << c * 8 + f[3] + 1 << '\n';
      return true;
    });
    return error.empty() ? 0 : fail(error);
  }
  CubeArrayParams p;
  p.cubes = int(cubes);
  const std::vector<Edge3> edges = cube_array(p);
  const std::string header = "# haloplot demo: " + std::to_string(cubes) + " x " +
                             std::to_string(cubes) +
                             " cubes, azimuth 30, elevation 40 (HALO paper, Figure 4)\n"
                             "# x1 y1 z1 x2 y2 z2 in steps; z larger = nearer\n";
  error = write_atomically(o.get("-o"), [&](std::ostream& out) {
    write_edges(out, edges, header);
    return true;
  });
  return error.empty() ? 0 : fail(error);
}

}  // namespace haloplot::host
