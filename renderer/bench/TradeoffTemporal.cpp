// TradeoffRunner's errors for --metric temporal (issue 35 part 4): each point
// renders the camera path's frames in order, its history (TAA's) carried from
// each frame to the next, and its temporal error (renderer/metrics/
// TemporalError.h) is measured against the same cameras' frames of the
// reference (its cache traces each camera once) or of --against's knobs.
#include <cmath>
#include <limits>
#include <map>

#include "renderer/Error.h"
#include "renderer/RenderSession.h"
#include "renderer/bench/ConfigurationRunner.h"
#include "renderer/bench/TradeoffRunner.h"
#include "renderer/metrics/TemporalError.h"
#include "renderer/passes/TaaPass.h"

namespace dw {

namespace {

// Frames at the path's first camera before its frames are taken: a temporal
// method's history is then the point's own (not the last point's) and has
// seen every jitter offset once.
constexpr int kSettleFrames = TaaPass::kJitterPeriod;

// The temporal error as an estimate whose "tiles" are the frame pairs (each
// pair's error summed over 1), so ConfidentFront resamples pairs.
ErrorEstimate estimateOf(const TemporalErrorResult& r) {
    ErrorEstimate e;
    e.value = r.mean;
    e.low = r.interval.valid() ? r.interval.low : std::numeric_limits<double>::quiet_NaN();
    e.high = r.interval.valid() ? r.interval.high : std::numeric_limits<double>::quiet_NaN();
    e.tiles.metric = "temporal";
    e.tiles.sums = r.pairs;
    e.tiles.counts.assign(r.pairs.size(), 1.0);
    return e;
}

}  // namespace

std::vector<ErrorEstimate> TradeoffRunner::capturePathErrors(RenderSession& session, ConfigurationRunner& runner,
                                                             const TradeoffReference& reference,
                                                             std::vector<std::string>& notes,
                                                             const BenchProgress& say) const {
    const int cameraCount = static_cast<int>(cameras_.size());
    const FrameRequest request{{gpuOutput(o_.buffer)}};
    std::map<std::string, FloatImage> againstImages;  // by configuration (every knob) and camera
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<ErrorEstimate> errors(points_.size(), ErrorEstimate{nan, nan, nan, {}});
    for (size_t p = 0; p < points_.size(); ++p) {
        const int first = static_cast<int>(p) * cameraCount;
        try {
            for (int i = 0; i < kSettleFrames; ++i) runner.capture(first, 0, FrameRequest{});
            std::vector<FloatImage> tests, against;
            for (int c = 0; c < cameraCount; ++c)  // in order: nothing else renders between them
                tests.push_back(measuredImage(runner.capture(first + c, 0, request), o_.buffer));
            for (int c = 0; c < cameraCount; ++c) {
                session.camera() = cameraOf(p, c);
                against.push_back(againstImage(session, reference, c, againstImages));
            }
            errors[p] = estimateOf(TemporalError::measure(against, tests, o_.resamples, pointSeed(p, 0)));
        } catch (const Error& err) {
            notes.push_back("point " + std::to_string(points_[p].index) + ": no temporal error: " + err.what());
            if (say) say("tradeoff: " + notes.back());
        }
    }
    return errors;
}

}  // namespace dw
