#include "ui/AbSplitView.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "renderer/metrics/Bootstrap.h"
#include "renderer/gl/Sampler.h"
#include "renderer/knobs/Preset.h"
#include "ui/Widgets.h"

namespace dw::ui {

namespace {

const char* sourceName(AbSource s) {
    switch (s) {
        case AbSource::Pinned: return "pinned";
        case AbSource::Preset: return "preset";
        case AbSource::Reference: return "CPU reference";
    }
    return "";
}

const char* displayName(AbDisplay d) {
    switch (d) {
        case AbDisplay::Split: return "split";
        case AbDisplay::Difference: return "|A-B| heat map";
        case AbDisplay::Flip: return "FLIP heat map";
    }
    return "";
}

// Pixel level: B's pixels crisp squares, as drawImageView draws A's.
void bindNearest(const ImDrawList*, const ImDrawCmd* cmd) { static_cast<const gl::Sampler*>(cmd->UserCallbackData)->bind(0); }
void unbindNearest(const ImDrawList*, const ImDrawCmd*) { gl::Sampler::unbind(0); }

ImTextureID textureOf(unsigned texture) { return reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(texture)); }

std::string msText(const std::vector<double>& ms) {
    if (ms.empty()) return "-";
    char t[48];
    std::snprintf(t, sizeof(t), "%.2f ms (%zu)", median(ms), ms.size());
    return t;
}

// Split, |A-B| or FLIP: as wide as its longest choice ("FLIP heat ma" was
// cut at 1024x640), the whole choice in its tooltip.
void displayCombo(AbView& ab) {
    ImGui::SetNextItemWidth(ImGui::CalcTextSize(displayName(AbDisplay::Flip)).x + ImGui::GetFrameHeight() +
                            2.0f * ImGui::GetStyle().FramePadding.x);
    if (ImGui::BeginCombo("##ab_display", displayName(ab.display))) {
        for (AbDisplay d : {AbDisplay::Split, AbDisplay::Difference, AbDisplay::Flip})
            if (ImGui::Selectable(displayName(d), ab.display == d)) {
                ab.display = d;
                ++ab.generation;
            }
        ImGui::EndCombo();
    }
    noteItem("ab.display");
    if (ImGui::IsItemHovered())
        tooltip("A/B display: %s (split: A left of the divider, B right; |A-B|: the absolute difference; FLIP: the "
                "perceived difference)",
                displayName(ab.display));
}

}  // namespace

float abControls(UiState& state) {
    AbView& ab = state.ab;
    if (ImGui::Checkbox("A/B", &ab.enabled)) ++ab.generation;
    noteItem("ab.toggle");
    if (ImGui::IsItemHovered())
        tooltip("A/B split (b): the current settings left of the divider (A), and right of it (B) a pinned\n"
                          "snapshot, a preset over the current settings, or the CPU reference; drag the divider");
    if (!ab.enabled) return 0.0f;
    ImGui::SameLine();
    // As wide as its longest choice ("CPU referer" was cut).
    ImGui::SetNextItemWidth(ImGui::CalcTextSize("CPU reference").x + ImGui::GetFrameHeight() + 2.0f * ImGui::GetStyle().FramePadding.x);
    if (ImGui::BeginCombo("##ab_source", sourceName(ab.source))) {
        for (AbSource s : {AbSource::Pinned, AbSource::Preset, AbSource::Reference})
            if (ImGui::Selectable(sourceName(s), ab.source == s)) {
                ab.source = s;
                ++ab.generation;
            }
        ImGui::EndCombo();
    }
    if (ab.source == AbSource::Preset) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);
        if (ImGui::BeginCombo("##ab_preset", ab.preset.empty() ? "choose" : ab.preset.c_str())) {
            for (const Preset& p : builtinPresets())
                if (ImGui::Selectable(p.name.c_str(), ab.preset == p.name)) {
                    ab.preset = p.name;
                    ++ab.generation;
                }
            ImGui::EndCombo();
        }
    }
    ImGui::SameLine();
    displayCombo(ab);
    ImGui::SameLine();
    if (ImGui::SmallButton("Pin")) ab.pinRequest = true;
    noteItem("ab.pin");
    if (ImGui::IsItemHovered()) tooltip("the current image becomes B (p)");
    // The numbers, in parts (B, A against B, against the reference, the GPU
    // times); a part wider than the panel is cut with "..." and shown whole
    // in a tooltip.
    std::vector<std::string> parts;
    bool error = false;
    if (!ab.ready) {
        parts.push_back("B: " + (ab.unavailable.empty() ? std::string("rendering...") : ab.unavailable));
        error = !ab.unavailable.empty();
    } else {
        char t[256];
        parts.push_back("A current | B " + ab.describeB);
        std::snprintf(t, sizeof(t), "A vs B: RMS %.5f, FLIP %.4f", ab.rms, ab.haveFlip ? ab.flip : 0.0);
        parts.emplace_back(t);
        if (ab.a.haveError) {
            std::snprintf(t, sizeof(t), "vs reference RMS/FLIP: A %.5f/%.4f, B %.5f/%.4f", ab.a.rms, ab.a.flip, ab.b.rms,
                          ab.b.flip);
            parts.emplace_back(t);
        }
        std::string gpu = "GPU A " + msText(ab.a.gpuMs) + ", B " +
                          (ab.source == AbSource::Reference ? std::string("- (CPU)") : msText(ab.b.gpuMs));
        if (ab.gpuDifference.valid()) {
            std::snprintf(t, sizeof(t), ", A-B %+.2f ms [%+.2f, %+.2f]", ab.gpuDifference.difference, ab.gpuDifference.low,
                          ab.gpuDifference.high);
            gpu += t;
        }
        parts.push_back(gpu);
    }
    // Packed on as many lines as the panel's width asks for (they take room
    // from the image box, not the render: abControls' caller). At 1600x900 a
    // single line with the reference's errors was cut, and its tooltip ran
    // off the window.
    const float avail = ImGui::GetContentRegionAvail().x;
    std::vector<std::string> text(1);
    for (const std::string& part : parts) {
        std::string& cur = text.back();
        const std::string joined = cur.empty() ? part : cur + " | " + part;
        if (cur.empty() || ImGui::CalcTextSize(joined.c_str()).x <= avail) cur = joined;
        else text.push_back(part);
    }
    const float top = ImGui::GetCursorPosY();
    ImGui::BeginGroup();
    for (const std::string& l : text) {
        if (error) ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
        else if (!ab.ready) ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
        clippedText(l, avail);
        if (error || !ab.ready) ImGui::PopStyleColor();
    }
    ImGui::EndGroup();
    noteItem("ab.numbers");
    return ImGui::GetCursorPosY() - top;
}

bool drawAbSplit(UiState& state, ImVec2 boxMin, ImVec2 boxSize, const ImagePlacement& placed, bool hovered) {
    AbView& ab = state.ab;
    if (!ab.enabled || !ab.ready || placed.size.x <= 0.0f) {
        ab.dragging = false;
        return false;
    }
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 boxMax(boxMin.x + boxSize.x, boxMin.y + boxSize.y);
    const float x0 = placed.min.x, y0 = placed.min.y, x1 = placed.min.x + placed.size.x, y1 = placed.min.y + placed.size.y;
    // The divider follows the mouse while dragged; a press within 5 px of it starts a drag.
    const ImGuiIO& io = ImGui::GetIO();
    float dx = x0 + ab.divider * placed.size.x;
    const bool near = hovered && std::fabs(io.MousePos.x - dx) <= 5.0f && io.MousePos.y >= std::max(y0, boxMin.y) &&
                      io.MousePos.y <= std::min(y1, boxMax.y);
    if (near && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !io.KeyCtrl) ab.dragging = true;
    if (ab.dragging) {
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) ab.divider = std::clamp((io.MousePos.x - x0) / placed.size.x, 0.0f, 1.0f);
        else ab.dragging = false;
        dx = x0 + ab.divider * placed.size.x;
    }
    if (near || ab.dragging) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    // B's part (image rows bottom-up, as drawImageView draws A: v from 1 to 0).
    const unsigned right = ab.display == AbDisplay::Split ? ab.textureB : ab.heatTexture;
    dl->PushClipRect(boxMin, boxMax, true);
    const bool crisp = state.nearestSampler && ab.width > 0 && placed.size.x / static_cast<float>(ab.width) >= 2.0f;
    if (crisp) dl->AddCallback(bindNearest, const_cast<gl::Sampler*>(state.nearestSampler));
    dl->AddImage(textureOf(right), ImVec2(dx, y0), ImVec2(x1, y1), ImVec2(ab.divider, 1.0f), ImVec2(1.0f, 0.0f));
    if (crisp) dl->AddCallback(unbindNearest, nullptr);
    const float top = std::max(y0, boxMin.y), bottom = std::min(y1, boxMax.y);
    dl->AddLine(ImVec2(dx, top), ImVec2(dx, bottom), IM_COL32(255, 255, 255, 230), 2.0f);
    const float mid = 0.5f * (top + bottom);
    dl->AddRectFilled(ImVec2(dx - 4, mid - 14), ImVec2(dx + 4, mid + 14), IM_COL32(255, 255, 255, 230), 2.0f);
    dl->AddText(ImVec2(dx - 16, top + 4), IM_COL32(255, 255, 255, 255), "A");
    dl->AddText(ImVec2(dx + 8, top + 4), IM_COL32(255, 255, 255, 255), "B");
    if (ab.display != AbDisplay::Split) {
        char scale[64];
        std::snprintf(scale, sizeof(scale), "%s 0..%.3g", ab.display == AbDisplay::Flip ? "FLIP" : "|A-B|", ab.heatHigh);
        dl->AddText(ImVec2(dx + 8, top + 20), IM_COL32(255, 255, 255, 255), scale);
    }
    dl->PopClipRect();
    noteRect("ab.divider", ImVec2(dx - 1, top), ImVec2(dx + 1, bottom));
    noteRect("ab.image", ImVec2(x0, y0), ImVec2(x1, y1));
    ab.dividerScreen = glm::vec2(dx, top);
    return near || ab.dragging;
}

}  // namespace dw::ui
