#include "python/WorkbenchSession.h"

#include <algorithm>
#include <cmath>

#include "python/ProcessContext.h"
#include "renderer/OptionLimits.h"
#include "renderer/ao/AovCostEstimate.h"
#include "renderer/graph/RenamedOutputs.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

WorkbenchSession::WorkbenchSession(const std::string& scene, int width, int height, const std::vector<std::string>& presets,
                                   const std::vector<std::string>& settings) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        throw Error("size must be between 1x1 and 16384x16384, got " + std::to_string(width) + "x" +
                    std::to_string(height));
    run_.scene = scene;
    for (const std::string& p : presets) run_.addPreset(p);
    run_.sets = settings;
    run_.width = width;
    run_.height = height;
    // The settings first, against the declarations: a bad one is the
    // registry's message, as KnobError.
    KnobRegistry declared = RunConfig::declaredKnobs();
    for (const std::string& s : settings) {
        try {
            declared.applyAssignment(s);
        } catch (const Error& e) {
            throw KnobError(e.what());
        }
    }
    run_.validate();
    refuseNonSceneFile(run_.sceneSpec());
    Scene loaded = loadScene(run_.sceneSpec());  // CPU only: a bad file fails before any GL work

    const ProcessContext& pc = processContext();
    owner_ = pc.thread;
    requireOwningThread();
    pc.context->makeCurrent();
    session_ = std::make_unique<RenderSession>();
    session_->setScene(std::move(loaded), run_);
    resize(width, height);
}

WorkbenchSession::~WorkbenchSession() {
    if (session_ && std::this_thread::get_id() != owner_) static_cast<void>(session_.release());
}

void WorkbenchSession::checkRecordStart(std::optional<std::uint64_t> firstFrame, const std::string& what) const {
    const std::uint64_t frame = firstFrame.value_or(session_->pipeline().frameIndex());
    if (!session_->scene().flames.empty() && frame != 0)
        throw Error("record: '" + session_->scene().name + "' animates (its flame particles move with the frame index) "
                    "and " + what + " began at frame " + std::to_string(frame) +
                    "; replay renders from frame 0, as render --frames does: record the first render() of a Session "
                    "(a new Session starts at frame 0)");
}

ExperimentRecord WorkbenchSession::record() {
    requireOwningThread();
    if (!last_) throw Error("record: nothing rendered yet (call render() first)");
    if (isReferenceOutput(last_->buffer))
        throw Error("record: the last render() was of '" + last_->buffer + "', an output of the CPU reference: a "
                    "record holds no ao_rays or seed, so replay could not trace it again (render --record refuses it "
                    "too); render a GPU buffer, then record()");
    // The record's knobs and image hash must come from the same frames: a
    // set() since the render would pair new knobs with the old image.
    const KnobRegistry& k = session_->knobs();
    std::string changed;
    for (size_t i = 0; i < k.size() && i < last_->knobs.size(); ++i)
        if (k.format(static_cast<int>(i)) != last_->knobs[i])
            changed += (changed.empty() ? "" : ", ") + k.spec(static_cast<int>(i)).name;
    if (!changed.empty())
        throw Error("record: knobs changed since the last render() (" + changed +
                    "); render() again, then record(), so the record's knobs are the ones that made its image");
    // An animated scene (flame particles move with the frame index) looks as
    // its frame index says; replay renders from frame 0, as the CLI's render
    // does, so only a render() that began at frame 0 can be recorded.
    checkRecordStart(last_->firstCounted - static_cast<std::uint64_t>(last_->warmup), "the last render()");
    processContext().context->makeCurrent();
    RunConfig run = run_;
    run.width = width_;
    run.height = height_;
    run.frames = last_->frames;
    run.warmup = last_->warmup;
    // The knobs as they rendered (Session.set included): all of them travel in the record.
    return ExperimentRecord::capture(*session_, run, last_->buffer, last_->firstCounted,
                                     processContext().context->platform());
}

ExperimentRecord WorkbenchSession::benchRecord(BenchOptions options, const std::string& ratioOf, int resamples,
                                               BenchResults* measured,
                                               const std::function<void(const std::string&)>& costWarning) {
    const RecordedBench recorded{options, ratioOf, resamples};
    BenchRunner runner(std::move(options));  // checks everything that fails without GL
    if (costWarning) runner.setWarningSink(costWarning);
    ProcessContext& pc = processContext();
    if (std::this_thread::get_id() != pc.thread)
        throw WrongThreadError("bench must run on the thread that made the GL context (thread " +
                               describeThread(pc.thread) + ")");
    pc.context->makeCurrent();
    BenchResults results = runner.run();
    results.machine.emplace_back("gl_platform", pc.context->platform());
    BenchBaseline baseline = runner.baseline();
    baseline.series = ratioOf;
    if (!results.configs.empty() && !hasSeries(results, ratioOf))
        throw Error("ratio_of: no configuration recorded '" + ratioOf + "' (the pass did not run, or has no such span)");
    const BenchSummary summary = summarize(results, baseline, resamples);
    ExperimentRecord record = ExperimentRecord::forBench(recorded, runner.scene(), results, summary);
    if (measured) *measured = std::move(results);
    return record;
}

TradeoffMeasurement WorkbenchSession::tradeoff(TradeoffRunner& runner, int aoRays, ReferencePixels pixels,
                                               const TradeoffStudyProgress& progress) {
    ProcessContext& pc = processContext();
    if (std::this_thread::get_id() != pc.thread)
        throw WrongThreadError("tradeoff must run on the thread that made the GL context (thread " +
                               describeThread(pc.thread) + ")");
    pc.context->makeCurrent();
    return TradeoffStudy::measure(runner, aoRays, pc.context->platform(), progress, 1, pixels);
}

BudgetSearchResult WorkbenchSession::search(const BudgetSearchOptions& options, const TradeoffStudyProgress& progress) {
    ProcessContext& pc = processContext();
    if (std::this_thread::get_id() != pc.thread)
        throw WrongThreadError("tradeoff must run on the thread that made the GL context (thread " +
                               describeThread(pc.thread) + ")");
    pc.context->makeCurrent();
    return BudgetSearch::run(options, progress);
}

void WorkbenchSession::requireOwningThread() const {
    const std::thread::id here = std::this_thread::get_id();
    if (here != processContext().thread)
        throw WrongThreadError("the workbench's GL context belongs to thread " + describeThread(processContext().thread) +
                               "; this call came from thread " + describeThread(here) +
                               " (use each Session from the thread that made the first one)");
}

const KnobSpec& WorkbenchSession::spec(const std::string& givenName) const {
    requireOwningThread();
    const std::string name = session_->knobs().canonicalName(givenName);  // an old name warns and stands for the new
    const auto id = session_->knobs().find(name);
    if (!id) {
        // The registry's own message for an unknown name.
        KnobRegistry copy = session_->knobs();
        try {
            copy.setFromString(name, "0");
        } catch (const Error& e) {
            throw KnobError(e.what());
        }
        throw KnobError("unknown knob '" + name + "'");
    }
    return session_->knobs().spec(*id);
}

std::string WorkbenchSession::getText(const std::string& name) const {
    return session_->knobs().format(*session_->knobs().find(spec(name).name));
}

double WorkbenchSession::value(const std::string& name) const {
    return session_->knobs().value(*session_->knobs().find(spec(name).name));
}

void WorkbenchSession::set(const std::string& name, const std::string& text) {
    requireOwningThread();
    try {
        session_->knobs().setFromString(name, text);
    } catch (const Error& e) {
        throw KnobError(e.what());
    }
}

const KnobRegistry& WorkbenchSession::knobs() const {
    requireOwningThread();
    return session_->knobs();
}

std::vector<BufferInfo> WorkbenchSession::buffers() const {
    requireOwningThread();
    std::vector<BufferInfo> list;
    for (const PublishedOutput& o : session_->pipeline().outputs().all())
        list.push_back({o.decl.name, toString(o.decl.kind), o.pass, o.decl.description});
    return list;
}

std::string WorkbenchSession::aovCostWarning() const {
    return AovCostEstimate::check(session_->knobs(), session_->scene(), session_->camera(), width_, height_);
}

void WorkbenchSession::checkRender(const std::string& buffer, int frames, int warmup) const {
    requireOwningThread();
    if (!limits::kFrames.holds(frames))
        throw Error("frames must be between " + std::to_string(limits::kFrames.min) + " and " +
                    std::to_string(limits::kFrames.max) + " (as render --frames), got " + std::to_string(frames));
    if (!limits::kWarmup.holds(warmup))
        throw Error("warmup must be between " + std::to_string(limits::kWarmup.min) + " and " +
                    std::to_string(limits::kWarmup.max) + " (as render --warmup), got " + std::to_string(warmup));
    if (!session_->pipeline().outputs().find(buffer))
        throw UnknownBufferError(unknownBufferMessage(buffer) + " (Session.buffers() lists them)");
}

bool WorkbenchSession::isReferenceOutput(const std::string& buffer) const {
    return session_->isReferenceOutput(buffer);
}

std::uint64_t WorkbenchSession::lastFrameOf(int frames, int warmup) const {
    return session_->pipeline().frameIndex() + static_cast<std::uint64_t>(warmup + frames - 1);
}

BufferImage WorkbenchSession::render(const std::string& buffer, int frames, int warmup,
                                     const reference::ReferenceImages* reference) {
    checkRender(buffer, frames, warmup);
    if (isReferenceOutput(buffer) && !reference)
        throw Error("'" + buffer + "' needs the CPU reference of the view (render() traces it)");
    processContext().context->makeCurrent();
    // The reference pass shows the reference handed over for these frames
    // (what the workbench's F9 hands it), or none: a reference of an earlier
    // view never shows.
    session_->showReference(reference,
                            "no CPU reference of this view: Session.render(\"reference.*\") traces one");
    FrameRequest request;
    request.outputs = {buffer};
    PassTimer& timer = session_->pipeline().timer();
    timer.setHistoryLength(std::max<size_t>(PassTimer::kHistory, static_cast<size_t>(warmup + frames)));
    FrameReport report;
    std::uint64_t firstCounted = 0;
    for (int i = 0; i < warmup + frames; ++i) {
        report = session_->render(request);
        if (i == warmup) firstCounted = report.frameIndex;
    }
    rendered_ = true;
    timings_ = TimingReport::build(timer, report, firstCounted, warmup);
    frameWarnings_ = report.warnings();
    last_ = LastRender{buffer, frames, warmup, firstCounted, {}};
    const KnobRegistry& k = session_->knobs();
    for (size_t i = 0; i < k.size(); ++i) last_->knobs.push_back(k.format(static_cast<int>(i)));

    // What writeOutput writes: display-ready outputs as their 8-bit values
    // (.png), everything else raw (.exr).
    const PublishedOutput* o = session_->pipeline().outputs().find(buffer);
    BufferImage out;
    out.eightBit = isDisplayReady(*o);
    const FloatImage image = session_->readRaw(buffer);
    out.width = image.width;
    out.height = image.height;
    out.channels = image.channels;
    if (out.eightBit) {
        // ImageIO's 8-bit conversion (writeImage): clamp, scale, round half up.
        out.bytes.resize(image.pixels.size());
        for (size_t i = 0; i < image.pixels.size(); ++i) {
            const float v = image.pixels[i];
            const float clamped = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
            out.bytes[i] = static_cast<std::uint8_t>(clamped * 255.0f + 0.5f);
        }
    } else {
        out.floats = image.pixels;
    }
    return out;
}

ProbeResult WorkbenchSession::probe(int x, int y) const {
    requireOwningThread();
    if (!rendered_) throw Error("probe needs a rendered frame: call render() first");
    if (x < 0 || y < 0 || x >= width_ || y >= height_)
        throw Error("probe (" + std::to_string(x) + ", " + std::to_string(y) + ") lies outside the " +
                    std::to_string(width_) + "x" + std::to_string(height_) + " frame");
    return probePixel(session_->pipeline(), x, y);
}

void WorkbenchSession::writeBuffer(const std::string& buffer, const std::string& path) {
    requireOwningThread();
    if (!rendered_) throw Error("write needs a rendered frame: call render() first");
    if (!session_->pipeline().outputs().find(buffer))
        throw UnknownBufferError(unknownBufferMessage(buffer) + " (Session.buffers() lists them)");
    session_->writeOutput(buffer, path);
}

void WorkbenchSession::writeKnobValues(const std::string& path) const { session_->writeKnobValues(path); }

reference::ReferenceImages WorkbenchSession::reference(const ReferenceOptions& options,
                                                       std::optional<std::uint64_t> frame) const {
    ReferenceOptions o = options;
    if (!o.rayScenes) o.rayScenes = rayScenes_.get();  // the session's cameras share one ray scene
    return reference::traceViewReference(session_->scene(), session_->knobs(), session_->camera(), width_, height_, o,
                                         frame)
        .images;
}

void WorkbenchSession::setSceneTime(double seconds) {
    requireOwningThread();
    run_.sceneTime = seconds;
    session_->setSceneTime(seconds);
    session_->poseAtSceneTime();
}

void WorkbenchSession::resize(int width, int height) {
    requireOwningThread();
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        throw Error("size must be between 1x1 and 16384x16384, got " + std::to_string(width) + "x" +
                    std::to_string(height));
    session_->resize(width, height);
    width_ = width;
    height_ = height;
    rendered_ = false;
}

const std::string& WorkbenchSession::sceneName() const { return session_->scene().name; }

}  // namespace dw
