#pragma once
// Where a frame's error comes from (`tradeoff --attribute`, Python
// attribute(), issue 34 part 4). For one view at the run's settings, against
// the CPU reference of that view (one reference: every row keeps the knobs
// the reference honours), the error (ImageError: the metric with its
// tile-bootstrap 95% interval) of
//   as_is          the settings as they are;
//   all_exact      every approximation family (ApproximationFamilies) at its
//                  most accurate setting;
//   and for each family F:
//     only_exact        the settings as they are with F alone made exact;
//     only_approximate  everything exact but F, left as it is.
// F's part is measured both ways: removed = as_is - only_exact (what making
// F exact takes away) and added = only_approximate - all_exact (what F
// alone adds to an otherwise exact frame), each with a paired 95% interval
// (the same tiles resampled for both images, 16x16 px as ImageError's).
// The parts need not add up: approximations interact (an AO error hides
// under a shadow, a threshold's cut light has no shadow to miss); the
// result says by how much they fail to (the sum of the parts against the
// total as_is - all_exact, both ways).
// Only error metrics whose parts subtract (flip, rms); psnr and ssim are
// refused. Needs a current GL 4.5 context to run().
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "renderer/RunConfig.h"
#include "renderer/bench/ImageError.h"
#include "renderer/bench/TradeoffRunner.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/scene/Scene.h"

namespace dw {

class RenderSession;

struct AttributionOptions {
    RunConfig run;                   // scene, preset, --set, width x height: the settings as they are
    std::string metric = "flip";     // flip | rms
    std::string buffer = "final";    // final | lbuffer | ao | shadow (TradeoffRunner::gpuOutput)
    int resamples = 2000;            // bootstrap resamples of every interval
};

// A difference of two errors on the same tiles with its 95% paired interval.
struct ErrorDifference {
    double value = 0.0, low = 0.0, high = 0.0;  // NaN: not measured
};

struct AttributionFamily {
    std::string name, what;
    std::vector<std::string> exact;    // the knob=value sets applied (those the scene's settings already hold included)
    std::vector<std::string> kept;     // knobs of the family left as they are: the reference honours them here
    ErrorEstimate onlyExact, onlyApproximate;
    ErrorDifference removed, added;    // as_is - only_exact; only_approximate - all_exact
};

struct AttributionResult {
    std::string metric, buffer;
    int width = 0, height = 0;
    ErrorEstimate asIs, allExact;
    ErrorDifference total;             // as_is - all_exact
    std::vector<AttributionFamily> families;
    double sumRemoved = 0.0, sumAdded = 0.0;  // the parts summed, against total.value
    int renders = 0;                   // distinct configurations rendered (rows that set nothing new share a frame)
    std::vector<std::string> notes;
};

// One attribution a configuration at a time: the window steps it once a UI
// frame (its Pareto panel); ErrorAttribution::run loops over it. Each step
// renders one configuration (the knobs as they are with a row's sets on
// top; a configuration whose knobs equal an earlier one's reuses its image),
// measures it and puts the session's knobs back.
class AttributionRun {
public:
    // `asIs`: the knobs as they are; `truth`: the reference's `buffer` image
    // of the view the session renders, at its size. Throws Error for a
    // metric other than flip or rms or an unknown buffer.
    void start(const KnobRegistry& asIs, const Scene& scene, FloatImage truth, const std::string& metric,
               const std::string& buffer, int resamples = 2000);
    // The next configuration; true while configurations remain. On the last
    // it computes the parts. An error stops the run (error() says it).
    bool step(RenderSession& session);
    void cancel() { running_ = false; }
    bool running() const { return running_; }
    bool done() const { return done_; }
    double progress() const;  // configurations measured over all, 0..1
    size_t configurations() const { return sets_.size(); }  // rows measured (rows that set nothing new share a frame)
    const std::string& error() const { return error_; }
    const AttributionResult& result() const { return result_; }

private:
    struct Measured;
    void measure(RenderSession& session, size_t configuration);
    void finish();
    KnobRegistry asIs_;
    FloatImage truth_;
    std::string metric_, buffer_, error_;
    int resamples_ = 2000;
    std::vector<std::vector<std::string>> sets_;  // per configuration: as_is, all_exact, then each family's two
    std::vector<std::shared_ptr<Measured>> measured_;
    size_t next_ = 0;
    bool running_ = false, done_ = false;
    AttributionResult result_;
};

class ErrorAttribution {
public:
    // Checks the metric (flip or rms), the buffer and the run, loads the
    // scene: Error / FileError before any GL.
    explicit ErrorAttribution(AttributionOptions options);
    // Error for a metric other than flip or rms, or an unknown buffer.
    static void checkMetricAndBuffer(const std::string& metric, const std::string& buffer);

    // Renders each distinct configuration once (untimed) and measures it
    // (AttributionRun, stepped to the end).
    // `reference` as tradeoff's (TradeoffStudy's cached references); `say`
    // gets a progress line per configuration.
    AttributionResult run(const TradeoffReference& reference, const std::function<void(const std::string&)>& say = {});

    const Scene& scene() const { return scene_; }
    const AttributionOptions& options() const { return o_; }

    // The Markdown table `tradeoff --attribute` prints, and its CSV (one row
    // per family and the two whole-frame rows; columns in docs/tradeoffs.md).
    static std::string table(const AttributionResult& r);
    static std::string csv(const AttributionResult& r);

private:
    AttributionOptions o_;
    Scene scene_;
};

}  // namespace dw
