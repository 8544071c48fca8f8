#include "cli/options.h"

#include <algorithm>

namespace haloplot::host {

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  size_t best_d = 3;
  for (const std::string& c : candidates) {
    const size_t d = edit_distance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  return best;
}

Options parse_options(int argc, char** argv, int first, const std::set<std::string>& valued,
                      const std::set<std::string>& boolean) {
  Options o;
  for (int i = first; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.size() > 1 && a[0] == '-') {
      if (valued.count(a)) {
        if (i + 1 >= argc) {
          o.error = "option " + a + " needs a value";
          return o;
        }
        o.values[a] = argv[++i];
      } else if (boolean.count(a)) {
        o.flags.insert(a);
      } else {
        std::vector<std::string> known(valued.begin(), valued.end());
        known.insert(known.end(), boolean.begin(), boolean.end());
        const std::string near = nearest(a, known);
        o.error = "unknown option " + a + (near.empty() ? "" : " (did you mean " + near + "?)");
        return o;
      }
    } else {
      o.positional.push_back(a);
    }
  }
  return o;
}

}  // namespace haloplot::host
