#include "ui/ReferenceControls.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "renderer/passes/ReferencePass.h"
#include "ui/Widgets.h"

namespace dw::ui {

std::string ReferenceControls::currentKey(RenderSession& session, reference::ReferenceRequest* request,
                                          reference::ReferenceModel* model) const {
    reference::ReferenceModel m = reference::ReferenceModel::fromKnobs(session.knobs(), session.scene());
    m.aoRays = std::clamp(aoRays, 1, 1024);
    m.pixelSamples = std::clamp(pixelSamples, 1, 256);
    reference::ReferenceRequest r;
    r.camera = session.camera();
    r.width = session.pipeline().width();
    r.height = session.pipeline().height();
    if (request) *request = r;
    if (model) *model = m;
    return reference::viewKey(session.scene(), m, r);
}

void ReferenceControls::start(UiState& state, RenderSession& session) {
    reference::ReferenceRequest request;
    reference::ReferenceModel model;
    currentKey(session, &request, &model);
    if (request.width < 1 || request.height < 1) {
        state.log.error("no frame has been rendered yet to take a reference of", state.time, "reference");
        return;
    }
    // The flames (fire) stay where this frame put them while the reference is rendered and shown.
    state.heldFlameFrame = state.flameFrame;
    job_.start(session.scene(), model, request);
    state.log.info("CPU reference of the view started (" + std::to_string(request.width) + "x" +
                       std::to_string(request.height) + ", " + std::to_string(aoRays) + " AO rays, " +
                       std::to_string(pixelSamples) + " samples per pixel)",
                   state.time);
}

void ReferenceControls::menuItems(UiState& state) {
    if (ImGui::MenuItem("CPU reference of this view", "F9", false, !job_.running())) state.requestReference = true;
    if (ImGui::IsItemHovered())
        tooltip("ray-traced ground truth (Embree, double precision) of this view, in the background; then "
                          "reference.lbuffer, reference.final, reference.ao and compare.error in the inspector");
    if (job_.running() && ImGui::MenuItem("Cancel the CPU reference")) job_.cancel();
    ImGui::SetNextItemWidth(120);
    // Held to reference --ao-rays' and --spp's ranges, also when typed (Ctrl+click).
    ImGui::SliderInt("AO rays", &aoRays, 1, 1024, "%d", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    ImGui::SliderInt("samples per pixel", &pixelSamples, 1, 256, "%d",
                     ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("reference --spp: 1 traces the pixel's centre; N averages N points over the pixel\n"
                          "(the truth of its area; reference.spp_error shows each pixel's standard error)");
}

void ReferenceControls::progressBar() {
    if (!job_.running()) return;
    char text[64];
    std::snprintf(text, sizeof text, "CPU reference %.0f%%", 100.0 * job_.progress());
    ImGui::ProgressBar(static_cast<float>(job_.progress()), ImVec2(180, 0), text);
    ImGui::SameLine();
    if (ImGui::SmallButton("cancel##reference")) job_.cancel();
}

void ReferenceControls::update(UiState& state, RenderSession& session) {
    auto* pass = session.pipeline().pass<ReferencePass>();
    if (!pass) return;
    if (state.requestReferenceCancel && job_.running()) job_.cancel();
    state.requestReferenceCancel = false;
    if (state.requestReference && !job_.running()) start(state, session);
    state.requestReference = false;
    std::string key;
    if (auto images = job_.takeResult(&key)) {
        ++state.referenceJobsEnded;
        auto shown = std::make_shared<ReferencePass::Images>();
        shown->lbuffer = images->lbuffer;
        shown->final = images->final;
        shown->ao = images->ao;
        shown->sppError = images->sppError;
        char describe[160];
        std::snprintf(describe, sizeof describe, "CPU reference (%.1f s, %d AO rays, AO standard error mean %.4f)",
                      images->stats.seconds, aoRays, images->stats.aoStandardErrorMean);
        shown->describe = describe;
        if (key == currentKey(session)) {
            pass->setReference(shown);
            shownKey_ = key;
            state.forceRender = true;  // the reference's outputs appear in the next frame
            state.log.done(std::string(describe) + " ready: reference.lbuffer, reference.final, reference.ao, compare.error",
                           state.time, "reference");
        } else {
            state.log.info("the CPU reference finished after the view changed; render it again (F9)", state.time);
        }
    }
    if (const std::string e = job_.takeError(); !e.empty()) {
        ++state.referenceJobsEnded;
        if (e == "cancelled") state.log.info("CPU reference cancelled", state.time);
        else state.log.error("CPU reference failed: " + e, state.time, "reference");
    }
    if (!shownKey_.empty() && currentKey(session) != shownKey_) {
        pass->setReference(nullptr, "the view changed since the CPU reference (camera, size, lights, the scene time or a "
                                    "knob of the model): render it again (F9)");
        shownKey_.clear();
        state.forceRender = true;
    }
    state.holdView = job_.running() || !shownKey_.empty();
    state.referenceProgress = job_.running() ? job_.progress() : -1.0;
    if (!state.holdView) state.heldFlameFrame.reset();
}

}  // namespace dw::ui
