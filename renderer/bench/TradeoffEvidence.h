#pragma once
// What `tradeoff` decides its front from (ConfidentFront's paired
// bootstrap), made from what the run measured:
//   time   per configuration and counted frame, the frame's time under
//          --time (the frame series, one pass or span, or the sum of a sum's
//          terms in that same frame); grouped by the interleaved round the
//          frame was rendered in (sample k is in round k / block for every
//          configuration). Draw b resamples the rounds with replacement,
//          the same rounds for every row, and takes the median of the drawn
//          rounds' frames. Fewer than kMinIntervalSamples (6) rounds: no
//          draws (the time is then never told apart).
//   error  per camera, the metric's per-tile sums (ErrorTiles). Draw b
//          resamples each camera's tiles with replacement, the same tiles
//          for every row, and recomputes the metric (an "all" row: the mean
//          over its cameras).
// Every row draws from generators with the same seeds, so draw b of two rows
// used the same resample: the pairing. Needs no GL.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "renderer/bench/BenchResults.h"
#include "renderer/bench/ConfidentFront.h"
#include "renderer/bench/ImageError.h"

namespace dw {

// config -> counted sample -> GPU ms of the time in that frame.
using FrameTimes = std::map<int, std::map<int, double>>;

// The per-frame time of `terms` (TradeoffTable::timeTerms: "frame", or
// passes/spans summed within each frame; a term that did not run in a frame
// adds nothing, a frame where none ran has no time).
FrameTimes frameTimes(const std::vector<BenchSample>& samples, const std::vector<std::string>& terms);

// One row's data: its configurations' frames (one configuration a camera;
// an "all" row several) and its cameras' error tiles (nullptr: none).
struct RowData {
    std::vector<const std::map<int, double>*> frames;
    std::vector<const ErrorTiles*> tiles;  // index = camera
    bool lowerIsBetter = true;
    double error = 0.0;  // the point estimate as reported
    double time = 0.0;   // the median of the frames' times
};

struct EvidenceDraws {
    int resamples = 2000;
    int block = 1;  // counted frames per configuration per round
    std::uint64_t seed = 777;
};

// The row's evidence: cost = time (its median, with draws over rounds),
// error (flipped for psnr/ssim) with draws over tiles. Missing data: no draws.
FrontEvidence rowEvidence(const RowData& row, const EvidenceDraws& how);

}  // namespace dw
