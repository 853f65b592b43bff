#pragma once
// One `tradeoff` measurement in this process, shared by `tradeoff` and by
// `replay` of a tradeoff record: a headless GL context, the references
// through the shared cache (each distinct one rendered once in the run), the
// runner's timed rounds and errors, and the machine fields a record holds.
// Reads: a TradeoffRunner (options checked, scene loaded). Writes: the
// TradeoffResult, its settings with the references' counts and seconds.
// Follows issue 23 (tradeoff) and issue 24 (records).
#include <string>

#include "renderer/bench/TradeoffRunner.h"

namespace dw {

struct TradeoffMeasurement {
    TradeoffResult result;
    BenchFields machine;  // the GL strings and platform, cpu, compiler, date
};

// `aoRays`: the reference's AO rays per pixel; `quiet`: no progress on stderr.
TradeoffMeasurement measureTradeoff(TradeoffRunner& runner, int aoRays, bool quiet);

}  // namespace dw
