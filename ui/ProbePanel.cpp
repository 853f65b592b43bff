#include "ui/ProbePanel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "ui/Widgets.h"

namespace dw::ui {

namespace {
void row(const char* label, const char* fmt, ...) IM_FMTARGS(2);
void row(const char* label, const char* fmt, ...) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    clippedText(label, ImGui::GetContentRegionAvail().x);
    ImGui::TableNextColumn();
    va_list args;
    va_start(args, fmt);
    char text[1024];
    std::vsnprintf(text, sizeof(text), fmt, args);
    va_end(args);
    clippedText(text, ImGui::GetContentRegionAvail().x);
}

// Label and value columns: the label as wide as the longest label needs.
bool beginRows(const char* id, float labelWidth) {
    if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg)) return false;
    ImGui::TableSetupColumn("label", ImGuiTableColumnFlags_WidthFixed, labelWidth);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
    return true;
}
}  // namespace

void ProbePanel::draw(const char* title, bool* open, UiState& state) {
    if (!beginPanel(title, open)) {
        ImGui::End();
        return;
    }
    const ProbeState& p = state.probe;
    if (!p.result.inside) {
        ImGui::TextDisabled("Hover over the viewport to read a pixel; click to pin it.");
        ImGui::End();
        return;
    }
    ImGui::Text("pixel (%d, %d)%s", p.result.x, p.result.y, p.pinned ? "  [pinned, Esc to release]" : "");
    // Magnifier of the viewport image around the pixel (nearest filtering).
    const ShownImage& img = state.viewportImage;
    if (img.texture && img.width > 0) {
        ImGui::SliderInt("zoom", &zoomPixels, 5, 63);
        const float half = zoomPixels * 0.5f;
        const float cx = p.uv.x * img.width, cy = p.uv.y * img.height;
        // GL textures are bottom-up: flip v.
        const ImVec2 uv0((cx - half) / img.width, 1.0f - (cy - half) / img.height);
        const ImVec2 uv1((cx + half) / img.width, 1.0f - (cy + half) / img.height);
        const float side = std::min(ImGui::GetContentRegionAvail().x, 180.0f);
        const ImVec2 at = ImGui::GetCursorScreenPos();
        ImGui::Image(textureId(img.texture), ImVec2(side, side), uv0, uv1);
        const float cell = side / zoomPixels;
        ImGui::GetWindowDrawList()->AddRect(ImVec2(at.x + side * 0.5f - cell * 0.5f, at.y + side * 0.5f - cell * 0.5f),
                                            ImVec2(at.x + side * 0.5f + cell * 0.5f, at.y + side * 0.5f + cell * 0.5f),
                                            IM_COL32(255, 255, 0, 255));
    }
    const SurfaceSample& s = p.result.surface;
    if (beginRows("surface", ImGui::CalcTextSize("position (world)").x + 8.0f)) {
        if (s.background) {
            row("surface", "background (no geometry)");
        } else {
            row("depth", "%.7f (linear %.4f)", s.depth, s.linearDepth);
            row("position (view)", "%.4f %.4f %.4f", s.viewPosition.x, s.viewPosition.y, s.viewPosition.z);
            row("position (world)", "%.4f %.4f %.4f", s.worldPosition.x, s.worldPosition.y, s.worldPosition.z);
            row("normal (view)", "%.4f %.4f %.4f", s.viewNormal.x, s.viewNormal.y, s.viewNormal.z);
            row("albedo", "%.4f %.4f %.4f", s.albedo.r, s.albedo.g, s.albedo.b);
            row("specular", "%.4f %.4f %.4f  n = %.1f", s.specular.r, s.specular.g, s.specular.b, s.exponent);
            row("emissive", "%.4f %.4f %.4f", s.emissive.r, s.emissive.g, s.emissive.b);
        }
        row("L-buffer", "%.5g %.5g %.5g  (L = %.5g)", s.radiance.r, s.radiance.g, s.radiance.b, s.luminance);
        ImGui::EndTable();
    }
    // The lights a volume strategy evaluates here (their volumes contain the
    // surface point); the viewport's volume overlay shows just these by default.
    if (!s.background) {
        char head[96];
        std::snprintf(head, sizeof(head), "lights at this pixel: %zu (+%d directional)###lights", p.lights.size(), p.directionalLights);
        if (ImGui::CollapsingHeader(head, ImGuiTreeNodeFlags_DefaultOpen))
            for (const auto& line : p.lightLines) ImGui::TextWrapped("%s", line.c_str());  // wrapped, never cut
    }
    float labelWidth = ImGui::CalcTextSize("sample 00").x;
    for (const auto& v : p.result.values) labelWidth = std::max(labelWidth, ImGui::CalcTextSize(v.output.c_str()).x);
    labelWidth = std::min(labelWidth + 8.0f, ImGui::GetContentRegionAvail().x * 0.5f);
    if (ImGui::CollapsingHeader("every output at this pixel", ImGuiTreeNodeFlags_DefaultOpen) && beginRows("raw", labelWidth)) {
        for (const auto& v : p.result.values) {
            switch (v.channels) {
                case 1: row(v.output.c_str(), "%.6g", v.raw.x); break;
                case 2: row(v.output.c_str(), "%.6g %.6g", v.raw.x, v.raw.y); break;
                case 3: row(v.output.c_str(), "%.5g %.5g %.5g", v.raw.x, v.raw.y, v.raw.z); break;
                default: row(v.output.c_str(), "%.5g %.5g %.5g %.5g", v.raw.x, v.raw.y, v.raw.z, v.raw.w); break;
            }
            // A multisample output: every sample under the mean above.
            for (size_t i = 0; i < v.samples.size(); ++i) {
                const std::string label = "  sample " + std::to_string(i);
                const glm::vec4& c = v.samples[i];
                if (v.channels == 1) row(label.c_str(), "%.6g", c.x);
                else row(label.c_str(), "%.5g %.5g %.5g %.5g", c.x, c.y, c.z, c.w);
            }
            // A per-pixel buffer element beyond its first four words.
            if (v.words.size() > 4) {
                std::string hex;
                for (std::uint32_t w : v.words) {
                    char b[12];
                    std::snprintf(b, sizeof(b), "%08x ", w);
                    hex += b;
                }
                row("  words", "%s", hex.c_str());
            }
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace dw::ui
