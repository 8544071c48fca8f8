// Command-line options for the haloplot tool: "--name value" and "--flag" pairs after a
// subcommand and its positional arguments. Unknown options are errors, never ignored.
#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

namespace haloplot::host {

struct Options {
  std::vector<std::string> positional;
  std::map<std::string, std::string> values;
  std::set<std::string> flags;
  std::string error;

  bool has(const std::string& flag) const { return flags.count(flag) != 0; }
  std::string get(const std::string& name, const std::string& fallback = "") const {
    auto it = values.find(name);
    return it == values.end() ? fallback : it->second;
  }
};

// The edit distance between two words (insertions, deletions, substitutions).
size_t edit_distance(const std::string& a, const std::string& b);
// The candidate nearest to `word` within two edits, or "" (for "did you mean" suggestions).
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);

// valued: options that take a value ("-o", "--halo"), as "--halo 5" or "--halo=5"; boolean:
// options that do not. An unknown option is an error that suggests the nearest known one and
// lists them all.
Options parse_options(int argc, char** argv, int first, const std::set<std::string>& valued,
                      const std::set<std::string>& boolean);

// Why an SVG output path cannot be written as named ("-o x.png": an image format the tool does
// not write), or "" when it can (.svg, no extension, "-", a device).
std::string svg_output_problem(const std::string& path);

}  // namespace haloplot::host
