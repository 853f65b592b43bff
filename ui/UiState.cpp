#include "ui/UiState.h"

#include <algorithm>

namespace dw::ui {

namespace {
constexpr size_t kMaxMessages = 200;

// A message is at most kMaxMessageBytes on screen: a record's knob of 20 000
// characters, echoed in its error, took ImGui past its 65 536 vertices a
// draw list and aborted the window. Cut at a UTF-8 character's start.
std::string shortened(std::string text) {
    if (text.size() <= MessageLog::kMaxMessageBytes) return text;
    const size_t whole = text.size();
    size_t cut = MessageLog::kMaxMessageBytes;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    text.resize(cut);
    return text + " ... (" + std::to_string(whole - cut) + " more bytes)";
}
}  // namespace

void MessageLog::push(Message m) {
    m.text = shortened(std::move(m.text));
    messages_.push_back(std::move(m));
    if (messages_.size() > kMaxMessages) {
        messages_.pop_front();
        if (bannerIndex_ >= 0) --bannerIndex_;
        if (toastIndex_ >= 0) --toastIndex_;
    }
}

void MessageLog::info(const std::string& text, double time) { push({time, false, text, {}}); }

void MessageLog::error(const std::string& text, double time, const std::string& action) {
    push({time, true, text, action});
    bannerIndex_ = static_cast<long>(messages_.size() - 1);
}

void MessageLog::done(const std::string& text, double time, const std::string& action) {
    push({time, false, text, action});
    toastIndex_ = static_cast<long>(messages_.size() - 1);
    succeeded(action);
}

void MessageLog::succeeded(const std::string& action) {
    if (const Message* b = banner(); b && !action.empty() && b->action == action) dismissBanner();
}

const Message* MessageLog::toast(double now) const {
    if (toastIndex_ < 0) return nullptr;
    const Message& m = messages_[static_cast<size_t>(toastIndex_)];
    return now - m.time <= kToastSeconds ? &m : nullptr;
}

}  // namespace dw::ui

namespace dw::ui {

StartResolution startResolution(const std::string& option, bool cpuRasterizer, bool scripted) {
    StartResolution r;
    if (option == "1/2") r.scale = ResolutionScale::Half;
    else if (option == "1/4") r.scale = ResolutionScale::Quarter;
    else if (option == "auto") r.scale = ResolutionScale::Auto;
    else if (option.empty() && cpuRasterizer && !scripted) {
        r.scale = ResolutionScale::Auto;
        r.autoScale = 0.25f;
        r.frameTargetMs = 150.0f;
        r.softwareDefault = true;
    }
    return r;
}

void ImageView::show(const std::string& name) {
    if (name == output) return;
    framingByOutput_[output] = {zoom, center, histogram};
    output = name;
    const auto it = framingByOutput_.find(name);
    const Framing f = it == framingByOutput_.end() ? Framing{} : it->second;
    zoom = f.zoom;
    center = f.center;
    histogram = f.histogram;
}

ImagePlacement placeImage(glm::vec2 imageSize, glm::vec2 boxMin, glm::vec2 boxSize, const ImageView& view) {
    ImagePlacement p;
    if (imageSize.x <= 0.0f || imageSize.y <= 0.0f) return p;
    p.fitScale = std::min(boxSize.x / imageSize.x, boxSize.y / imageSize.y);
    p.size = imageSize * p.fitScale * std::max(view.zoom, 1e-3f);
    p.min = boxMin + boxSize * 0.5f - view.center * p.size;
    return p;
}

float nextAutoScale(float scale, float frameMs, float targetMs) {
    if (!(frameMs > 0.0f) || !(targetMs > 0.0f)) return scale;
    if (frameMs > targetMs) scale *= 0.8f;
    else if (frameMs < 0.5f * targetMs) scale *= 1.25f;
    return std::clamp(scale, 0.125f, 1.0f);
}

void zoomAt(ImageView& view, float factor, glm::vec2 screen, const ImagePlacement& before) {
    const glm::vec2 uv = before.uvAt(screen);
    const float zoom = std::clamp(view.zoom * factor, 0.05f, 256.0f);
    // The point under the cursor stays: centre moves towards it by the zoom change.
    const float k = before.size.x > 0.0f ? view.zoom / zoom : 1.0f;
    view.center = uv + (view.center - uv) * k;
    view.zoom = zoom;
    if (zoom <= 1.0f) view.center = glm::vec2(0.5f);
}

}  // namespace dw::ui
