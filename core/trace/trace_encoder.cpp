#include "haloplot/trace/trace_encoder.h"

namespace haloplot {
namespace {
// Signed values go out zigzagged (0, -1, 1, -2, ... as 0, 1, 2, 3, ...) so small ones of
// either sign take one byte.
uint64_t zigzag(int64_t v) { return (uint64_t(v) << 1) ^ (v < 0 ? ~uint64_t(0) : 0); }
}  // namespace

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

void TraceEncoder::put_varint(uint64_t v) {
  while (v >= 0x80) {
    put_byte(uint8_t(v | 0x80));
    v >>= 7;
  }
  put_byte(uint8_t(v));
}

TraceEncoder::TraceEncoder(CharSink sink, const Machine& m, TraceForm form)
    : sink_(sink), form_(form) {
  put(form == TraceForm::kBinary ? "haloplot-trace 2 binary\ntick_hz "
                                 : "haloplot-trace 2\ntick_hz ");
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
  put(form == TraceForm::kBinary ? "\ndata\n" : "\n");
}

// Tags of the binary form: the low two bits say the record, the rest carry small fields.
void TraceEncoder::write_block(const StepSegment& b) {
  if (form_ == TraceForm::kBinary) {
    put_byte(uint8_t(1 | b.dominant << 2 | (b.dir_bits & 3u) << 3));
    put_varint(b.major);
    put_varint(b.minor);
    return;
  }
  put(b.dominant == 0 ? "b 0 " : "b 1 ");
  put_u64(b.major);
  put(" ");
  put_u64(b.minor);
  put((b.dir_bits & 1u) ? " -" : " +");
  put((b.dir_bits & 2u) ? "-\n" : "+\n");
}

void TraceEncoder::write_steps(uint64_t count, int64_t delta, int64_t add) {
  if (form_ == TraceForm::kBinary) {
    put_byte(uint8_t(count < 64 ? count << 2 : 0));  // 0: the count follows as a varint
    if (count >= 64) put_varint(count);
    put_varint(zigzag(delta));
    put_varint(zigzag(add));
    return;
  }
  put("s ");
  put_u64(count);
  put(" ");
  put_i64(delta);
  put(" ");
  put_i64(add);
  put("\n");
}

void TraceEncoder::write_pen(uint64_t tick, bool down, uint32_t dwell) {
  if (form_ == TraceForm::kBinary) {
    put_byte(uint8_t(2 | (down ? 4 : 0)));
    put_varint(tick);
    put_varint(dwell);
    return;
  }
  put("p ");
  put_u64(tick);
  put(down ? " down " : " up ");
  put_u64(dwell);
  put("\n");
}

void TraceEncoder::write_end(uint64_t tick) {
  if (form_ == TraceForm::kBinary) {
    put_byte(3);
    put_varint(tick);
    put_varint(digest_);
    return;
  }
  put("end ");
  put_u64(tick);
  put(" ");
  put_u64(digest_);
  put("\n");
}

// Writes the open line with the events it really ran (all of them, unless the plot stopped
// inside it), after its block's b line if that is not out yet. The interval is written as the
// change the segment makes to the tick's interval register, which after a line of n events
// from I by A holds I + n A: a ramp that goes on writes 0 there, so lines stay short.
void TraceEncoder::close_line() {
  if (!line_.open) return;
  line_.open = false;
  if (line_.ran == 0) return;  // loaded, never stepped: the plot stopped first
  if (block_pending_) {
    block_pending_ = false;
    write_block(block_);
  }
  write_steps(line_.ran, line_.interval_q8 - register_q8_, line_.add_q8);
  register_q8_ = line_.interval_q8 + int64_t(line_.ran) * line_.add_q8;
}

void TraceEncoder::segment(const StepSegment& s) {
  if (s.kind == StepSegment::kPen) {
    close_line();
    write_pen(pen_tick_, pen_down_, s.dwell_ticks);
    return;
  }
  // The tick's register after the open line's promised events: a segment that starts there
  // with the same add continues the ramp and joins the line.
  const int64_t next = line_.interval_q8 + int64_t(line_.count) * line_.add_q8;
  if (line_.open && !s.new_block && line_.ran == line_.count && s.interval_q8 == next &&
      s.add_q8 == line_.add_q8) {
    line_.count += s.count;
    return;
  }
  close_line();
  if (s.new_block) {
    block_ = s;
    block_pending_ = true;
    dominant_ = s.dominant;
  }
  line_ = Line{s.count, 0, s.interval_q8, s.add_q8, true};
}

void TraceEncoder::step(uint64_t tick, uint8_t motor, bool backward) {
  digest_ = trace_digest_step(digest_, 8 * tick + 2u * motor + (backward ? 1u : 0u));
  if (motor == dominant_) ++line_.ran;
}

void TraceEncoder::pen(uint64_t tick, bool down) {
  digest_ = trace_digest_step(digest_, 8 * tick + 4u + (down ? 1u : 0u));
  pen_tick_ = tick;
  pen_down_ = down;
}

void TraceEncoder::finish(uint64_t end_tick) {
  close_line();
  write_end(end_tick);
}

}  // namespace haloplot
