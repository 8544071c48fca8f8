#include "io/atomic_file.h"

#include <cstdio>

namespace haloplot::host {

std::string write_atomically(const std::string& path,
                             const std::function<bool(std::ostream&)>& write) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) return path + ": cannot open for writing";
    const bool fine = write(out);
    out.flush();
    if (!fine || !out) {
      out.close();
      std::remove(tmp.c_str());
      return path + ": write failed";
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    return path + ": cannot rename the finished file into place";
  }
  return "";
}

}  // namespace haloplot::host
