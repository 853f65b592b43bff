#include "ui/FitBudgetView.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "renderer/Error.h"
#include "renderer/bench/TradeoffRunner.h"
#include "renderer/graph/PassTimer.h"
#include "renderer/passes/ReferencePass.h"
#include "renderer/reference/ReferenceModel.h"
#include "ui/Widgets.h"

namespace dw::ui {

namespace {

constexpr const char* kAction = "fit budget";
constexpr const char* kAgainstCurrent = "the current image (chosen: the current settings score 0)";
constexpr const char* kAgainstReference = "the CPU reference";

// The series whose measured change the panel shows: the time's terms, then the frame.
std::vector<std::string> shownSeries(const std::string& time) {
    std::vector<std::string> s;
    if (time != PassTimer::kFrameSeries) {
        try {
            s = TradeoffTable::timeTerms(time);
        } catch (const std::exception&) {
        }
    }
    s.push_back(PassTimer::kFrameSeries);
    return s;
}

bool sameChange(const KnobChange& a, const KnobChange& b) {
    return a.knobs == b.knobs && a.before == b.before && a.after == b.after;
}

// The first knob whose value differs between the two ("" when none).
std::string firstDifference(const KnobRegistry& a, const KnobRegistry& b) {
    for (int id = 0; id < static_cast<int>(a.size()); ++id)
        if (a.value(id) != b.value(id)) return a.spec(id).name;
    return {};
}

// The baseline every point is measured against: the current image by choice,
// else the CPU reference of the view (false: none shown, asked for).
bool baselineOf(bool againstCurrent, RenderSession& session, FloatImage& baseline, std::string& name) {
    const FloatImage current = TradeoffRunner::measuredImage(session, "final");
    if (againstCurrent) {
        baseline = current;
        name = kAgainstCurrent;
        return true;
    }
    if (const ReferencePass* ref = session.pipeline().pass<ReferencePass>(); ref && ref->reference())
        baseline = ref->reference()->final;
    name = kAgainstReference;
    return baseline.width == current.width && baseline.height == current.height && current.width > 0;
}

// A point as BudgetPicker's lines name it, "point 12 (a=v, b=v, ...)", and as
// the panel does: only the values that differ from the settings swept about.
std::string fullName(const TradeoffTable& t, const TradeoffRow& r) {
    std::string values;
    for (size_t a = 0; a < t.axes.size() && a < r.axisValues.size(); ++a)
        values += (values.empty() ? "" : ", ") + t.axes[a] + "=" + r.axisValues[a];
    return "point " + std::to_string(r.point) + (values.empty() ? "" : " (" + values + ")");
}

std::string shortName(const TradeoffTable& t, const TradeoffRow& r, const KnobRegistry& previous) {
    std::string values;
    for (size_t a = 0; a < t.axes.size() && a < r.axisValues.size(); ++a) {
        const auto id = previous.find(t.axes[a]);
        if (id && previous.format(*id) == r.axisValues[a]) continue;
        values += (values.empty() ? "" : ", ") + t.axes[a] + "=" + r.axisValues[a];
    }
    return "point " + std::to_string(r.point) + " (" + (values.empty() ? "the settings before the fit" : values) + ")";
}

// The picker's lines with each point named by what it changes (a sweep of
// some 30 axes one at a time named all 30 in every line), and a long list of
// the points tied with the pick as their count (the plot's tooltips name them).
std::vector<std::string> shortened(std::vector<std::string> lines, const FitBudgetRun& run) {
    constexpr size_t kListed = 6;
    for (std::string& l : lines) {
        for (const TradeoffRow& r : run.table().rows) {
            const std::string full = fullName(run.table(), r);
            if (const size_t at = l.find(full); at != std::string::npos)
                l.replace(at, full.size(), shortName(run.table(), r, run.previous()));
        }
        const size_t from = l.find("from point(s) "), fit = l.find(", which fit too");
        if (run.pick().tied.size() > kListed && from != std::string::npos && fit != std::string::npos && from < fit)
            l.replace(from, fit - from, "from " + std::to_string(run.pick().tied.size()) + " other points (ringed faintly)");
    }
    return lines;
}

}  // namespace

// Against the CPU reference: the effects on that its final image has not (as
// the CLI's note says), which a sweep then finds "more accurate" turned off.
static std::string unmodelledNote(bool againstCurrent, const RenderSession& session) {
    if (againstCurrent) return "";
    const auto model = reference::ReferenceModel::fromKnobs(session.knobs(), session.scene());
    const reference::KnobReport report = reference::reportKnobs(session.knobs(), model);
    std::string on;
    for (const auto& n : report.unmodelledOn) on += (on.empty() ? " " : ", ") + n;
    if (on.empty()) return "";
    return "note: the reference's final image has no" + on +
           ": a point that turns them off scores nearer it (set them false, aa.method none, to fit the shading alone)";
}

bool FitBudgetView::start(double budgetMs, bool againstCurrent, UiState& state, RenderSession& session) {
    message.clear();
    waitingForReference = false;
    FitBudgetSettings settings;
    settings.budgetMs = budgetMs;
    settings.time = time;
    try {
        FitBudgetRun::check(settings, session);  // before anything renders, the reference included
        if (state.sweep.running() || state.attribution.running() || state.recordRun.running() || state.measure.active())
            throw Error("a quick sweep, an attribution, a record or a cost of a change is being measured; "
                        "wait for it or cancel it");
        FloatImage baseline;
        std::string name;
        if (!baselineOf(againstCurrent, session, baseline, name)) {
            waitingForReference = true;
            waitingJobsEnded = state.referenceJobsEnded;
            state.requestReference = true;
            state.log.info("fit budget: tracing the CPU reference of the view first", state.time);
            return false;
        }
        state.fitBudget.start(session, std::move(baseline), name, settings);
    } catch (const std::exception& e) {
        message = std::string("fit budget not started: ") + e.what();
        state.log.error(message, state.time, kAction);
        return false;
    }
    pickLines.clear();
    summary.clear();
    referenceNote = unmodelledNote(againstCurrent, session);
    if (!referenceNote.empty()) state.log.info("fit budget: " + referenceNote, state.time);
    errorSaid = false;
    state.log.succeeded(kAction);
    state.log.info("fit budget: sweeping " + std::to_string(state.fitBudget.points()) +
                       " points of the speed/quality knobs about the current settings",
                   state.time);
    return true;
}

void FitBudgetView::update(double budgetMs, bool againstCurrent, UiState& state, RenderSession& session) {
    const FitBudgetRun& run = state.fitBudget;
    if (!errorSaid && !run.running() && !run.error().empty()) {
        errorSaid = true;
        message = "fit budget stopped: " + run.error() + "; nothing applied";
        state.log.error(message, state.time, kAction);
    }
    if (waitingForReference) {
        const ReferencePass* ref = session.pipeline().pass<ReferencePass>();
        if (ref && ref->reference()) {
            waitingForReference = false;
            start(budgetMs, againstCurrent, state, session);
        } else if (state.referenceJobsEnded != waitingJobsEnded && state.referenceProgress < 0.0 &&
                   !state.requestReference) {
            waitingForReference = false;
            message = "fit budget not started: the CPU reference of this view did not come (cancelled, failed or the "
                      "view changed; see Messages)";
            state.log.error(message, state.time, kAction);
        }
    }
    takeResult(state, session);
    followMeasurement(state);
}

void FitBudgetView::takeResult(UiState& state, RenderSession& session) {
    const FitBudgetRun& run = state.fitBudget;
    if (!run.done() || taken == run.finished()) return;
    taken = run.finished();
    errorSaid = true;
    pickLines = shortened(run.pick().lines, run);
    summary = std::to_string(run.points()) + " points about the settings, FLIP against " + run.baselineName() +
              (run.leftOut() ? "; " + std::to_string(run.leftOut()) + " left out: over the AOV cost limit" : "") +
              (referenceNote.empty() ? "" : "\n" + referenceNote);
    if (run.pick().point < 0) {
        message = "fit budget: nothing applied (no point fits the budget)";
        state.log.info(message + ": " + (pickLines.empty() ? std::string() : pickLines.front()), state.time);
        return;
    }
    // A measurement of another change sets the knobs between its frames: stopped first.
    if (state.measure.active()) state.measure.cancel(session.knobs(), "cancelled: fit budget applied its pick");
    if (const std::string moved = firstDifference(run.previous(), session.knobs()); !moved.empty()) {
        message = "fit budget: nothing applied: " + moved + " changed during the sweep (fit again)";
        state.log.error(message, state.time, kAction);
        return;
    }
    KnobRegistry trial = run.previous();
    try {
        for (const std::string& a : run.assignmentsOf(run.pick().point)) trial.applyAssignment(a);
    } catch (const std::exception& e) {
        message = std::string("fit budget: nothing applied: ") + e.what();
        state.log.error(message, state.time, kAction);
        return;
    }
    KnobChangeWatcher watcher;
    watcher.reset(run.previous());
    const std::optional<KnobChange> c = watcher.update(trial, false);
    verdict.reset();
    measureStatus.clear();
    if (!c) {
        applied = "the pick is the current settings: nothing to apply or measure";
        return;
    }
    session.knobs().copyValues(trial);
    change = c;
    applied = c->what;
    message.clear();
    state.log.done("fit budget applied point " + std::to_string(run.pick().point) + ": " + c->what, state.time, kAction);
    // The cost of the change, measured as the timings panel measures one.
    session.pipeline().timer().setPaused(false);
    state.measure.start(*c, ChangeMeasurement::Settings{}, passesReachedBy(session.pipeline(), c->knobs));
    measuring = true;
}

void FitBudgetView::followMeasurement(UiState& state) {
    if (!measuring || !change) return;
    const ChangeMeasurement& m = state.measure;
    if (m.state() == ChangeMeasurement::State::Idle || !sameChange(m.change(), *change)) {
        measuring = false;
        measureStatus = "not measured: another change took its place in the timings panel";
    } else if (m.state() == ChangeMeasurement::State::Done) {
        measuring = false;
        verdict = m.verdict();
    } else if (m.state() == ChangeMeasurement::State::Cancelled) {
        measuring = false;
        measureStatus = "measurement " + m.status();
    }
}

void FitBudgetView::undo(UiState& state, RenderSession& session) {
    if (!change) return;
    if (measuring && state.measure.active()) state.measure.cancel(session.knobs(), "cancelled: fit budget undone");
    measuring = false;
    for (size_t i = 0; i < change->knobs.size(); ++i) session.knobs().set(change->knobs[i], change->before[i]);
    state.log.done("fit budget undone: " + change->what + " reversed", state.time, kAction);
    applied.clear();
    message = "undone: the settings before fit budget are back";
    change.reset();
    verdict.reset();
    measureStatus.clear();
}

void FitBudgetView::draw(double& budgetMs, bool againstCurrent, UiState& state, RenderSession& session,
                         const std::string& counter, double* budgetCount) {
    controls(budgetMs, againstCurrent, state, session, counter, budgetCount);
    progress(state);
    result(state, session);
}

// The budget field, *fit budget* beside it, and the time it bounds.
void FitBudgetView::controls(double& budgetMs, bool againstCurrent, UiState& state, RenderSession& session,
                             const std::string& counter, double* budgetCount) {
    const float spacing = ImGui::GetStyle().FramePadding.x * 2.0f;
    const bool byCounter = !counter.empty() && budgetCount;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * (byCounter ? 7.0f : 5.0f));
    if (byCounter) ImGui::InputDouble(("budget " + counter + "##budget").c_str(), budgetCount, 0.0, 0.0, "%.6g");
    else ImGui::InputDouble("budget ms##budget", &budgetMs, 0.0, 0.0, "%g");
    noteItem("pareto.budget");
    if (ImGui::IsItemHovered()) {
        if (byCounter)
            tooltip("%s (the cost chosen above, exact): marks the pick among the points on show, as tradeoff --cost "
                    "%s --budget N does",
                    counter.c_str(), counter.c_str());
        else tooltip("GPU milliseconds: marks the pick among the points on show, and is what fit budget fits");
    }
    sameLineIfFits(ImGui::CalcTextSize("fit budget").x + spacing);
    ImGui::BeginDisabled(state.fitBudget.running() || waitingForReference || byCounter);
    if (ImGui::Button("fit budget")) start(budgetMs, againstCurrent, state, session);
    ImGui::EndDisabled();
    noteItem("pareto.fit_budget");
    if (byCounter && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        tooltip("fit budget fits GPU milliseconds: choose the cost gpu_ms to fit");
    else if (ImGui::IsItemHovered())
        tooltip("sweeps the speed/quality knobs about the current settings (tradeoff --knobs speed/quality) in the "
                "background, applies the least-error point whose time's 95%% interval ends under the budget, then "
                "measures it against the previous settings (the cost of a change); undo puts them back");
    sameLineIfFits(ImGui::GetFontSize() * 8.0f + ImGui::CalcTextSize("time").x + spacing);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    ImGui::InputText("time", time, sizeof(time));
    noteItem("pareto.fit_time");
    if (ImGui::IsItemHovered())
        tooltip("what the budget bounds (tradeoff --time): frame, a pass (ao) or a sum of passes (lighting+ao+ao_filter)");
}

// The sweep running (or the reference it waits for), with *cancel*.
void FitBudgetView::progress(UiState& state) {
    const float spacing = ImGui::GetStyle().FramePadding.x * 2.0f;
    if (waitingForReference) {
        ImGui::TextDisabled("fit budget: tracing the CPU reference of this view first...");
        sameLineIfFits(ImGui::CalcTextSize("cancel").x + spacing);
        if (ImGui::SmallButton("cancel##fit_reference")) {
            state.requestReferenceCancel = true;
            waitingForReference = false;
            message = "fit budget cancelled: nothing applied";
        }
        noteItem("pareto.fit_cancel");
        return;
    }
    FitBudgetRun& run = state.fitBudget;
    if (!run.running()) return;
    char label[128];
    std::snprintf(label, sizeof(label), "fit budget: %zu points, %.0f%%", run.points(), run.progress() * 100.0);
    ImGui::ProgressBar(static_cast<float>(run.progress()), ImVec2(ImGui::GetFontSize() * 14.0f, 0), label);
    noteItem("pareto.fit_progress");
    sameLineIfFits(ImGui::CalcTextSize("cancel").x + spacing);
    if (ImGui::SmallButton("cancel##fit")) {
        run.cancel();
        errorSaid = true;
        message = "fit budget cancelled: nothing applied, the settings are as they were";
        state.log.info(message, state.time);
    }
    noteItem("pareto.fit_cancel");
}

// The last fit: why nothing was applied, or the pick with its intervals, what
// was applied with *undo*, and the measured change.
void FitBudgetView::result(UiState& state, RenderSession& session) {
    if (!message.empty()) {
        wrappedColored(message.rfind("undone", 0) == 0 ? kDimColor : kErrorColor, message);
        noteItem("pareto.fit_message");
    }
    if (state.fitBudget.running()) return;
    if (!summary.empty()) wrappedColored(kDimColor, "fit budget swept " + summary);
    for (const std::string& l : pickLines)
        wrappedColored(l.rfind("pick: none", 0) == 0 ? kErrorColor : kOkColor, l);
    if (!pickLines.empty()) noteItem("pareto.fit_pick");
    if (applied.empty()) return;
    wrappedColored(kOkColor, "applied: " + applied);
    noteItem("pareto.fit_applied");
    if (change) {
        if (ImGui::Button("undo##fit")) {
            undo(state, session);
            return;
        }
        noteItem("pareto.fit_undo");
        if (ImGui::IsItemHovered()) tooltip("puts the previous values of the changed knobs back");
    }
    measuredChange(state, session);
}

// The cost of the applied change: its progress with *cancel*, then the time's verdict per series.
void FitBudgetView::measuredChange(UiState& state, RenderSession& session) {
    if (measuring && state.measure.active()) {
        const ChangeMeasurement& m = state.measure;
        ImGui::ProgressBar(m.progress(), ImVec2(ImGui::GetFontSize() * 14.0f, 0), ("cost of the change: " + m.status()).c_str());
        noteItem("pareto.fit_measure_progress");
        ImGui::SameLine();
        if (ImGui::SmallButton("cancel##fit_measure")) state.measure.cancel(session.knobs(), "cancelled");
        return;
    }
    if (!measureStatus.empty()) wrappedColored(kDimColor, measureStatus);
    if (!verdict) return;
    for (const std::string& series : shownSeries(state.fitBudget.settings().time)) {
        const PassVerdict* p = verdict->find(series);
        if (!p) continue;
        const std::string line = "measured against the previous settings: " + series + " " + p->describe() +
                                 (p->significant ? "" : p->influenced ? " (n.s.)" : " (not reached)");
        wrappedColored(p->significant ? (p->afterMs > p->beforeMs ? kErrorColor : kOkColor) : kDimColor, line);
        noteItem("pareto.fit_measured." + series);
        if (ImGui::IsItemHovered()) tooltip("%s", verdict->method().c_str());
    }
}

}  // namespace dw::ui
