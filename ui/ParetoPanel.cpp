#include "ui/ParetoPanel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "renderer/Error.h"
#include "renderer/OptionText.h"
#include "renderer/ao/AovCostEstimate.h"
#include "renderer/bench/BudgetPick.h"
#include "renderer/knobs/Preset.h"
#include "renderer/passes/ReferencePass.h"
#include "ui/Widgets.h"

namespace dw::ui {

namespace {

std::string groupOf(const TradeoffRow& r) { return r.camera + " | " + r.metric + " | " + r.buffer; }

bool finite(double v) { return std::isfinite(v); }

// "ssao.samples=16, ssao.resolution=half"; with `centre` (a sweep about
// settings, one axis at a time: those settings' values) only the values that
// differ from it, and "as before the fit" for none.
std::string label(const TradeoffTable& t, const TradeoffRow& r, const std::vector<std::string>& centre) {
    std::string s;
    for (size_t i = 0; i < t.axes.size() && i < r.axisValues.size(); ++i) {
        if (i < centre.size() && centre[i] == r.axisValues[i]) continue;
        if (!s.empty()) s += ", ";
        s += t.axes[i] + "=" + r.axisValues[i];
    }
    if (s.empty() && !centre.empty()) return "as before the fit";
    return s.empty() ? "point " + std::to_string(r.point) : s;
}

// An end of the axis across: 3 digits for ms, a count whole where it is under a billion ("9480", not "9.48e+03").
std::string axisNumber(double v) {
    char t[32];
    std::snprintf(t, sizeof(t), std::fabs(v) >= 1000.0 && std::fabs(v) < 1e9 ? "%.0f" : "%.3g", v);
    return t;
}

// The unit of a cost across: "ms" for gpu_ms, else the counter's own name.
std::string unitOf(const std::string& cost) { return cost == "gpu_ms" ? "ms" : cost; }

}  // namespace

std::vector<std::string> ParetoPanel::costs() const {
    std::vector<std::string> c{"gpu_ms"};
    for (int i = 0; i < PassCounts::kCount; ++i)
        if (table.hasCounter(i)) c.push_back(PassCounts::name(i));
    return c;
}

std::string ParetoPanel::marksCost(const TradeoffTable& t) {
    ParetoPanel probe;
    probe.table = t;
    for (const std::string& c : probe.costs()) {
        TradeoffTable copy = t;
        try {
            copy.markParetoFront(t.time, c);
        } catch (const std::exception&) {
            continue;
        }
        bool same = true;
        for (size_t i = 0; i < t.rows.size() && same; ++i) same = copy.rows[i].pareto == t.rows[i].pareto;
        if (same) return c;
    }
    return "gpu_ms";
}

void ParetoPanel::tiesFromFront() {
    // The ties are not in the CSV: decided again on the CSV's cost (as tradeoff merge does), the marks kept.
    TradeoffTable ranked = table;
    try {
        ranked.markParetoFront(table.time, csvCost);
    } catch (const std::exception&) {
        return;
    }
    for (size_t i = 0; i < table.rows.size(); ++i) {
        table.rows[i].errorTies = ranked.rows[i].errorTies;
        table.rows[i].timeTies = ranked.rows[i].timeTies;
    }
    table.frontRules = ranked.frontRules;
}

double ParetoPanel::costAcross(const TradeoffRow& r) const {
    return cost == "gpu_ms" ? r.timeMs : table.costOf(r, table.time, cost);
}

bool ParetoPanel::load(const std::string& file) {
    try {
        TradeoffTable t = TradeoffTable::readCsv(file);
        if (t.rows.empty()) throw Error(file + ": no rows (an empty sweep)");
        table = std::move(t);
        csvCost = cost = marksCost(table);
        tiesFromFront();
        tableIsFit = false;
        labelCentre.clear();
        pickedFor.clear();
        loadedPath = file;
        tableBaseline.clear();
        group = 0;
        hovered = -1;
        error.clear();
        applied.clear();
        return true;
    } catch (const std::exception& e) {
        error = e.what();
        return false;
    }
}

std::vector<std::string> ParetoPanel::groups() const {
    std::vector<std::string> g;
    for (const auto& r : table.rows)
        if (std::find(g.begin(), g.end(), groupOf(r)) == g.end()) g.push_back(groupOf(r));
    // The row over every camera first, where there is one.
    std::stable_partition(g.begin(), g.end(), [](const std::string& s) { return s.rfind("all |", 0) == 0; });
    return g;
}

bool ParetoPanel::apply(int row, UiState& state, RenderSession& session) {
    if (row < 0 || row >= static_cast<int>(table.rows.size())) return false;
    const TradeoffRow& r = table.rows[static_cast<size_t>(row)];
    // On a copy first: one refused value applies nothing.
    KnobRegistry trial = session.knobs();
    Camera camera = session.camera();
    try {
        for (size_t i = 0; i < table.axes.size() && i < r.axisValues.size(); ++i) {
            const std::string& axis = table.axes[i];
            const std::string& value = r.axisValues[i];
            if (axis == "study") continue;  // a label (tradeoff --study): the point's knobs are in the other axes
            if (axis == "preset") {
                RunConfig run;
                run.setPreset(value);
                const Preset::ApplyReport rep = run.preset()->applyOver(trial, session.scene().settings);
                if (!rep.ignored.empty()) throw Error("preset " + value + ": " + rep.ignored.front());
            } else if (axis == "camera.near" || axis == "camera.far") {
                char* end = nullptr;
                const float v = std::strtof(value.c_str(), &end);
                if (!end || *end || !(v > 0.0f)) throw Error(axis + " must be a positive number, not '" + value + "'");
                (axis == "camera.near" ? camera.nearPlane : camera.farPlane) = v;
            } else {
                trial.setFromString(axis, value);
            }
        }
        if (!(camera.nearPlane < camera.farPlane)) throw Error("camera.near must be below camera.far");
    } catch (const std::exception& e) {
        error = "point " + std::to_string(r.point) + " not applied: " + e.what();
        state.log.error(error, state.time, "pareto apply");
        return false;
    }
    session.knobs().copyValues(trial);
    session.camera() = camera;
    error.clear();
    applied = "applied point " + std::to_string(r.point) + ": " + label(table, r, labelCentre);
    state.log.done(applied, state.time, "pareto apply");
    return true;
}

std::vector<std::pair<std::string, std::string>> ParetoPanel::overAovCost(const std::string& knob,
                                                                           RenderSession& session, int width,
                                                                           int height) {
    std::vector<std::pair<std::string, std::string>> over;
    const int w = std::max(width, 16), h = std::max(height, 16);
    const Camera& camera = session.camera();  // the sweep renders with it
    for (const std::string& value : QuickSweep::valuesOf(session.knobs(), knob)) {
        KnobRegistry trial = session.knobs();
        trial.setFromString(knob, value);
        const auto e = AovCostEstimate::forKnobs(trial, session.scene(), camera, w, h);
        if (!e) continue;
        const auto [aw, ah] = AovCostEstimate::aoSize(trial, w, h);
        if (AovCostEstimate::exceeds(*e, aw, ah)) over.emplace_back(value, AovCostEstimate::warning(*e, trial, w, h));
    }
    return over;
}

namespace {
constexpr const char* kCurrentImage = "the current image (chosen: the current value scores 0)";
constexpr const char* kReference = "the CPU reference";
}  // namespace

bool ParetoPanel::startSweep(std::string knob, UiState& state, RenderSession& session, bool confirmed) {
    // By value: `knob` may be askedKnob, cleared below.
    askedKnob.clear();
    askedCost.clear();
    askedCostHeadline.clear();
    askedCostDetail.clear();
    askedReference.clear();
    askedConfirmed = false;
    waitingKnob.clear();
    try {
        if (!confirmed) {
            // The live view's AOV guard covers the states the view renders; a
            // sweep renders states of its own, so it asks here, before any.
            const auto over = overAovCost(knob, session, session.pipeline().width(), session.pipeline().height());
            if (!over.empty()) {
                std::string values;
                for (const auto& [v, w] : over) values += (values.empty() ? "" : ", ") + v;
                askedKnob = knob;
                askedCostHeadline = knob + ": " + std::to_string(over.size()) + " of " +
                                    std::to_string(QuickSweep::valuesOf(session.knobs(), knob).size()) +
                                    " values over the AOV cost limit (" + values + ")";
                askedCostDetail = knob + "=" + over.front().first + ": " + over.front().second;
                askedCost = "quick sweep of " + knob + " not started: " + std::to_string(over.size()) + " of " +
                            std::to_string(QuickSweep::valuesOf(session.knobs(), knob).size()) +
                            " values over the AOV cost limit (" + values + "); " + askedCostDetail;
                state.log.error(askedCost + ". 'sweep anyway' in the Pareto panel renders them", state.time,
                                "quick sweep");
                return false;
            }
        }
        const FloatImage current = session.readRaw("final");
        FloatImage baseline;
        std::string name;
        if (againstCurrent) {
            baseline = current;
            name = kCurrentImage;
        } else {
            // The CPU reference of this very view, at the frame's size; never
            // the current image in its place (its value would score 0).
            if (const ReferencePass* ref = session.pipeline().pass<ReferencePass>(); ref && ref->reference())
                baseline = ref->reference()->final;
            if (baseline.width != current.width || baseline.height != current.height || current.width == 0) {
                askedKnob = knob;
                askedConfirmed = confirmed;
                askedReference = "no CPU reference of this view to measure FLIP against";
                state.log.error("quick sweep of " + knob + " not started: " + askedReference +
                                    ". 'trace reference' in the Pareto panel traces it (as F9 does) and "
                                    "then sweeps, or 'use current image' measures against the image on show",
                                state.time, "quick sweep");
                return false;
            }
            name = kReference;
        }
        state.sweep.start(session.knobs(), knob, std::move(baseline), name);
        sweepShown = false;
        error.clear();
        state.log.succeeded("quick sweep");
        if (confirmed) state.log.info("quick sweep of " + knob + ": rendering values over the AOV cost limit, as asked", state.time);
        return true;
    } catch (const std::exception& e) {
        error = "quick sweep of " + knob + ": " + e.what();
        return false;
    }
}

void ParetoPanel::traceReferenceThenSweep(std::string knob, UiState& state, bool confirmed) {
    askedKnob.clear();
    askedReference.clear();
    askedConfirmed = false;
    waitingKnob = std::move(knob);
    waitingConfirmed = confirmed;
    waitingJobsEnded = state.referenceJobsEnded;
    state.requestReference = true;
    state.log.succeeded("quick sweep");
    state.log.info("quick sweep of " + waitingKnob + ": tracing the CPU reference of the view first", state.time);
}

void ParetoPanel::updateWaiting(UiState& state, RenderSession& session) {
    if (waitingKnob.empty()) return;
    const ReferencePass* ref = session.pipeline().pass<ReferencePass>();
    if (!ref) {
        error = "quick sweep of " + waitingKnob + " not started: this pipeline has no reference pass";
        waitingKnob.clear();
        return;
    }
    if (ref->hasReference()) {
        const std::string knob = waitingKnob;
        waitingKnob.clear();
        startSweep(knob, state, session, waitingConfirmed);
        return;
    }
    if (state.referenceJobsEnded != waitingJobsEnded && state.referenceProgress < 0.0 && !state.requestReference) {
        error = "quick sweep of " + waitingKnob +
                " not started: the CPU reference did not come (cancelled, failed or the view changed; see Messages)";
        state.log.error(error, state.time, "quick sweep");
        waitingKnob.clear();
    }
}

void ParetoPanel::draw(const char* title, bool* open, UiState& state, RenderSession& session) {
    updateWaiting(state, session);  // also while the panel is collapsed
    fit.update(budgetMs, againstCurrent, state, session);
    if (!beginPanel(title, open)) {
        ImGui::End();
        return;
    }
    pickSweepKnob(session);
    if (state.sweep.running()) sweepProgress(state);
    else if (!waitingKnob.empty()) referenceWait(state);
    else sweepControls(state, session);
    showFinishedSweep(state);
    if (cost == "gpu_ms" || table.rows.empty()) fit.draw(budgetMs, againstCurrent, state, session);
    else fit.draw(budgetMs, againstCurrent, state, session, cost, &budgetCount);
    showFinishedFit(state);
    attribution.draw(state, session);
    csvControls();
    if (table.rows.empty()) {
        wrappedColored(kDimColor, "a tradeoff CSV (deferred-workbench tradeoff --csv FILE): GPU ms or a cost counter "
                                  "against error");
        ImGui::End();
        return;
    }
    const std::vector<std::string> gs = groups();
    groupControls(gs);
    costControls();
    std::string metric;
    const std::vector<int> rows = groupRows(gs[static_cast<size_t>(group)], metric);
    if (rows.empty()) {
        ImGui::TextDisabled(cost == "gpu_ms" ? "no row of this group has both a time and an error"
                                             : "no row of this group has both this counter and an error");
        ImGui::End();
        return;
    }
    if (!tableBaseline.empty()) {
        // What the errors are measured against, over the plot (wrapped, never cut).
        const bool self = tableBaseline != kReference;
        wrappedColored(self ? kErrorColor : kDimColor, metric + " against " + tableBaseline);
        noteItem("pareto.baseline");
    }
    budgetControls(gs[static_cast<size_t>(group)]);
    plot(rows, metric, state, session);
    ImGui::End();
}

// What the budget field picks among the group's points (BudgetPicker); the
// fit's own table at the fit's budget: its lines are the fit's, above.
void ParetoPanel::budgetControls(const std::string& groupName) {
    const bool byCounter = cost != "gpu_ms";
    const double budget = byCounter ? budgetCount : budgetMs;
    const std::string key = groupName + "@" + cost + "@" + optionNumberText(budget);
    if (key != pickedFor) {
        pickedFor = key;
        pickLines.clear();
        for (auto& r : table.rows) r.pick.clear();
        const std::string camera = groupName.substr(0, groupName.find(" | "));
        try {
            // As tradeoff --budget-ms X, or --cost C --budget N (exact); refused in the CLI's words.
            if (budget != 0.0)
                pickLines = byCounter ? BudgetPicker::pick(table, budget, camera, BudgetPicker::counterCost(table, cost)).lines
                                      : BudgetPicker::pick(table, budget, camera).lines;
        } catch (const Error& e) {
            pickLines = {e.what()};
        }
    }
    if (tableIsFit && !byCounter && budgetMs == fitBudgetMs) return;
    for (const auto& l : pickLines) wrappedColored(l.rfind("pick: ", 0) == 0 ? kOkColor : kErrorColor, l);
    if (!pickLines.empty()) noteItem("pareto.pick");
}

// The speed/quality knob last pointed at in the Parameters panel (its rows are noted as knob.<name>).
void ParetoPanel::pickSweepKnob(RenderSession& session) {
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    for (const auto& [name, item] : drawnItems())
        if (name.rfind("knob.", 0) == 0 && item.frame >= ImGui::GetFrameCount() - 1 && mouse.x >= item.x &&
            mouse.x < item.x + item.w && mouse.y >= item.y && mouse.y < item.y + item.h)
            if (const auto id = session.knobs().find(name.substr(5)); id && session.knobs().spec(*id).tradeoff)
                sweepKnob = name.substr(5);
}

// The running sweep's progress, with *cancel*.
void ParetoPanel::sweepProgress(UiState& state) {
    char label[128];
    std::snprintf(label, sizeof(label), "sweeping %s: %.0f%%", state.sweep.knob().c_str(), state.sweep.progress() * 100.0);
    ImGui::ProgressBar(static_cast<float>(state.sweep.progress()), ImVec2(ImGui::GetFontSize() * 16.0f, 0), label);
    ImGui::SameLine();
    if (ImGui::SmallButton("cancel")) state.sweep.cancel();
}

// Tracing the reference the sweep asked for (the menu bar shows it too), with *cancel*.
void ParetoPanel::referenceWait(UiState& state) {
    const float spacing = ImGui::GetStyle().FramePadding.x * 2.0f;
    char label[160];
    const double p = std::max(state.referenceProgress, 0.0);
    std::snprintf(label, sizeof(label), "CPU reference for %s: %.0f%%", waitingKnob.c_str(), p * 100.0);
    ImGui::ProgressBar(static_cast<float>(p), ImVec2(ImGui::GetFontSize() * 16.0f, 0), label);
    noteItem("pareto.reference_progress");
    sameLineIfFits(ImGui::CalcTextSize("cancel").x + spacing);
    if (ImGui::SmallButton("cancel##waiting")) {
        state.requestReferenceCancel = true;
        state.log.info("quick sweep of " + waitingKnob + " cancelled while its CPU reference was traced", state.time);
        waitingKnob.clear();
    }
    noteItem("pareto.reference_cancel");
}

// The knob to sweep, *quick sweep*, what it is measured against; then the
// sweep's error and the question holding a sweep back, if any.
void ParetoPanel::sweepControls(UiState& state, RenderSession& session) {
    const float spacing = ImGui::GetStyle().FramePadding.x * 2.0f;
    // As wide as the knob's whole name where the panel allows ("gbuffer.normal_enco" was cut).
    const float knobWidth = ImGui::CalcTextSize(sweepKnob.empty() ? "point at a knob" : sweepKnob.c_str()).x +
                            ImGui::GetFrameHeight() + spacing;
    ImGui::SetNextItemWidth(std::min(std::max(knobWidth, ImGui::GetFontSize() * 12.0f), ImGui::GetContentRegionAvail().x));
    if (ImGui::BeginCombo("##sweep_knob", sweepKnob.empty() ? "point at a knob" : sweepKnob.c_str())) {
        for (const KnobSpec& s : session.knobs().specs())
            if (s.tradeoff && ImGui::Selectable(s.name.c_str(), s.name == sweepKnob)) sweepKnob = s.name;
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        tooltip("%s%sthe speed/quality knob to sweep: the one last pointed at in Parameters, or chosen here",
                sweepKnob.c_str(), sweepKnob.empty() ? "" : ": ");
    sameLineIfFits(ImGui::CalcTextSize("quick sweep").x + spacing);
    ImGui::BeginDisabled(sweepKnob.empty());
    if (ImGui::Button("quick sweep")) startSweep(sweepKnob, state, session);
    ImGui::EndDisabled();
    noteItem("pareto.sweep");
    // What each value's FLIP is measured against: a choice, shown on the plot.
    const char* against[] = {"vs CPU reference", "vs current image"};
    const float againstWidth = ImGui::CalcTextSize(against[1]).x + ImGui::GetFrameHeight() + spacing;
    sameLineIfFits(againstWidth);
    ImGui::SetNextItemWidth(againstWidth);
    int choice = againstCurrent ? 1 : 0;
    if (ImGui::Combo("##sweep_against", &choice, against, 2)) againstCurrent = choice == 1;
    if (ImGui::IsItemHovered())
        tooltip("what each swept value's FLIP is measured against: the CPU reference of this view "
                          "(ray-traced, F9; traced first if none is shown), or the current settings' image "
                          "(no reference needed; the current value then scores 0)");
    noteItem("pareto.against");
    if (!state.sweep.error().empty()) wrappedColored(kErrorColor, "quick sweep stopped: " + state.sweep.error());
    if (!askedCost.empty()) askAboutCost(state, session);
    else if (!askedReference.empty()) askForReference(state, session);
}

// A sweep held back by its AOV cost: asked first, as the live view's AOV
// guard asks; the buttons above the text, so a narrow, short panel still shows them.
void ParetoPanel::askAboutCost(UiState& state, RenderSession& session) {
    const float spacing = ImGui::GetStyle().FramePadding.x * 2.0f;
    if (ImGui::Button("sweep anyway")) startSweep(askedKnob, state, session, true);
    noteItem("pareto.sweep_anyway");
    sameLineIfFits(ImGui::CalcTextSize("cancel").x + spacing);
    if (ImGui::Button("cancel##aov")) {
        askedKnob.clear();
        askedCost.clear();
        state.log.succeeded("quick sweep");
    }
    noteItem("pareto.sweep_cancel");
    if (!askedCost.empty()) {
        wrappedColored(kErrorColor, askedCostHeadline);
        if (ImGui::IsItemHovered()) tooltip("%s", askedCost.c_str());
        wrappedColored(kDimColor, askedCostDetail);
    }
}

// A sweep held back for want of a CPU reference: *trace reference*, *use current image*, *cancel*.
void ParetoPanel::askForReference(UiState& state, RenderSession& session) {
    const float spacing = ImGui::GetStyle().FramePadding.x * 2.0f;
    if (ImGui::Button("trace reference"))
        traceReferenceThenSweep(askedKnob, state, askedConfirmed);
    if (ImGui::IsItemHovered())
        tooltip("traces the CPU reference of this view in the background (as F9 does, with its "
                          "progress and cancel), then sweeps against it");
    noteItem("pareto.trace_reference");
    sameLineIfFits(ImGui::CalcTextSize("use current image").x + spacing);
    if (ImGui::Button("use current image")) {
        againstCurrent = true;
        startSweep(askedKnob, state, session, askedConfirmed);
    }
    if (ImGui::IsItemHovered())
        tooltip("measures each value against the image on show: the current value scores 0");
    noteItem("pareto.against_current");
    sameLineIfFits(ImGui::CalcTextSize("cancel").x + spacing);
    if (ImGui::Button("cancel##reference")) {
        askedKnob.clear();
        askedReference.clear();
        state.log.succeeded("quick sweep");
    }
    noteItem("pareto.reference_ask_cancel");
    if (!askedReference.empty())
        wrappedColored(kErrorColor, "quick sweep of " + askedKnob + ": " + askedReference + " (F9)");
}

// The finished sweep replaces the table on show.
void ParetoPanel::showFinishedSweep(UiState& state) {
    if (sweepShown || !state.sweep.done()) return;
    table = state.sweep.table();
    csvCost = cost = "gpu_ms";
    tableIsFit = false;
    labelCentre.clear();
    pickedFor.clear();
    loadedPath = "quick sweep of " + state.sweep.knob() + " (FLIP against " + state.sweep.baselineName() + ")";
    tableBaseline = state.sweep.baselineName();
    group = 0;
    applied.clear();
    sweepShown = true;
}

// The finished fit's sweep replaces the table on show (its pick ringed; its lines are the fit's).
void ParetoPanel::showFinishedFit(UiState& state) {
    const FitBudgetRun& run = state.fitBudget;
    if (!run.done() || fitShown == run.finished()) return;
    fitShown = run.finished();
    table = run.table();
    csvCost = cost = "gpu_ms";
    tableIsFit = true;
    fitBudgetMs = run.settings().budgetMs;
    labelCentre.clear();
    for (const std::string& axis : table.axes)
        labelCentre.push_back(run.previous().find(axis) ? run.previous().format(*run.previous().find(axis)) : std::string());
    pickedFor.clear();
    loadedPath = "fit budget: " + std::to_string(run.points()) + " points of the speed/quality knobs about the settings (FLIP against " +
                 run.baselineName() + ", time " + run.settings().time + ")";
    tableBaseline = run.baselineName();
    group = 0;
    applied.clear();
}

// What is on show, the CSV's path with *Load*, and the last load's or apply's error.
void ParetoPanel::csvControls() {
    if (!loadedPath.empty()) {
        // Wrapped, whole (the knob's name was cut: "quick sweep of gbuff..."); the plot keeps its own room below.
        wrappedColored(kDimColor, loadedPath);
        noteItem("pareto.loaded");
    }
    ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x - ImGui::GetFontSize() * 4.0f, 60.0f));
    const bool enter = ImGui::InputText("##csv", path, sizeof(path), ImGuiInputTextFlags_EnterReturnsTrue);
    noteItem("pareto.path");
    ImGui::SameLine();
    if (ImGui::Button("Load") || enter) load(path);
    noteItem("pareto.load");
    if (!error.empty()) wrappedColored(kErrorColor, error);
}

// Which group is plotted (`gs`: groups(), not empty); what the last click applied.
void ParetoPanel::groupControls(const std::vector<std::string>& gs) {
    group = std::clamp(group, 0, static_cast<int>(gs.size()) - 1);
    // The combo as wide as the panel allows; its label beside it only where it fits.
    const char* groupLabel = "camera | metric | buffer";
    ImGui::SetNextItemWidth(std::min(ImGui::GetFontSize() * 14.0f, ImGui::GetContentRegionAvail().x));
    if (ImGui::BeginCombo("##group", gs[static_cast<size_t>(group)].c_str())) {
        for (size_t i = 0; i < gs.size(); ++i)
            if (ImGui::Selectable(gs[i].c_str(), static_cast<int>(i) == group)) group = static_cast<int>(i);
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered()) tooltip("%s", groupLabel);
    noteItem("pareto.group");
    const float labelWidth = ImGui::CalcTextSize(groupLabel).x;
    if (ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x - ImGui::GetItemRectMax().x >=
        labelWidth + ImGui::GetStyle().ItemSpacing.x) {
        ImGui::SameLine();
        ImGui::TextDisabled("%s", groupLabel);
    }
    if (!applied.empty()) ImGui::TextColored(kOkColor, "%s", applied.c_str());
}

// What the plot has across: "GPU frame ms (median)", or a counter of the time's span: "frame fragments (exact)".
std::string ParetoPanel::acrossName() const {
    return cost == "gpu_ms" ? "GPU " + table.time + " ms (median)" : table.time + " " + cost + " (exact)";
}

// The cost across (gpu_ms or a counter the table holds); a line when the marks were decided on another.
void ParetoPanel::costControls() {
    const std::vector<std::string> cs = costs();
    if (std::find(cs.begin(), cs.end(), cost) == cs.end()) cost = "gpu_ms";
    ImGui::SetNextItemWidth(ImGui::CalcTextSize("primitives").x + ImGui::GetFrameHeight() * 2.0f);
    if (ImGui::BeginCombo("cost##pareto_cost", cost.c_str())) {
        for (const std::string& c : cs)
            if (ImGui::Selectable(c.c_str(), c == cost)) cost = c;
        ImGui::EndCombo();
    }
    noteItem("pareto.cost");
    if (ImGui::IsItemHovered())
        tooltip("across the plot (tradeoff --cost): gpu_ms, the table's %s time with its interval, or a counter of "
                "its span (exact); the budget field then bounds it in its unit",
                table.time.c_str());
    if (cost != csvCost) {
        wrappedColored(ImVec4(0.95f, 0.8f, 0.35f, 1.0f), "the front marks are the CSV's, decided on its cost " + csvCost + ", not on " + cost +
                                       " (tradeoff merge --cost " + cost + " decides them on " + cost + ")");
        noteItem("pareto.marks_cost");
    }
}

// The rows of `groupName` with both numbers (indices into table.rows), their
// metric, and plotAxes around them; none: plotAxes is left as it was.
std::vector<int> ParetoPanel::groupRows(const std::string& groupName, std::string& metric) {
    std::vector<int> rows;
    double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
    for (size_t i = 0; i < table.rows.size(); ++i) {
        const TradeoffRow& r = table.rows[i];
        if (groupOf(r) != groupName || !finite(costAcross(r)) || !finite(r.error)) continue;
        rows.push_back(static_cast<int>(i));
        metric = r.metric;
        // A counter is exact: its value alone; the time with its interval.
        const double c = costAcross(r);
        const double xs[3] = {c, cost == "gpu_ms" ? r.timeMsLo : c, cost == "gpu_ms" ? r.timeMsHi : c};
        for (double x : xs)
            if (finite(x)) xlo = std::min(xlo, x), xhi = std::max(xhi, x);
        for (double y : {r.error, r.errorLo, r.errorHi})
            if (finite(y)) ylo = std::min(ylo, y), yhi = std::max(yhi, y);
    }
    if (rows.empty()) return rows;
    // Padded around the data, but never below 0 where the data are not (a
    // time or an error of 0 sits on the axis, not over a negative range).
    const bool xPositive = xlo >= 0.0, yPositive = ylo >= 0.0;
    if (xhi <= xlo) xlo -= 0.5 * std::max(std::fabs(xlo), 1.0), xhi += 0.5 * std::max(std::fabs(xhi), 1.0);
    if (yhi <= ylo) ylo -= 0.5 * std::max(std::fabs(ylo), 1e-6), yhi += 0.5 * std::max(std::fabs(yhi), 1e-6);
    const double padX = 0.06 * (xhi - xlo), padY = 0.08 * (yhi - ylo);
    xlo -= padX, xhi += padX, ylo -= padY, yhi += padY;
    if (xPositive) xlo = std::max(xlo, 0.0);
    if (yPositive) ylo = std::max(ylo, 0.0);
    plotAxes = {xlo, xhi, ylo, yhi};
    return rows;
}

// The plot of `rows` over plotAxes: its frame and axes, the front joined,
// the points with their intervals and the front's labels; the point under
// the mouse named in a tooltip, and applied when clicked.
void ParetoPanel::plot(const std::vector<int>& rows, const std::string& metric, UiState& state, RenderSession& session) {
    {
        // A narrow panel has no room for the axes' names under the plot: a line above it says them.
        const std::string unit = unitOf(cost);
        char lo[96], whole[200];
        std::snprintf(lo, sizeof(lo), "%s %s", axisNumber(plotAxes.xlo).c_str(), unit.c_str());
        std::snprintf(whole, sizeof(whole), "%s %s   %s against %s", axisNumber(plotAxes.xhi).c_str(), unit.c_str(),
                      acrossName().c_str(), metric.c_str());
        const float plotWidth = std::max(ImGui::GetContentRegionAvail().x, 80.0f) - 64.0f;
        if (ImGui::CalcTextSize(whole).x > plotWidth - ImGui::CalcTextSize(lo).x - 8.0f) {
            wrappedColored(kDimColor, "across: " + acrossName() + "; up: " + metric);
            noteItem("pareto.axes");
        }
    }
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    // The plot keeps room to be read (it was about 90x40 px at 1024x640, its
    // labels over each other): in a short panel it is taller than what is
    // left, and the panel scrolls down to it (never sideways).
    const ImVec2 size(std::max(avail.x, 80.0f), std::max(avail.y, ImGui::GetFontSize() * 11.0f));
    ImGui::InvisibleButton("##pareto_plot", size);
    noteItem("pareto.plot");
    const bool plotHovered = ImGui::IsItemHovered();
    const bool clicked = ImGui::IsItemClicked(ImGuiMouseButton_Left);
    const PlotFrame f{plotAxes, origin.x + 56, origin.x + size.x - 8, origin.y + 6, origin.y + size.y - 22};
    plotAxesDrawn(f, origin.x, metric);
    plotFront(f, rows);
    plotPoints(f, rows, plotHovered);
    if (hovered >= 0) {
        const TradeoffRow& r = table.rows[static_cast<size_t>(hovered)];
        ImGui::GetWindowDrawList()->AddCircle(ImVec2(f.sx(costAcross(r)), f.sy(r.error)), 8.0f, IM_COL32(255, 255, 255, 255), 16,
                                              1.5f);
        tooltip("%s", hoverText(r).c_str());
        if (clicked) apply(hovered, state, session);
    }
}

// The plot's background and frame, the error's ends up the left (from
// `textX`) and the time's under it, with the axes' names where they fit.
void ParetoPanel::plotAxesDrawn(const PlotFrame& f, float textX, const std::string& metric) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(ImVec2(f.left, f.top), ImVec2(f.right, f.bottom), IM_COL32(24, 24, 28, 255));
    dl->AddRect(ImVec2(f.left, f.top), ImVec2(f.right, f.bottom), IM_COL32(90, 90, 100, 255));
    char t[200];
    std::snprintf(t, sizeof(t), "%.3g", f.axes.yhi);
    dl->AddText(ImVec2(textX, f.top), IM_COL32(170, 170, 170, 255), t);
    std::snprintf(t, sizeof(t), "%.3g", f.axes.ylo);
    dl->AddText(ImVec2(textX, f.bottom - ImGui::GetFontSize()), IM_COL32(170, 170, 170, 255), t);
    const std::string unit = unitOf(cost);
    std::snprintf(t, sizeof(t), "%s %s", axisNumber(f.axes.xlo).c_str(), unit.c_str());
    dl->AddText(ImVec2(f.left, f.bottom + 4), IM_COL32(170, 170, 170, 255), t);
    const float loWidth = ImGui::CalcTextSize(t).x;
    // The axes' names after the upper end where they fit, else the end alone (the caption line above says them).
    std::snprintf(t, sizeof(t), "%s %s   %s against %s", axisNumber(f.axes.xhi).c_str(), unit.c_str(),
                  acrossName().c_str(), metric.c_str());
    if (ImGui::CalcTextSize(t).x > f.right - f.left - loWidth - 8.0f)
        std::snprintf(t, sizeof(t), "%s %s", axisNumber(f.axes.xhi).c_str(), unit.c_str());
    dl->AddText(ImVec2(std::max(f.left + loWidth + 8.0f, f.right - ImGui::CalcTextSize(t).x), f.bottom + 4),
                IM_COL32(170, 170, 170, 255), t);
}

// The front, joined left to right.
void ParetoPanel::plotFront(const PlotFrame& f, const std::vector<int>& rows) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    std::vector<int> front;
    for (int i : rows)
        if (table.rows[static_cast<size_t>(i)].pareto) front.push_back(i);
    std::sort(front.begin(), front.end(), [&](int a, int b) {
        return costAcross(table.rows[static_cast<size_t>(a)]) < costAcross(table.rows[static_cast<size_t>(b)]);
    });
    for (size_t k = 1; k < front.size(); ++k) {
        const TradeoffRow &a = table.rows[static_cast<size_t>(front[k - 1])], &b = table.rows[static_cast<size_t>(front[k])];
        dl->AddLine(ImVec2(f.sx(costAcross(a)), f.sy(a.error)), ImVec2(f.sx(costAcross(b)), f.sy(b.error)),
                    IM_COL32(255, 170, 60, 160), 1.5f);
    }
}

namespace {

// A point by its front class: pareto and told apart filled, pareto but tied a
// ring, indistinguishable a hollow square, dominated small; the pick ringed green.
void drawMarker(ImDrawList* dl, ImVec2 p, const TradeoffRow& r) {
    const ImU32 front = IM_COL32(255, 170, 60, 255), other = IM_COL32(110, 160, 230, 255);
    if (r.pareto && r.tiedWith.empty()) dl->AddCircleFilled(p, 5.0f, front);
    else if (r.pareto) dl->AddCircle(p, 5.0f, front, 16, 2.0f);
    else if (r.front == "indistinguishable") dl->AddRect(ImVec2(p.x - 4, p.y - 4), ImVec2(p.x + 4, p.y + 4), IM_COL32(240, 210, 90, 255), 0.0f, 0, 1.5f);
    else dl->AddCircleFilled(p, 3.0f, other);
    if (r.pick == "pick") dl->AddCircle(p, 10.0f, IM_COL32(90, 220, 110, 255), 20, 2.5f);
    else if (r.pick == "tied") dl->AddCircle(p, 10.0f, IM_COL32(90, 220, 110, 140), 20, 1.0f);
}

}  // namespace

// What the tooltip says of a point: its settings, both numbers with their
// intervals, its front class with dominated_by and tied_with, its pick.
std::string ParetoPanel::hoverText(const TradeoffRow& r) const {
    char numbers[256];
    std::snprintf(numbers, sizeof(numbers), "\n%s %.4g [%.4g, %.4g]\nGPU %s %.3f ms [%.3f, %.3f]", r.metric.c_str(), r.error,
                  r.errorLo, r.errorHi, table.time.c_str(), r.timeMs, r.timeMsLo, r.timeMsHi);
    std::string s = label(table, r, labelCentre) + numbers;
    if (cost != "gpu_ms") s += "\n" + acrossName() + " " + optionNumberText(costAcross(r)) + " " + cost;
    if (r.front == "pareto" || (r.front.empty() && r.pareto)) s += "\non the Pareto front";
    else if (r.front == "indistinguishable") s += "\nindistinguishable: off the front, not confidently dominated";
    else if (r.front == "dominated") {
        s += "\ndominated (confidently) by";
        for (int q : r.dominatedBy) s += " " + std::to_string(q);
    }
    if (!r.tiedWith.empty()) {
        s += "\ncannot be told apart from:";
        for (const auto& [q, axes] : r.tiedWith) s += " " + std::to_string(q) + " (" + axes + ")";
    }
    if (!r.pick.empty()) s += "\nbudget: " + r.pick;
    return s + "\nclick: apply these settings";
}

// Points with both intervals, the front's labelled where a label has room;
// the nearest within 8 px of the mouse is `hovered` (-1: none).
void ParetoPanel::plotPoints(const PlotFrame& f, const std::vector<int>& rows, bool plotHovered) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    hovered = -1;
    float best = 64.0f;
    std::vector<ImVec4> labelRects;  // (x0, y0, x1, y1) of the point labels drawn: none is drawn over another
    auto drawLabel = [&](ImVec2 p, const std::string& text) {
        const ImVec2 ts = ImGui::CalcTextSize(text.c_str());
        // Right of the point, or left of it where the plot ends first.
        float x = p.x + 6.0f;
        if (x + ts.x > f.right) x = p.x - 6.0f - ts.x;
        const float y = p.y - ts.y - 2.0f;
        if (x < f.left || y < f.top) return;
        const ImVec4 r(x, y, x + ts.x, y + ts.y);
        for (const ImVec4& o : labelRects)
            if (r.x < o.z && o.x < r.z && r.y < o.w && o.y < r.w) return;  // the tooltip names it
        labelRects.push_back(r);
        dl->AddText(ImVec2(x, y), IM_COL32(255, 200, 130, 255), text.c_str());
    };
    for (int i : rows) {
        const TradeoffRow& r = table.rows[static_cast<size_t>(i)];
        const ImVec2 p(f.sx(costAcross(r)), f.sy(r.error));
        const ImU32 bar = IM_COL32(150, 150, 160, 200);
        // A counter is exact: no interval across.
        if (cost == "gpu_ms" && finite(r.timeMsLo) && finite(r.timeMsHi)) dl->AddLine(ImVec2(f.sx(r.timeMsLo), p.y), ImVec2(f.sx(r.timeMsHi), p.y), bar);
        if (finite(r.errorLo) && finite(r.errorHi)) dl->AddLine(ImVec2(p.x, f.sy(r.errorLo)), ImVec2(p.x, f.sy(r.errorHi)), bar);
        drawMarker(dl, p, r);
        if (r.pareto) drawLabel(p, label(table, r, labelCentre));
        const float d2 = (mouse.x - p.x) * (mouse.x - p.x) + (mouse.y - p.y) * (mouse.y - p.y);
        if (plotHovered && d2 < best) best = d2, hovered = i;
        noteRect("pareto.point." + std::to_string(r.point), ImVec2(p.x - 1, p.y - 1), ImVec2(p.x + 1, p.y + 1));
    }
}

}  // namespace dw::ui
