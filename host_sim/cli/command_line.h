// What every command does with its command line the same way: a refusal on stderr as
// "haloplot: ...", the input-and-output check with its usage lines, integer options read
// with their range in the message. One wording for all, so the commands refuse alike.
#pragma once
#include <cstdint>
#include <string>

#include "cli/options.h"
#include "haloplot/memory/parts.h"
#include "haloplot/status/status.h"

namespace haloplot::host {

// Says "haloplot: MESSAGE" on stderr; returns 1, the command's exit code.
int fail(const std::string& message);
// "STAGE failed: kStatusName".
int fail_status(const char* stage, Status s);

// "usage:\n" and a command's usage lines (cli/usage.cpp), for its --help and its refusals.
std::string usage_of(const char* usage_lines);

// True for one input file and an -o output, what cut, draw, plot, sim and replay take.
bool one_input_and_output(const Options& o);
// What is missing or extra among the input and -o, named, then the command's usage.
int bad_arguments(const Options& o, const std::string& cmd, const char* usage_lines);

// Reads the integer option `name` into *out when given (left as is when not); false with
// *error giving the range when it is not an integer in [lo, hi].
bool read_int_option(const Options& o, const std::string& name, int64_t lo, int64_t hi,
                     int64_t* out, std::string* error);

// --threads N (1 to 256; default: every core the machine has) as the core's parts runner;
// false with *error when N is not such a count.
bool read_threads_option(const Options& o, const Parts** parts, std::string* error);

// "12.345" from a count of thousandths (the plot time in --stats).
std::string thousandths(uint64_t v);

}  // namespace haloplot::host
