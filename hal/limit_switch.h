// End-stop switches, one per motor direction that has one. Polled by the main loop and by
// the tick when homing; a triggered switch stops motion at once.
//
//   struct MyLimits {
//     bool triggered(uint8_t motor, bool backward);
//   };
#pragma once
