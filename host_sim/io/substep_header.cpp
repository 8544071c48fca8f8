#include "io/substep_header.h"

#include "haloplot/geometry/contract.h"
#include "io/line_reader.h"

namespace haloplot::host {

std::string substep_header(int32_t substep_bits) {
  return substep_bits > 0 ? "# substep " + std::to_string(substep_bits) + "\n" : "";
}

bool read_substep_header(const std::string& comments, int32_t* substep_bits, std::string* why) {
  *substep_bits = 0;
  const std::string key = "# substep ";
  const size_t at = comments.find(key);
  if (at == std::string::npos) return true;
  const size_t end = comments.find('\n', at);
  const std::string value =
      comments.substr(at + key.size(), end == std::string::npos ? end : end - at - key.size());
  int64_t v = 0;
  if (!parse_int(value, 0, kMaxSubstepBits, &v)) {
    *why = "bad '# substep' header '" + excerpt(value) + "': sub-step bits are an integer in [0, " +
           std::to_string(kMaxSubstepBits) + "]";
    return false;
  }
  *substep_bits = int32_t(v);
  return true;
}

}  // namespace haloplot::host
