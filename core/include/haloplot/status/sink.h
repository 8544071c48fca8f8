// Where a stage's results go, one at a time: a plain function and its context, so the firmware
// streams them into the next stage without a buffer and the host collects them. A sink that
// returns anything but kOk stops the stage with that status. Every stage's sink is this one
// template (DRAW's SpanSink is Sink<Span>, the QI's QiSink is Sink<QiPiece>, ...).
#pragma once
#include "haloplot/status/status.h"

namespace haloplot {

template <typename T>
struct Sink {
  Status (*emit)(void* context, const T& item);
  void* context;
};

}  // namespace haloplot
