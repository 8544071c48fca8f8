// Write-then-rename, so a failed run never leaves a half-written output behind.
#pragma once
#include <fstream>
#include <functional>
#include <string>

namespace haloplot::host {

// Calls write(stream) on PATH.tmp, then renames it over PATH. Returns "" or an error message.
std::string write_atomically(const std::string& path,
                             const std::function<bool(std::ostream&)>& write);

}  // namespace haloplot::host
