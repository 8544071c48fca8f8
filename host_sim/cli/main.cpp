// haloplot: the host tool. Runs the same freestanding core as the firmware. This file holds
// the start-up and the table of commands; each command lives in cli/cmd_<name>.cpp
// (cli/commands.h), its usage lines in cli/usage.cpp.
#include <iostream>
#include <string>
#include <vector>
// After a C library header: they define __GLIBC__.
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "cli/command_line.h"
#include "cli/commands.h"
#include "io/atomic_file.h"

using namespace haloplot::host;

namespace {

struct Command {
  const char* name;
  const char* usage;  // its lines in `haloplot --help`
  int (*run)(int argc, char** argv);
};

// In the order `haloplot --help` lists them.
const Command kCommands[] = {
    {"demo-scene", kDemoSceneUsage, cmd_demo_scene},
    {"random-scene", kRandomSceneUsage, cmd_random_scene},
    {"cut", kCutUsage, cmd_cut},
    {"draw", kDrawUsage, cmd_draw},
    {"plot", kPlotUsage, cmd_plot},
    {"sim", kSimUsage, cmd_sim},
    {"replay", kReplayUsage, cmd_replay},
    {"send", kSendUsage, cmd_send},
    {"view2d", kView2dUsage, cmd_view2d},
};

const Command* find_command(const std::string& name) {
  for (const Command& c : kCommands)
    if (name == c.name) return &c;
  return nullptr;
}

// Every command's usage lines, the text of `haloplot --help`.
std::string full_usage() {
  std::string text = "usage:\n";
  for (const Command& c : kCommands) text += c.usage;
  return text;
}

// Every output the command will write, checked before any work: a missing folder is said
// at once, not after a long plot. These names are outputs in every command that has them.
std::string output_path_problem(int argc, char** argv) {
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    for (const char* name :
         {"-o", "--gcode", "--hpgl", "--spans", "--cut", "--trace", "--dump-edges"}) {
      const std::string n = name;
      std::string path;
      if (arg == n && i + 1 < argc)
        path = argv[i + 1];
      else if (arg.compare(0, n.size() + 1, n + "=") == 0)
        path = arg.substr(n.size() + 1);
      const std::string problem = path.empty() ? "" : output_problem(path);
      if (!problem.empty()) return problem;
    }
  }
  return "";
}

int run_command(int argc, char** argv) {
  const std::string cmd = argv[1];
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    std::cout << full_usage();
    return 0;
  }
  if (cmd == "--version" || cmd == "version") {
    std::cout << "haloplot " HALOPLOT_VERSION "\n";
    return 0;
  }
  const Command* command = find_command(cmd);
  for (int i = 2; i < argc; ++i)
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      // An unknown command's --help lists them all.
      std::cout << (command ? usage_of(command->usage) : full_usage());
      return 0;
    }
  if (const std::string problem = output_path_problem(argc, argv); !problem.empty())
    return fail(problem);
  if (command) return command->run(argc, argv);
  std::vector<std::string> names;
  for (const Command& c : kCommands) names.push_back(c.name);
  const std::string near = nearest(cmd, names);
  return fail("unknown command '" + cmd + "'" +
              (near.empty() ? "" : " (did you mean " + near + "?)") + "\n" + full_usage());
}

}  // namespace

// The tool is one command that builds and drops many large arrays (a big model's vertices,
// faces, sides, pieces, path): glibc would give each one back to the system when it is
// freed and take fresh pages for the next, a page fault per 4 KB every time. Keeping freed
// memory for reuse instead (as much as glibc allows in the heap: 32 MB per block) cut a
// 200,000-triangle plot's time by a fifth; the largest buffers come from HostMemory.
static void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_TOP_PAD, 16 << 20);
#endif
}

int main(int argc, char** argv) {
  keep_freed_memory();
  if (argc < 2) return fail(full_usage());
  // Every output of the command is staged here and put in place only when the command
  // succeeds, all together (io/atomic_file.h); a failed command leaves none behind.
  haloplot::host::OutputSet outputs;
  const int rc = run_command(argc, argv);
  if (rc != 0) return rc;
  const std::string error = outputs.commit();
  return error.empty() ? 0 : fail(error);
}
