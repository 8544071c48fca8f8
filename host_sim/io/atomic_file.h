// The outputs of one run, committed together or not at all: a failed run leaves no output
// behind, neither half-written nor a partial set (the SVG without the spans that failed).
//
// Where an output goes:
//   - a regular file, or a path that does not exist yet: written to PATH.tmp beside it and
//     renamed over it when the run commits;
//   - a symbolic link: followed; its target is written as above and the link stays a link;
//   - "-": standard output; a character device (/dev/null, a serial port) or a FIFO: written
//     through when the run commits (staged in a temporary file until then), never replaced;
//   - anything else (a directory, a socket, a link to nowhere) is refused by name.
#pragma once
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace haloplot::host {

class OutputSet {
 public:
  OutputSet();   // becomes the current set: write_atomically() stages into it
  ~OutputSet();  // removes what was staged and not committed
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // Stages one output; "" or an error message naming the path.
  std::string stage(const std::string& path, const std::function<bool(std::ostream&)>& write);
  // Puts every staged output in place, in the order staged; "" or an error message.
  std::string commit();

 private:
  struct Staged {
    std::string path, target, tmp;
    bool through;  // "-", a device or a FIFO: copied into, never replaced
  };
  std::vector<Staged> staged_;
  OutputSet* previous_;
};

// Why PATH cannot be written as an output, checked before a command does its work (so a
// missing folder is said at once, not after minutes of work): "" when it can. The same rules
// as staging (above), and for a file its folder must exist and take a new file (PATH.tmp).
std::string output_problem(const std::string& path);

// SIGINT, SIGTERM and SIGHUP remove every temporary file the current outputs have staged or are
// writing before the signal ends the process as it would have (nothing half-written is left,
// neither PATH.tmp nor a staged copy). Installed by the first OutputSet; a signal the process
// was started ignoring (nohup) stays ignored.
void remove_staged_on_signal();

// Stages PATH in the current OutputSet (the haloplot tool keeps one per command and commits
// it when the command succeeds); with none current, writes and commits at once. Returns "" or
// an error message.
std::string write_atomically(const std::string& path,
                             const std::function<bool(std::ostream&)>& write);

}  // namespace haloplot::host
