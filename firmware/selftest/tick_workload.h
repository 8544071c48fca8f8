// The workload both step-tick benchmarks time, so the host figure (callgrind,
// tests/bench/step_tick_bench.cpp) and the Cortex-M4 figure (QEMU -icount,
// firmware/selftest/plot_selftest.cpp) measure the same thing: a 3 : 2 Bresenham move in
// segments of 16 steps with a gentle ramp, the shape the step prep makes while cruising.
#pragma once
#include "haloplot/motion/step_segment.h"

namespace bench {

template <typename Queue>
void fill_tick_workload(Queue& queue, bool* first_segment) {
  while (!queue.full()) {
    haloplot::StepSegment s;
    s.kind = haloplot::StepSegment::kSteps;
    s.new_block = *first_segment;
    *first_segment = false;
    s.dominant = 0;
    s.dir_bits = 0;
    s.major = 3000000;
    s.minor = 2000000;
    s.count = 16;
    s.interval_q8 = 100 * 256;
    s.add_q8 = -1;
    queue.push(s);
  }
}

}  // namespace bench
