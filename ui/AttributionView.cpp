#include "ui/AttributionView.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "renderer/passes/ReferencePass.h"
#include "ui/Widgets.h"

namespace dw::ui {

namespace {

std::string interval(double v, double lo, double hi) {
    if (std::isnan(v)) return "-";
    char text[96];
    if (std::isnan(lo) || std::isnan(hi)) std::snprintf(text, sizeof(text), "%.2g (no interval)", v);
    else std::snprintf(text, sizeof(text), "%.2g [%.2g, %.2g]", v, lo, hi);
    return text;
}

std::string part(const ErrorDifference& d) {
    if (d.value == 0.0 && d.low == 0.0 && d.high == 0.0) return "0 (same image)";
    return interval(d.value, d.low, d.high) + (!(d.low > 0.0) && !(d.high < 0.0) ? " ~0" : "");
}

}  // namespace

void AttributionView::draw(UiState& state, RenderSession& session) {
    updateWaiting(state, session);
    const bool shown = ImGui::CollapsingHeader("Where the error comes from");
    noteItem("pareto.attribution");
    if (!shown) return;
    controls(state, session);
    if (!error.empty()) wrappedColored(kErrorColor, error);
    if (!state.attribution.done()) return;
    const AttributionResult& r = state.attribution.result();
    table(r, session);
    bars(r);
}

void AttributionView::controls(UiState& state, RenderSession& session) {
    if (state.attribution.running()) {
        char label[96];
        std::snprintf(label, sizeof(label), "attributing: %.0f%%", state.attribution.progress() * 100.0);
        ImGui::ProgressBar(static_cast<float>(state.attribution.progress()), ImVec2(ImGui::GetFontSize() * 16.0f, 0), label);
        ImGui::SameLine();
        if (ImGui::SmallButton("cancel##attribution")) state.attribution.cancel();
        return;
    }
    if (waitingForReference) {
        ImGui::TextDisabled("tracing the CPU reference of this view first...");
        return;
    }
    if (ImGui::Button("attribute this view")) start(state, session);
    noteItem("pareto.attribute");
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("FLIP of the final image against the CPU reference of this view, as the settings are,\n"
                          "with every approximation family exact, and each family alone exact and alone\n"
                          "approximate: each family's part both ways (tradeoff --attribute, docs/tradeoffs.md)");
}

// Against the CPU reference on show (F9) at the frame's size; with none, asks for it and starts when it comes.
bool AttributionView::start(UiState& state, RenderSession& session) {
    error.clear();
    FloatImage truth;
    if (const ReferencePass* ref = session.pipeline().pass<ReferencePass>(); ref && ref->reference())
        truth = ref->reference()->final;
    const FloatImage current = session.readRaw("final");
    if (truth.width != current.width || truth.height != current.height || current.width == 0) {
        waitingForReference = true;
        waitingJobsEnded = state.referenceJobsEnded;
        state.requestReference = true;
        state.log.info("attribution: tracing the CPU reference of the view first", state.time);
        return false;
    }
    try {
        viewKey = viewKeyOf(session);
        against = session.pipeline().pass<ReferencePass>()->reference()->describe + ", " + std::to_string(current.width) +
                  "x" + std::to_string(current.height);
        state.attribution.start(session.knobs(), session.scene(), std::move(truth), "flip", "final");
        return true;
    } catch (const std::exception& e) {
        error = std::string("attribution not started: ") + e.what();
        return false;
    }
}

// A reference asked for by start(): the attribution begins when it is shown;
// a trace that ended without one (cancelled, failed, the view changed) ends the wait.
void AttributionView::updateWaiting(UiState& state, RenderSession& session) {
    if (!state.attribution.running() && !state.attribution.error().empty() && error.empty())
        error = "attribution stopped: " + state.attribution.error();
    if (!waitingForReference) return;
    const ReferencePass* ref = session.pipeline().pass<ReferencePass>();
    if (ref && ref->reference()) {
        waitingForReference = false;
        start(state, session);
    } else if (state.referenceJobsEnded != waitingJobsEnded) {
        waitingForReference = false;
        error = "attribution not started: the CPU reference of this view did not come (cancelled, failed or the view changed)";
    }
}

std::string AttributionView::viewKeyOf(RenderSession& session) {
    std::string key;
    for (int id = 0; id < static_cast<int>(session.knobs().size()); ++id) key += session.knobs().format(id) + ",";
    const Camera& c = session.camera();
    char camera[256];
    std::snprintf(camera, sizeof(camera), "%g,%g,%g;%g,%g,%g;%g;%dx%d", c.position.x, c.position.y, c.position.z,
                  c.target.x, c.target.y, c.target.z, c.fovYDegrees, session.pipeline().width(), session.pipeline().height());
    return key + camera;
}

void AttributionView::table(const AttributionResult& r, RenderSession& session) const {
    if (viewKeyOf(session) != viewKey)
        wrappedColored(kErrorColor, "of an earlier view: the settings, the camera or the size changed since; attribute "
                                    "again for this one");
    wrappedColored(kDimColor, "against the " + against);
    ImGui::Text("FLIP of final: as is %s, all exact %s", interval(r.asIs.value, r.asIs.low, r.asIs.high).c_str(),
                interval(r.allExact.value, r.allExact.low, r.allExact.high).c_str());
    if (ImGui::BeginTable("attribution", 3, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("family");
        ImGui::TableSetupColumn("removed");
        ImGui::TableSetupColumn("added");
        ImGui::TableHeadersRow();
        for (const AttributionFamily& f : r.families) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(f.name.c_str());
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", f.what.c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(part(f.removed).c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(part(f.added).c_str());
        }
        ImGui::EndTable();
    }
    char sums[256];
    std::snprintf(sums, sizeof(sums), "total %s; the parts sum to %.3g removed, %.3g added (they need not add up)",
                  interval(r.total.value, r.total.low, r.total.high).c_str(), r.sumRemoved, r.sumAdded);
    wrappedColored(kDimColor, sums);
    wrappedColored(kDimColor, "removed: as is - this family alone exact; added: this family alone approximate - all exact");
    for (const std::string& n : r.notes) wrappedColored(kDimColor, "note: " + n);
}

// Two bars a family (removed, added) with their intervals; faint where the interval holds 0.
void AttributionView::bars(const AttributionResult& r) {
    double lo = 0.0, hi = 0.0;
    for (const AttributionFamily& f : r.families)
        for (const ErrorDifference* d : {&f.removed, &f.added}) {
            if (std::isfinite(d->low)) lo = std::min(lo, d->low);
            if (std::isfinite(d->high)) hi = std::max(hi, d->high);
        }
    if (!(hi > lo)) return;
    const float rowH = ImGui::GetTextLineHeightWithSpacing(), labelW = ImGui::GetFontSize() * 8.0f;
    const float width = std::max(100.0f, ImGui::GetContentRegionAvail().x - labelW);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    auto x = [&](double v) { return origin.x + labelW + static_cast<float>((v - lo) / (hi - lo)) * width; };
    const ImU32 colours[2] = {IM_COL32(70, 130, 200, 255), IM_COL32(240, 150, 50, 255)};
    for (size_t i = 0; i < r.families.size(); ++i) {
        const AttributionFamily& f = r.families[i];
        const float y = origin.y + static_cast<float>(i) * rowH;
        draw->AddText(ImVec2(origin.x, y), ImGui::GetColorU32(ImGuiCol_Text), f.name.c_str());
        const ErrorDifference* parts[2] = {&f.removed, &f.added};
        for (int k = 0; k < 2; ++k) {
            const ErrorDifference& d = *parts[k];
            if (!std::isfinite(d.value)) continue;
            const float y0 = y + 2.0f + static_cast<float>(k) * (rowH - 4.0f) / 2.0f, y1 = y0 + (rowH - 4.0f) / 2.0f - 1.0f;
            const bool unclear = !(d.low > 0.0) && !(d.high < 0.0);
            const ImU32 c = unclear ? (colours[k] & 0x00FFFFFFu) | 0x60000000u : colours[k];
            draw->AddRectFilled(ImVec2(std::min(x(0.0), x(d.value)), y0), ImVec2(std::max(x(0.0), x(d.value)), y1), c);
            draw->AddLine(ImVec2(x(d.low), (y0 + y1) / 2), ImVec2(x(d.high), (y0 + y1) / 2), IM_COL32(20, 20, 20, 255));
        }
    }
    draw->AddLine(ImVec2(x(0.0), origin.y), ImVec2(x(0.0), origin.y + rowH * static_cast<float>(r.families.size())),
                  ImGui::GetColorU32(ImGuiCol_Text));
    ImGui::Dummy(ImVec2(labelW + width, rowH * static_cast<float>(r.families.size())));
    noteItem("pareto.attribution_bars");
    wrappedColored(kDimColor, "blue: removed when made exact alone; orange: added when left approximate alone; "
                              "lines: 95% intervals; faint: cannot be told from 0");
}

}  // namespace dw::ui
