#include "trace/trace_encoder.h"

namespace haloplot {

void TraceEncoder::put(const char* text) {
  uint32_t n = 0;
  while (text[n]) ++n;
  sink_.write(sink_.context, text, n);
}

void TraceEncoder::put_u64(uint64_t v) {
  char digits[20];
  uint32_t n = 0;
  do {
    digits[19 - n++] = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v);
  sink_.write(sink_.context, digits + 20 - n, n);
}

void TraceEncoder::put_i64(int64_t v) {
  if (v < 0) {
    put("-");
    put_u64(uint64_t(0) - uint64_t(v));
  } else {
    put_u64(uint64_t(v));
  }
}

TraceEncoder::TraceEncoder(CharSink sink, const Machine& m) : sink_(sink) {
  put("haloplot-trace 1\ntick_hz ");
  put_u64(m.tick_hz);
  put(m.kinematics == Kinematics::kCoreXY ? "\nkinematics corexy\nsteps "
                                          : "\nkinematics cartesian\nsteps ");
  put_u64(m.steps_num);
  put("/");
  put_u64(m.steps_den);
  put("\nbacklash ");
  put_u64(m.backlash[0]);
  put(" ");
  put_u64(m.backlash[1]);
  put("\n");
}

void TraceEncoder::flush(uint8_t motor) {
  Run& r = runs_[motor];
  if (r.count == 0) return;
  put(motor == 0 ? "m 0 " : "m 1 ");
  put_u64(r.t0);
  put(" ");
  put_u64(r.count);
  put(" ");
  put_i64(r.dt);
  put(" ");
  put_i64(r.ddt);
  put(r.backward ? " -\n" : " +\n");
  r = Run{};
}

void TraceEncoder::step(uint64_t tick, uint8_t motor, bool backward) {
  Run& r = runs_[motor];
  if (r.count > 0 && r.backward == backward) {
    const int64_t gap = int64_t(tick - r.last);
    if (r.count == 1) {
      r.dt = r.last_dt = gap;
      r.last = tick;
      ++r.count;
      return;
    }
    if (r.count == 2) r.ddt = gap - r.last_dt;
    if (gap == r.last_dt + r.ddt) {
      r.last_dt = gap;
      r.last = tick;
      ++r.count;
      return;
    }
  }
  flush(motor);
  r.t0 = r.last = tick;
  r.count = 1;
  r.backward = backward;
}

void TraceEncoder::pen(uint64_t tick, bool down) {
  put("p ");
  put_u64(tick);
  put(down ? " down\n" : " up\n");
}

void TraceEncoder::finish(uint64_t end_tick) {
  flush(0);
  flush(1);
  put("end ");
  put_u64(end_tick);
  put("\n");
}

}  // namespace haloplot
