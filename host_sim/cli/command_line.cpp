#include "cli/command_line.h"

#include <iostream>

#include "io/line_reader.h"
#include "pipeline/thread_parts.h"

namespace haloplot::host {

int fail(const std::string& message) {
  std::cerr << "haloplot: " << message << "\n";
  return 1;
}

int fail_status(const char* stage, Status s) {
  return fail(std::string(stage) + " failed: " + status_name(s));
}

std::string usage_of(const char* usage_lines) { return std::string("usage:\n") + usage_lines; }

bool one_input_and_output(const Options& o) {
  return o.positional.size() == 1 && !o.get("-o").empty();
}

int bad_arguments(const Options& o, const std::string& cmd, const char* usage_lines) {
  std::string what;
  if (o.positional.empty())
    what = "missing the input file";
  else if (o.positional.size() > 1)
    what = "one input file expected, got " + std::to_string(o.positional.size()) + " ('" +
           o.positional[0] + "', '" + o.positional[1] + "'" +
           (o.positional.size() > 2 ? ", ..." : "") + ")";
  else
    what = "missing -o OUTPUT";
  return fail(cmd + ": " + what + "\n" + usage_of(usage_lines));
}

bool read_int_option(const Options& o, const std::string& name, int64_t lo, int64_t hi,
                     int64_t* out, std::string* error) {
  const std::string v = o.get(name);
  if (v.empty()) return true;
  if (!parse_int(v, lo, hi, out)) {
    *error = name + " '" + v + "' must be an integer in [" + std::to_string(lo) + ", " +
             std::to_string(hi) + "]";
    return false;
  }
  return true;
}

bool read_threads_option(const Options& o, const Parts** parts, std::string* error) {
  int64_t threads = machine_threads();
  const std::string v = o.get("--threads");
  if (!v.empty() && !parse_int(v, 1, kMaxThreads, &threads)) {
    *error = "--threads '" + v + "' must be a count of threads from 1 to 256 (default: " +
             std::to_string(machine_threads()) + ", this machine's cores)";
    return false;
  }
  *parts = thread_parts(uint32_t(threads));
  return true;
}

std::string thousandths(uint64_t v) {
  std::string f = std::to_string(v % 1000);
  return std::to_string(v / 1000) + "." + std::string(3 - f.size(), '0') + f;
}

}  // namespace haloplot::host
