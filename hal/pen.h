// The pen lift: a hobby servo or a solenoid. The motion queue orders pen changes with the
// steps and waits travel + settle ticks after each (Machine::pen_travel_ticks,
// pen_settle_ticks), so the implementation only sets the position.
//
//   struct MyPen {
//     void set(bool down);   // servo pulse width or solenoid pin
//   };
#pragma once
