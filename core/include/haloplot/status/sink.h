// Where a stage's results go, one at a time: a plain function and its context, so the firmware
// streams them into the next stage without a buffer and the host collects them. A sink that
// returns anything but kOk stops the stage with that status. Every stage's sink is this one
// template (DRAW's SpanSink is Sink<Span>, the QI's QiSink is Sink<QiPiece>, ...). The stages
// that hand on two kinds of result (FallbackSink, HiddenSink: pieces and outline runs) carry one
// function per kind; the trace's CharSink writes text and cannot fail, so it returns nothing.
#pragma once
#include "haloplot/status/status.h"

namespace haloplot {

template <typename T>
struct Sink {
  Status (*emit)(void* context, const T& item);
  void* context;
};

}  // namespace haloplot
