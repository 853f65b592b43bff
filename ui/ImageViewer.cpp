#include "ui/ImageViewer.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "renderer/gl/Sampler.h"
#include "renderer/inspect/BufferView.h"
#include "renderer/inspect/OutputReadback.h"
#include "shaders/bufferview/turbo.h"
#include "ui/Widgets.h"

namespace dw::ui {

namespace {

using M = BufferViewSettings::Mapping;
using C = BufferViewSettings::Channel;

const char* kMappings[] = {"auto", "direct (range)", "linear depth", "normal colours", "heat map", "tone map", "non-finite (NaN / Inf)"};
const char* kChannels[] = {"RGB", "R", "G", "B", "A"};

ImU32 barColor(M mapping, float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    if (mapping == M::Heatmap) {
        const glm::vec3 c = gpu::turbo(t);
        return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f));
    }
    return ImGui::ColorConvertFloat4ToU32(ImVec4(t, t, t, 1.0f));
}

void bindNearest(const ImDrawList*, const ImDrawCmd* cmd) { static_cast<const gl::Sampler*>(cmd->UserCallbackData)->bind(0); }
void unbindNearest(const ImDrawList*, const ImDrawCmd*) { gl::Sampler::unbind(0); }

}  // namespace

bool displayRange(const ImageView& view, const PublishedOutput& output, const ShownImage& img, float& lo, float& hi) {
    if (isDisplayReady(output)) return false;
    const BufferViewSettings s = view.settingsOr();
    const M mapping = BufferView::resolveMapping(output.decl.kind, s);
    if (mapping != M::Direct && mapping != M::Heatmap && mapping != M::LinearDepth) return false;
    if (!BufferView::resolveAutoRange(output.decl.kind, s)) {
        lo = s.rangeMin;
        hi = s.rangeMax;
        return true;
    }
    if (!img.haveAutoRange) return false;
    // As the view shader does: one range over R, G and B for colours, the
    // channel's own otherwise; a heat map starts at 0 or below.
    const int c = static_cast<int>(s.channel) - 1;
    if (c < 0) {
        lo = std::min({img.autoLo.r, img.autoLo.g, img.autoLo.b});
        hi = std::max({img.autoHi.r, img.autoHi.g, img.autoHi.b});
    } else {
        lo = img.autoLo[c];
        hi = img.autoHi[c];
    }
    if (mapping == M::Heatmap) {
        lo = std::min(img.autoLo.r, 0.0f);
        hi = img.autoHi.r;
    }
    return true;
}

bool imageViewControls(ImageView& view, const PublishedOutput* output, const ShownImage& img, const std::string& prefix) {
    bool changed = false;
    const float w = ImGui::GetFontSize() * 7.0f;
    if (output && !isDisplayReady(*output)) {
        BufferViewSettings& s = view.settings();
        if (const int layers = selectableLayers(*output); layers > 0) {
            s.layer = std::min(s.layer, layers - 1);
            ImGui::SetNextItemWidth(w);
            const char* what = resourceKind(*output) == ResourceKind::TextureCubeArray ? "cube" : "layer";
            changed |= ImGui::SliderInt(what, &s.layer, -1, layers - 1, s.layer < 0 ? "all" : "%d");
            ImGui::SameLine();
        }
        if (const int samples = sampleCount(*output); samples > 1) {
            s.sample = std::min(s.sample, samples - 1);
            ImGui::SetNextItemWidth(w);
            changed |= ImGui::SliderInt("sample", &s.sample, -1, samples - 1, s.sample < 0 ? "resolved" : "%d");
            ImGui::SameLine();
        }
        int c = static_cast<int>(s.channel);
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 4.0f);
        if (ImGui::Combo("##channel", &c, kChannels, 5)) {
            s.channel = static_cast<C>(c);
            changed = true;
        }
        if (ImGui::IsItemHovered()) tooltip("channel shown (kept for %s)", view.output.c_str());
        ImGui::SameLine();
        int m = static_cast<int>(s.mapping) + 1;
        const M resolved = BufferView::resolveMapping(output->decl.kind, s);
        ImGui::SetNextItemWidth(w * 1.3f);
        if (ImGui::Combo("##mapping", &m, kMappings, 7)) {
            s.mapping = static_cast<M>(m - 1);
            changed = true;
        }
        if (ImGui::IsItemHovered())
            tooltip("mapping to colours; auto is %s for this output", kMappings[static_cast<int>(resolved) + 1]);
        if (resolved == M::NonFinite) {
            // NaN magenta, +Inf red, -Inf blue over a dim picture of the rest; counted from a read-back.
            ImGui::SameLine();
            const NonFiniteCount& n = img.nonFinite;
            if (!img.haveNonFinite) ImGui::TextDisabled("counting...");
            else if (n.nonFinite() == 0) ImGui::TextDisabled("no NaN or Inf in %lld values", n.values);
            else
                ImGui::TextColored(ImVec4(1.0f, 0.3f, 1.0f, 1.0f), "NaN %lld, +Inf %lld, -Inf %lld; first at (%d, %d)", n.nan,
                                   n.positiveInf, n.negativeInf, n.firstX, n.firstY);
        }
        if (resolved == M::Tonemap) {
            ImGui::SameLine();
            ImGui::SetNextItemWidth(w);
            changed |= ImGui::SliderFloat("EV", &s.exposure, -10.0f, 10.0f, "%.1f");
        }
        if (resolved == M::Direct || resolved == M::LinearDepth || resolved == M::Heatmap) {
            ImGui::SameLine();
            bool automatic = BufferView::resolveAutoRange(output->decl.kind, s);
            if (ImGui::Checkbox("auto range", &automatic)) {
                s.autoRange = automatic ? 1 : 0;
                if (!automatic) displayRange(view, *output, img, s.rangeMin, s.rangeMax);
                changed = true;
            }
            if (!automatic) {
                ImGui::SameLine();
                ImGui::SetNextItemWidth(w * 1.6f);
                float range[2] = {s.rangeMin, s.rangeMax};
                if (ImGui::InputFloat2("##range", range, "%.5g")) {
                    s.rangeMin = range[0];
                    s.rangeMax = range[1];
                    changed = true;
                }
            }
        }
        ImGui::SameLine();
        ImGui::Checkbox("histogram", &view.histogram);
        ImGui::SameLine();
    }
    // Zoom: fit, one image pixel per screen pixel, and the factor.
    if (ImGui::SmallButton("fit")) {
        view.zoom = 1.0f;
        view.center = glm::vec2(0.5f);
    }
    if (ImGui::IsItemHovered()) tooltip("the whole image in the view (Ctrl+wheel zooms at the cursor, Ctrl+drag pans)");
    ImGui::SameLine();
    if (ImGui::SmallButton("1:1") && view.fitScale > 0.0f) view.zoom = 1.0f / view.fitScale;
    if (ImGui::IsItemHovered()) tooltip("one image pixel per screen pixel");
    ImGui::SameLine();
    ImGui::TextDisabled("x%.1f", view.zoom);
    // The shown output at its own resolution (F12 saves the whole window).
    sameLineIfFits(ImGui::CalcTextSize("save EXR save PNG").x + 4 * ImGui::GetStyle().FramePadding.x);
    if (ImGui::SmallButton("save EXR")) view.saveRequest = "exr";
    if (!prefix.empty()) noteItem(prefix + ".save_exr");
    if (ImGui::IsItemHovered())
        tooltip("%s's raw values at its own resolution to an OpenEXR file in the export folder", view.output.c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("save PNG")) view.saveRequest = "png";
    if (!prefix.empty()) noteItem(prefix + ".save_png");
    if (ImGui::IsItemHovered())
        tooltip("%s as shown (channel, mapping, range) at its own resolution to a PNG in the export folder",
                          view.output.c_str());
    return changed;
}

void imageViewLegend(ImageView& view, const PublishedOutput* output, const ShownImage& img) {
    if (!output) return;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float width = ImGui::GetContentRegionAvail().x;
    float lo = 0.0f, hi = 0.0f;
    const bool ranged = displayRange(view, *output, img, lo, hi);
    const M mapping = BufferView::resolveMapping(output->decl.kind, view.settingsOr());
    if (ranged && (mapping == M::Heatmap || mapping == M::Direct || mapping == M::LinearDepth)) {
        // The colour bar: what each colour means, with values at its ends and middle.
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const float h = 10.0f, barW = std::max(width, 40.0f);
        const int steps = 64;
        for (int i = 0; i < steps; ++i) {
            const float x0 = at.x + barW * static_cast<float>(i) / steps, x1 = at.x + barW * static_cast<float>(i + 1) / steps;
            dl->AddRectFilledMultiColor(ImVec2(x0, at.y), ImVec2(x1, at.y + h), barColor(mapping, static_cast<float>(i) / steps),
                                        barColor(mapping, static_cast<float>(i + 1) / steps), barColor(mapping, static_cast<float>(i + 1) / steps),
                                        barColor(mapping, static_cast<float>(i) / steps));
        }
        ImGui::Dummy(ImVec2(barW, h));
        noteRect("legend.colour_bar", at, ImVec2(at.x + barW, at.y + h));
        char a[32], b[32], m[32];
        std::snprintf(a, sizeof(a), "%.4g", lo);
        std::snprintf(m, sizeof(m), "%.4g", 0.5f * (lo + hi));
        std::snprintf(b, sizeof(b), "%.4g%s", hi, mapping == M::LinearDepth ? " (linear depth)" : "");
        const float y = ImGui::GetCursorScreenPos().y;
        dl->AddText(ImVec2(at.x, y), IM_COL32(200, 200, 205, 255), a);
        dl->AddText(ImVec2(at.x + barW * 0.5f - ImGui::CalcTextSize(m).x * 0.5f, y), IM_COL32(200, 200, 205, 255), m);
        dl->AddText(ImVec2(at.x + barW - ImGui::CalcTextSize(b).x, y), IM_COL32(200, 200, 205, 255), b);
        ImGui::Dummy(ImVec2(barW, ImGui::GetTextLineHeight()));
    }
    if (!view.histogram) return;
    const ImageHistogram& hist = img.histogram;
    if (hist.channels.empty()) {
        ImGui::TextDisabled("histogram: %s", img.histogramOf.empty() ? "waiting for the next frame" : "this output has no image to bin");
        return;
    }
    // Per channel, log counts, over the data's finite range; the display
    // range's ends as two handles to drag.
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const ImVec2 size(std::max(width, 40.0f), 64.0f);
    dl->AddRectFilled(at, ImVec2(at.x + size.x, at.y + size.y), IM_COL32(22, 22, 26, 255));
    const int sel = static_cast<int>(view.settingsOr().channel) - 1;
    const ImU32 colours[4] = {IM_COL32(255, 90, 90, 220), IM_COL32(90, 230, 90, 220), IM_COL32(110, 140, 255, 220), IM_COL32(220, 220, 220, 200)};
    std::uint64_t maxCount = 1;
    for (const auto& ch : hist.channels)
        for (auto c : ch.counts) maxCount = std::max(maxCount, c);
    const double logMax = std::log1p(static_cast<double>(maxCount));
    for (size_t c = 0; c < hist.channels.size(); ++c) {
        if (sel >= 0 && static_cast<int>(c) != sel) continue;
        const auto& counts = hist.channels[c].counts;
        const ImU32 col = hist.channels.size() == 1 ? colours[3] : colours[c];
        for (size_t i = 0; i + 1 < counts.size(); ++i) {
            auto Y = [&](std::uint64_t n) { return at.y + size.y - size.y * static_cast<float>(std::log1p(static_cast<double>(n)) / logMax); };
            const float x0 = at.x + size.x * static_cast<float>(i) / static_cast<float>(counts.size() - 1);
            const float x1 = at.x + size.x * static_cast<float>(i + 1) / static_cast<float>(counts.size() - 1);
            dl->AddLine(ImVec2(x0, Y(counts[i])), ImVec2(x1, Y(counts[i + 1])), col, 1.2f);
        }
    }
    auto X = [&](float v) { return at.x + size.x * (v - hist.lo) / std::max(hist.hi - hist.lo, 1e-20f); };
    ImGui::InvisibleButton("##histogram", size);
    if (ranged) {
        BufferViewSettings& s = view.settings();
        for (int end = 0; end < 2; ++end) {
            const float v = end == 0 ? lo : hi;
            const float x = std::clamp(X(v), at.x, at.x + size.x);
            dl->AddLine(ImVec2(x, at.y), ImVec2(x, at.y + size.y), IM_COL32(255, 220, 80, 255), 2.0f);
            ImGui::SetCursorScreenPos(ImVec2(x - 4.0f, at.y));
            ImGui::PushID(end);
            ImGui::InvisibleButton("##handle", ImVec2(8.0f, size.y));
            if (ImGui::IsItemHovered() || ImGui::IsItemActive()) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
            if (ImGui::IsItemActive() && ImGui::GetIO().MouseDelta.x != 0.0f) {
                // Dragging a handle sets the range by hand.
                const float value = hist.lo + (ImGui::GetIO().MousePos.x - at.x) / size.x * (hist.hi - hist.lo);
                if (BufferView::resolveAutoRange(output->decl.kind, s)) {
                    s.autoRange = 0;
                    s.rangeMin = lo;
                    s.rangeMax = hi;
                }
                (end == 0 ? s.rangeMin : s.rangeMax) = value;
            }
            ImGui::PopID();
        }
        ImGui::SetCursorScreenPos(ImVec2(at.x, at.y + size.y));
    }
    std::uint64_t nan = 0, inf = 0;
    for (const auto& ch : hist.channels) {
        nan += ch.nan;
        inf += ch.inf;
    }
    char facts[160];
    std::snprintf(facts, sizeof(facts), "values %.4g .. %.4g, log counts%s", hist.lo, hist.hi, nan + inf ? "," : "");
    ImGui::TextDisabled("%s", facts);
    if (nan + inf) {
        ImGui::SameLine();
        ImGui::TextColored(kErrorColor, "%llu NaN, %llu Inf", static_cast<unsigned long long>(nan), static_cast<unsigned long long>(inf));
    }
}

ImagePlacement drawImageView(ImageView& view, const ShownImage& img, ImVec2 boxMin, ImVec2 boxSize, const gl::Sampler* nearest,
                             bool hovered, bool active) {
    const glm::vec2 bmin(boxMin.x, boxMin.y), bsize(boxSize.x, boxSize.y);
    ImagePlacement p = placeImage(glm::vec2(img.width, img.height), bmin, bsize, view);
    if (p.fitScale > 0.0f) view.fitScale = p.fitScale;
    ImGuiIO& io = ImGui::GetIO();
    if (img.texture && hovered && io.KeyCtrl && io.MouseWheel != 0.0f) {
        zoomAt(view, std::pow(1.25f, io.MouseWheel), glm::vec2(io.MousePos.x, io.MousePos.y), p);
        p = placeImage(glm::vec2(img.width, img.height), bmin, bsize, view);
    }
    if (img.texture && active && io.KeyCtrl && ImGui::IsMouseDown(ImGuiMouseButton_Left) && p.size.x > 0.0f) {
        view.center -= glm::vec2(io.MouseDelta.x, io.MouseDelta.y) / p.size;
        view.center = glm::clamp(view.center, glm::vec2(0.0f), glm::vec2(1.0f));
        p = placeImage(glm::vec2(img.width, img.height), bmin, bsize, view);
    }
    ImDrawList* dl = ImGui::GetWindowDrawList();
    if (!img.texture || img.width <= 0 || img.height <= 0) {
        dl->AddRectFilled(boxMin, ImVec2(boxMin.x + boxSize.x, boxMin.y + boxSize.y), IM_COL32(30, 30, 34, 255));
        const std::string why = img.unavailable.empty() ? "no image" : img.unavailable;
        dl->AddText(nullptr, 0.0f, ImVec2(boxMin.x + 12, boxMin.y + 12), IM_COL32(255, 140, 120, 255), why.c_str(), nullptr,
                    std::max(boxSize.x - 24.0f, 40.0f));
        return p;
    }
    dl->PushClipRect(boxMin, ImVec2(boxMin.x + boxSize.x, boxMin.y + boxSize.y), true);
    // Pixel level: each image pixel a crisp square, not a blur.
    const bool crisp = nearest && p.size.x / static_cast<float>(img.width) >= 2.0f;
    if (crisp) dl->AddCallback(bindNearest, const_cast<gl::Sampler*>(nearest));
    dl->AddImage(textureId(img.texture), ImVec2(p.min.x, p.min.y), ImVec2(p.min.x + p.size.x, p.min.y + p.size.y), ImVec2(0, 1),
                 ImVec2(1, 0));
    if (crisp) dl->AddCallback(unbindNearest, nullptr);
    dl->PopClipRect();
    return p;
}

}  // namespace dw::ui
