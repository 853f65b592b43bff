#include "ui/AovCostGuard.h"

#include <imgui.h>

#include <algorithm>
#include <optional>

#include "renderer/RenderSession.h"
#include "renderer/ao/AovCostEstimate.h"
#include "ui/UiState.h"
#include "ui/ViewportComposer.h"

namespace dw::ui {

namespace {
// The camera is estimated again at most this often while it moves (the
// dragon's 405k volumes take 0.07-0.22 s on one loaded core).
constexpr double kCameraRecheckSeconds = 0.5;
}  // namespace

std::vector<double> AovCostGuard::values(const RenderSession& session) const {
    const KnobRegistry& k = session.knobs();
    std::vector<double> v(k.size());
    for (std::size_t i = 0; i < k.size(); ++i) v[i] = k.value(static_cast<int>(i));
    return v;
}

void AovCostGuard::restore(RenderSession& session, const std::vector<double>& v) const {
    KnobRegistry& k = session.knobs();
    if (v.size() != k.size()) return;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (k.value(static_cast<int>(i)) != v[i]) k.set(static_cast<int>(i), v[i]);
}

void AovCostGuard::beforeFrame(UiState& state, RenderSession& session) {
    const Camera& cam = session.camera();
    const bool sceneChanged = checkedScene_ != &session.scene() || checkedSource_ != session.scene().source;
    const bool knobsChanged = checkedGeneration_ != session.knobs().generation();
    const bool cameraChanged =
        cam.position != checkedEye_ || cam.target != checkedTarget_ || cam.fovYDegrees != checkedFov_;
    // The size this frame renders at (ViewportComposer resizes to it after
    // this call), not the last frame's: the first frames and every resize
    // (the panel, the resolution scale) are estimated at the size they render.
    const glm::ivec2 size = ViewportComposer::targetSize(state);
    const int w = std::max(size.x, 16), h = std::max(size.y, 16);
    const bool sizeChanged = glm::ivec2(w, h) != checkedSize_;
    if (!sceneChanged && !knobsChanged && !sizeChanged &&
        !(cameraChanged && state.time - checkedAt_ >= kCameraRecheckSeconds))
        return;
    if (sceneChanged) {
        lastGood_.clear();
        confirmed_.clear();
    }
    checkedSize_ = {w, h};
    checkedScene_ = &session.scene();
    checkedSource_ = session.scene().source;
    checkedEye_ = cam.position;
    checkedTarget_ = cam.target;
    checkedFov_ = cam.fovYDegrees;
    checkedAt_ = state.time;
    const std::vector<double> now = values(session);
    auto over = [&](const KnobRegistry& knobs) -> std::optional<AovCostEstimate> {
        auto e = AovCostEstimate::forKnobs(knobs, session.scene(), cam, w, h);
        const auto [aw, ah] = AovCostEstimate::aoSize(knobs, w, h);
        if (e && AovCostEstimate::exceeds(*e, aw, ah)) return e;
        return std::nullopt;
    };
    const auto estimate = over(session.knobs());
    // A confirmed state stays confirmed at its size and smaller ones; a
    // larger frame costs more and is asked about again.
    const bool confirmedHere = now == confirmed_ && static_cast<double>(w) * h <= confirmedPixels_;
    if (!estimate || confirmedHere) {
        if (!estimate) lastGood_ = now;
        checkedGeneration_ = session.knobs().generation();
        return;
    }
    // Over the limit and not confirmed: back to the last good state, or, if
    // that one is over the limit too from here, to ao.method's default.
    message_ = AovCostEstimate::warning(*estimate, session.knobs(), w, h);
    refused_ = now;
    refusedPixels_ = static_cast<double>(w) * h;
    if (!lastGood_.empty() && lastGood_ != now) restore(session, lastGood_);
    if (over(session.knobs())) {
        if (const auto m = session.knobs().find("ao.method")) session.knobs().reset(*m);
    }
    lastGood_ = values(session);
    checkedGeneration_ = session.knobs().generation();
    ++state.knobsPutBack;
    state.log.error(message_ + ". The previous settings are kept; 'Render AOV anyway' in the window 'AOV cost' "
                               "renders it",
                    state.time, "aov cost");
}

void AovCostGuard::draw(UiState& state, RenderSession& session) {
    if (refused_.empty()) return;
    const ImGuiViewport* screen = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(screen->WorkPos.x + screen->WorkSize.x * 0.5f, screen->WorkPos.y + screen->WorkSize.y * 0.4f),
                            ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(520, 0), ImGuiCond_Appearing);
    ImGui::Begin("AOV cost", nullptr, ImGuiWindowFlags_NoCollapse);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(message_.c_str());
    ImGui::TextUnformatted("The previous settings are kept.");
    ImGui::PopTextWrapPos();
    if (ImGui::Button("Render AOV anyway")) confirm(state, session);
    ImGui::SameLine();
    if (ImGui::Button("Keep the previous settings")) dismiss(state);
    ImGui::End();
}

void AovCostGuard::confirm(UiState& state, RenderSession& session) {
    if (refused_.empty()) return;
    restore(session, refused_);
    confirmed_ = refused_;
    confirmedPixels_ = refusedPixels_;
    refused_.clear();
    state.log.succeeded("aov cost");
    state.log.info("AOV: rendering the state over the cost limit, as asked", state.time);
}

void AovCostGuard::dismiss(UiState& state) {
    refused_.clear();
    state.log.succeeded("aov cost");
}

}  // namespace dw::ui
