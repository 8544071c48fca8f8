#include "link/serial_port.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

namespace haloplot::host {
namespace {

class FdTransport : public Transport {
 public:
  explicit FdTransport(int fd) : fd_(fd) {}
  ~FdTransport() override { ::close(fd_); }
  bool write(const uint8_t* b, size_t n) override {
    while (n > 0) {
      const ssize_t w = ::write(fd_, b, n);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) return false;
      b += w, n -= size_t(w);
    }
    return true;
  }
  size_t read(uint8_t* out, size_t cap, int timeout_ms) override {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, timeout_ms) <= 0) return 0;
    const ssize_t r = ::read(fd_, out, cap);
    if (r == 0) closed_ = true;  // readable with no data: end of stream
    return r > 0 ? size_t(r) : 0;
  }
  bool closed() const override { return closed_; }

 private:
  int fd_;
  bool closed_ = false;
};

int connect_socket(const std::string& path) {
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  if (fd < 0) return -1;
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::strncpy(addr.sun_path, path.c_str(), sizeof addr.sun_path - 1);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0) return fd;
  ::close(fd);
  return -1;
}

}  // namespace

std::unique_ptr<Transport> open_port(const std::string& path, int wait_ms, std::string* error) {
  if (path.size() >= sizeof(sockaddr_un{}.sun_path)) {
    *error = path + ": path too long";
    return nullptr;
  }
  // A device node does not appear by waiting (a socket that QEMU is about to serve does).
  if (path.rfind("/dev/", 0) == 0) wait_ms = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(wait_ms);
  for (;;) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && S_ISSOCK(st.st_mode)) {
      const int fd = connect_socket(path);
      if (fd >= 0) return std::make_unique<FdTransport>(fd);
    } else if (::stat(path.c_str(), &st) == 0) {
      const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY);
      if (fd < 0) {
        *error = path + ": " + std::strerror(errno);
        return nullptr;
      }
      termios t{};
      if (::tcgetattr(fd, &t) == 0) {  // a tty: raw, 115200 8N1 (board/pins.h)
        ::cfmakeraw(&t);
        ::cfsetspeed(&t, B115200);
        ::tcsetattr(fd, TCSANOW, &t);
      }
      return std::make_unique<FdTransport>(fd);
    }
    if (std::chrono::steady_clock::now() > deadline) {
      *error = path + ": no such serial device or socket";
      return nullptr;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

}  // namespace haloplot::host
