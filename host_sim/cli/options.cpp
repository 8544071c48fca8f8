#include "cli/options.h"

#include <algorithm>
#include <cctype>

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
    std::string a = argv[i];
    if (a.size() > 1 && a[0] == '-') {
      // --name=value, as most tools take it, is --name value.
      const size_t eq = a.rfind("--", 0) == 0 ? a.find('=') : std::string::npos;
      const bool inline_value = eq != std::string::npos;
      const std::string value = inline_value ? a.substr(eq + 1) : "";
      if (inline_value) a = a.substr(0, eq);
      if (valued.count(a)) {
        if (!inline_value && i + 1 >= argc) {
          o.error = "option " + a + " needs a value";
          return o;
        }
        o.values[a] = inline_value ? value : argv[++i];
      } else if (boolean.count(a)) {
        if (inline_value) {
          o.error = "option " + a + " takes no value (given '" + value + "')";
          return o;
        }
        o.flags.insert(a);
      } else {
        std::vector<std::string> known(valued.begin(), valued.end());
        known.insert(known.end(), boolean.begin(), boolean.end());
        std::sort(known.begin(), known.end());
        const std::string near = nearest(a, known);
        o.error = "unknown option " + a + (near.empty() ? "" : " (did you mean " + near + "?)");
        o.error += "\nknown options:";
        for (const std::string& k : known) o.error += " " + k;
        return o;
      }
    } else {
      o.positional.push_back(a);
    }
  }
  return o;
}

std::string svg_output_problem(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  // Formats a user may well ask for by name; any other name (a device, "-") is written as SVG.
  static const std::set<std::string> kNotSvg = {"png",   "pdf",  "jpg", "jpeg", "gif", "bmp", "tif",
                                                "tiff",  "webp", "eps", "ps",   "dxf", "emf", "wmf",
                                                "gcode", "nc",   "ngc", "hpgl", "plt"};
  if (kNotSvg.count(ext) == 0) return "";
  std::string hint = "convert the SVG, for example with Inkscape or rsvg-convert";
  if (ext == "gcode" || ext == "nc" || ext == "ngc") hint = "for G-code give --gcode " + path;
  if (ext == "hpgl" || ext == "plt") hint = "for HPGL give --hpgl " + path;
  return "-o " + path + ": -o writes SVG only, not ." + ext + " (" + hint + ")";
}

}  // namespace haloplot::host
