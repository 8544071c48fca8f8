#include "platform/console.h"

#include "platform/semihosting.h"

namespace haloplot::fw {

void Console::write(void* ctx, const char* text, uint32_t length) {
  auto* c = static_cast<Console*>(ctx);
  for (uint32_t i = 0; i < length; ++i) {
    if (c->n_ == sizeof c->buf_) c->flush();
    c->buf_[c->n_++] = text[i];
  }
}

void Console::flush() {
  if (n_) semihost_write(buf_, n_);
  n_ = 0;
}

void Console::stat(const char* key, uint64_t value) {
  char line[96];
  char* p = append(line, "fw ");
  p = append(p, key);
  p = append(p, "=");
  p = append_u64(p, value);
  append(p, "\n");
  write(this, line, uint32_t(p - line + 1));
}

}  // namespace haloplot::fw
