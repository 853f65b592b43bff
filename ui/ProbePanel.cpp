#include "ui/ProbePanel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "ui/Widgets.h"

namespace dw::ui {

namespace {
// A label and value row; the pair also goes to `copy` (the panel's text for the clipboard).
void row(std::string& copy, const char* label, const char* fmt, ...) IM_FMTARGS(3);
void row(std::string& copy, const char* label, const char* fmt, ...) {
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
    std::string l(label);
    l.erase(0, l.find_first_not_of(' '));
    copy += l + "\t" + text + "\n";
}

// Label and value columns: the label as wide as the longest label needs.
bool beginRows(const char* id, float labelWidth) {
    if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg)) return false;
    ImGui::TableSetupColumn("label", ImGuiTableColumnFlags_WidthFixed, labelWidth);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
    return true;
}
// Magnifier of the viewport image around the pixel (nearest filtering), `zoomPixels` across.
void magnifier(const ProbeState& p, const ShownImage& img, int& zoomPixels) {
    if (img.texture && img.width > 0) {
        // The label keeps its room ("zoom" was cut beside a full-width slider).
        ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("zoom").x -
                                             ImGui::GetStyle().ItemInnerSpacing.x, 40.0f));
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
}

// The G-buffer's surface at the pixel and its L-buffer value.
void surfaceRows(std::string& copy, const SurfaceSample& s) {
    if (beginRows("surface", ImGui::CalcTextSize("position (world)").x + 8.0f)) {
        if (s.background) {
            row(copy, "surface", "background (no geometry)");
        } else {
            row(copy, "depth", "%.7f (linear %.4f)", s.depth, s.linearDepth);
            row(copy, "position (view)", "%.4f %.4f %.4f", s.viewPosition.x, s.viewPosition.y, s.viewPosition.z);
            row(copy, "position (world)", "%.4f %.4f %.4f", s.worldPosition.x, s.worldPosition.y, s.worldPosition.z);
            row(copy, "normal (view)", "%.4f %.4f %.4f", s.viewNormal.x, s.viewNormal.y, s.viewNormal.z);
            row(copy, "albedo", "%.4f %.4f %.4f", s.albedo.r, s.albedo.g, s.albedo.b);
            row(copy, "specular", "%.4f %.4f %.4f  n = %.1f", s.specular.r, s.specular.g, s.specular.b, s.exponent);
            row(copy, "emissive", "%.4f %.4f %.4f", s.emissive.r, s.emissive.g, s.emissive.b);
        }
        row(copy, "L-buffer", "%.5g %.5g %.5g  (L = %.5g)", s.radiance.r, s.radiance.g, s.radiance.b, s.luminance);
        ImGui::EndTable();
    }
}

// The lights a volume strategy evaluates here and the transparent fragments the oit method kept.
void lightsAndFragments(std::string& copy, const ProbeState& p) {
    const SurfaceSample& s = p.result.surface;
    // The lights a volume strategy evaluates here (their volumes contain the
    // surface point); the viewport's volume overlay shows just these by default.
    if (!s.background) {
        char head[96];
        std::snprintf(head, sizeof(head), "lights at this pixel: %zu (+%d directional)###lights", p.lights.size(), p.directionalLights);
        if (ImGui::CollapsingHeader(head, ImGuiTreeNodeFlags_DefaultOpen))
            for (const auto& line : p.lightLines) ImGui::TextWrapped("%s", line.c_str());  // wrapped, never cut
        for (const auto& line : p.lightLines) copy += "light\t" + line + "\n";
    }
    // The transparent fragments the oit method kept here, nearest first (issue 21).
    if (!p.result.fragmentsFrom.empty()) {
        char head[96];
        std::snprintf(head, sizeof(head), "transparent fragments: %zu (%s)###fragments", p.result.fragments.size(),
                      p.result.fragmentsFrom.c_str());
        if (ImGui::CollapsingHeader(head, ImGuiTreeNodeFlags_DefaultOpen) &&
            beginRows("fragments", ImGui::CalcTextSize("fragment 00").x + 8.0f)) {
            for (std::size_t i = 0; i < p.result.fragments.size(); ++i) {
                const TransparentFragment& f = p.result.fragments[i];
                const std::string label = "fragment " + std::to_string(i);
                row(copy, label.c_str(), "depth %.6f  colour %.4g %.4g %.4g  alpha %.3f", f.depth, f.colour.r, f.colour.g,
                    f.colour.b, f.alpha);
            }
            ImGui::EndTable();
        }
    }
}

// Every output's raw value at the pixel, a multisample output's samples, a buffer element's words.
void everyOutput(std::string& copy, const ProbeState& p) {
    float labelWidth = ImGui::CalcTextSize("sample 00").x;
    for (const auto& v : p.result.values) labelWidth = std::max(labelWidth, ImGui::CalcTextSize(v.output.c_str()).x);
    labelWidth = std::min(labelWidth + 8.0f, ImGui::GetContentRegionAvail().x * 0.5f);
    if (ImGui::CollapsingHeader("every output at this pixel", ImGuiTreeNodeFlags_DefaultOpen) && beginRows("raw", labelWidth)) {
        for (const auto& v : p.result.values) {
            switch (v.channels) {
                case 1: row(copy, v.output.c_str(), "%.6g", v.raw.x); break;
                case 2: row(copy, v.output.c_str(), "%.6g %.6g", v.raw.x, v.raw.y); break;
                case 3: row(copy, v.output.c_str(), "%.5g %.5g %.5g", v.raw.x, v.raw.y, v.raw.z); break;
                default: row(copy, v.output.c_str(), "%.5g %.5g %.5g %.5g", v.raw.x, v.raw.y, v.raw.z, v.raw.w); break;
            }
            // A multisample output: every sample under the mean above.
            for (size_t i = 0; i < v.samples.size(); ++i) {
                const std::string label = "  sample " + std::to_string(i);
                const glm::vec4& c = v.samples[i];
                if (v.channels == 1) row(copy, label.c_str(), "%.6g", c.x);
                else row(copy, label.c_str(), "%.5g %.5g %.5g %.5g", c.x, c.y, c.z, c.w);
            }
            // A per-pixel buffer element beyond its first four words.
            if (v.words.size() > 4) {
                std::string hex;
                for (std::uint32_t w : v.words) {
                    char b[12];
                    std::snprintf(b, sizeof(b), "%08x ", w);
                    hex += b;
                }
                row(copy, "  words", "%s", hex.c_str());
            }
        }
        ImGui::EndTable();
    }
}

}  // namespace

void ProbePanel::draw(const char* title, bool* open, UiState& state) {
    if (!beginPanel(title, open)) {
        ImGui::End();
        return;
    }
    const ProbeState& p = state.probe;
    if (!p.result.inside) {
        wrappedColored(kDimColor, "Hover over the viewport to read a pixel; click to pin it.");
        ImGui::End();
        return;
    }
    ImGui::Text("pixel (%d, %d)%s", p.result.x, p.result.y, p.pinned ? "  [pinned, Esc to release]" : "");
    // Wrapped rather than cut in a narrow panel (beside the Pareto panel: "cop").
    sameLineIfFits(ImGui::CalcTextSize("copy").x + 2.0f * ImGui::GetStyle().FramePadding.x);
    // Every value below as tab-separated lines (this frame's, drawn last frame).
    if (ImGui::SmallButton("copy")) {
        ImGui::SetClipboardText(copyText.c_str());
        state.log.done("probe values of pixel (" + std::to_string(p.result.x) + ", " + std::to_string(p.result.y) +
                           ") copied to the clipboard",
                       state.time);
    }
    std::string copy = "pixel\t" + std::to_string(p.result.x) + " " + std::to_string(p.result.y) + "\n";
    magnifier(p, state.viewportImage, zoomPixels);
    surfaceRows(copy, p.result.surface);
    lightsAndFragments(copy, p);
    everyOutput(copy, p);
    copyText = std::move(copy);
    ImGui::End();
}

}  // namespace dw::ui
