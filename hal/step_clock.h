// The step clock: a one-shot timer that calls the step tick, which returns the delay to the
// next event in ticks (0: stop). The firmware arms a hardware timer compare; the simulator
// just adds the delay to its virtual time.
//
//   struct MyClock {
//     static constexpr uint32_t kHz = 1000000;  // must equal Machine::tick_hz
//     void arm(uint32_t ticks);                 // call the tick after `ticks`
//     void stop();
//   };
#pragma once
