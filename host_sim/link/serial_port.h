// A byte link to a controller: a serial device (a USB-serial adapter, set raw at 115200 8N1)
// or a Unix socket (QEMU's emulated USART: -chardev socket,...,server=on).
#pragma once
#include <memory>
#include <string>

#include "link/job_client.h"

namespace haloplot::host {

// Opens `path`; a socket is retried for up to `wait_ms` while its server starts. Null and
// *error set on failure.
std::unique_ptr<Transport> open_port(const std::string& path, int wait_ms, std::string* error);

}  // namespace haloplot::host
