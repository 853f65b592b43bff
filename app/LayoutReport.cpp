#include "app/LayoutReport.h"

#include <nlohmann/json.hpp>

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>

#include "renderer/io/TextFile.h"
#include "renderer/passes/ReferencePass.h"
#include "ui/Widgets.h"

namespace dw {

namespace {

// Named items drawn in the last frame (ui::noteItem): where, in which panel,
// and the visible part of that panel.
nlohmann::json itemsReport() {
    nlohmann::json items = nlohmann::json::object();
    for (const auto& [name, d] : ui::drawnItems())
        if (d.frame == ImGui::GetFrameCount())
            items[name] = {{"x", d.x}, {"y", d.y}, {"w", d.w}, {"h", d.h}, {"panel", d.window},
                           {"clip", {d.clipX, d.clipY, d.clipW, d.clipH}}};
    return items;
}

// The CPU reference the workbench shows, and the frame's error against it.
nlohmann::json referenceReport(RenderSession& session) {
    const ReferencePass* pass = session.pipeline().pass<ReferencePass>();
    if (!pass || !pass->hasReference()) return {{"shown", false}};
    const ReferencePass::Errors& e = pass->errors();
    return {{"shown", true}, {"stats", pass->stats()}, {"mean_absolute", e.meanAbsolute}, {"rms", e.rms},
            {"max", e.max}, {"mean_relative", e.meanRelative}};
}

// The A/B split's state and numbers, as the viewport shows them.
nlohmann::json abReport(const ui::AbView& ab) {
    auto median = [](std::vector<double> v) -> nlohmann::json {
        if (v.empty()) return nullptr;
        std::sort(v.begin(), v.end());
        return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    };
    auto side = [&](const ui::AbSide& s) {
        return nlohmann::json{{"have_error", s.haveError}, {"rms", s.rms}, {"flip", s.flip}, {"gpu_ms_median", median(s.gpuMs)},
                              {"gpu_frames", s.gpuMs.size()}};
    };
    const char* sources[] = {"pinned", "preset", "reference"};
    const char* displays[] = {"split", "difference", "flip"};
    nlohmann::json j = {{"enabled", ab.enabled},
                        {"source", sources[static_cast<int>(ab.source)]},
                        {"display", displays[static_cast<int>(ab.display)]},
                        {"preset", ab.preset},
                        {"divider", ab.divider},
                        {"divider_x", ab.dividerScreen.x},
                        {"ready", ab.ready},
                        {"unavailable", ab.unavailable},
                        {"describe_b", ab.describeB},
                        {"size", {ab.width, ab.height}},
                        {"rms", ab.rms},
                        {"psnr", std::isfinite(ab.psnr) ? nlohmann::json(ab.psnr) : nlohmann::json(nullptr)},
                        {"mean", ab.meanAbsolute},
                        {"flip", ab.haveFlip ? nlohmann::json(ab.flip) : nlohmann::json(nullptr)},
                        {"a", side(ab.a)},
                        {"b", side(ab.b)}};
    if (ab.gpuDifference.valid())
        j["gpu_difference_ms"] = {ab.gpuDifference.difference, ab.gpuDifference.low, ab.gpuDifference.high};
    return j;
}

}  // namespace

void writeLayoutReport(const std::string& path, const ui::WorkbenchUi& ui, const ui::UiState& state, int fbw, int fbh,
                       RenderSession& session) {
    const PassTimer& timer = session.pipeline().timer();
    // The newest frame whose GPU times have come back (-1: none).
    const PassTimer::Series* total = timer.find(PassTimer::kFrameSeries);
    const long long lastTimedFrame =
        total && !total->samples.empty() ? static_cast<long long>(total->samples.back().frame) : -1;
    nlohmann::json errors = nlohmann::json::array();
    for (const ui::Message& m : state.log.all())
        if (m.error) errors.push_back(m.text);
    nlohmann::json panels = nlohmann::json::array();
    for (const auto& d : ui.drawnPanels()) {
        const ImGuiWindow* w = ImGui::FindWindowByName(d.name.c_str());
        if (!w || !w->WasActive) continue;
        panels.push_back({{"name", d.name}, {"x", w->Pos.x}, {"y", w->Pos.y}, {"w", w->Size.x}, {"h", w->Size.y}});
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const nlohmann::json j = {{"display", {display.x, display.y}},
                              {"framebuffer", {fbw, fbh}},
                              {"menu_bar_height", ImGui::GetFrameHeight()},
                              {"panels", panels},
                              {"probe", {{"pinned", state.probe.pinned},
                                         {"pixel", {state.probe.pixel.x, state.probe.pixel.y}},
                                         {"shows_values", state.probe.result.inside}}},
                              {"camera", {{"position", {state.cameraPosition.x, state.cameraPosition.y, state.cameraPosition.z}}}},
                              {"viewport", {{"output", state.viewport.output},
                                            {"zoom", state.viewport.zoom},
                                            {"unavailable", state.viewportImage.unavailable}}},
                              {"reference", referenceReport(session)},
                              {"render_size", {state.renderSize.x, state.renderSize.y}},
                              {"resolution", {{"scale", state.viewport.scale()},
                                              {"auto", state.viewport.resolution == ui::ResolutionScale::Auto},
                                              {"software_start", state.viewport.softwareStart}}},
                              {"wanted_size", {state.wantedSize.x, state.wantedSize.y}},
                              {"frames", state.frame + 1},
                              {"frames_rendered", state.framesRendered},
                              {"last_rendered_frame", static_cast<long long>(state.report.frameIndex)},
                              {"last_timed_frame", lastTimedFrame},
                              {"renderdoc_captures", state.renderdocCaptures},
                              {"banner", state.log.banner() ? state.log.banner()->text : std::string()},
                              {"scene", {{"name", session.scene().name}, {"source", session.scene().source}}},
                              {"recent_scenes", std::vector<std::string>(state.recentScenes.begin(), state.recentScenes.end())},
                              {"active_preset", state.activePreset},
                              {"ab", abReport(state.ab)},
                              {"axes", state.viewport.overlay.axes},
                              {"timings", ui::timingsReport(timer, state)},
                              {"items", itemsReport()},
                              {"errors", errors}};
    writeFileAtomically(path, j.dump(2) + "\n");
}

}  // namespace dw
