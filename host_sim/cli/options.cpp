#include "cli/options.h"

namespace haloplot::host {

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
        o.error = "unknown option " + a;
        return o;
      }
    } else {
      o.positional.push_back(a);
    }
  }
  return o;
}

}  // namespace haloplot::host
