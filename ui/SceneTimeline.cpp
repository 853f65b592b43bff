#include "ui/SceneTimeline.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "renderer/RenderSession.h"

namespace dw::ui {

void SceneTimeline::reset() {
    playing = false;
    time = 0.0;
    haveLast_ = false;
}

bool SceneTimeline::advance(RenderSession& session) {
    const SceneAnimation& anim = session.scene().animation;
    const auto now = std::chrono::steady_clock::now();
    if (playing && haveLast_) {
        time += std::chrono::duration<double>(now - last_).count() * speed;
        const double end = anim.duration();
        if (end <= 0.0) {
            time = 0.0;
        } else if (time > end) {
            if (loop) time = std::fmod(time, end);
            else {
                time = end;
                playing = false;
            }
        }
    }
    last_ = now;
    haveLast_ = playing;
    const bool moved = anim.posedAt != time;
    session.setSceneTime(time);
    session.poseAtSceneTime();
    return moved && !anim.empty();
}

namespace {

// Which clip plays for file `f` ("none" or one of its clips).
void clipChoice(SceneAnimation& anim, std::size_t f) {
    int& playing = anim.playing[f];
    const std::string shown = playing >= 0 ? anim.clips[static_cast<std::size_t>(playing)].name : std::string("none");
    const std::string label = "animation##file" + std::to_string(f);
    if (!ImGui::BeginCombo(label.c_str(), shown.c_str())) return;
    if (ImGui::Selectable("none", playing < 0)) playing = -1;
    for (std::size_t c = 0; c < anim.clips.size(); ++c) {
        if (anim.clips[c].file != static_cast<int>(f)) continue;
        const std::string item = anim.clips[c].name + "##" + std::to_string(c);
        if (ImGui::Selectable(item.c_str(), playing == static_cast<int>(c))) playing = static_cast<int>(c);
    }
    ImGui::EndCombo();
}

}  // namespace

void SceneTimeline::draw(RenderSession& session) {
    SceneAnimation& anim = session.mutableScene().animation;
    if (anim.empty() || !ImGui::CollapsingHeader("animation", ImGuiTreeNodeFlags_DefaultOpen)) return;
    for (std::size_t f = 0; f < anim.files.size() && f < anim.playing.size(); ++f) {
        const std::vector<int> before = anim.playing;
        clipChoice(anim, f);
        if (anim.playing != before) anim.posedAt = -1.0;  // another clip: pose again
    }
    if (ImGui::Button(playing ? "pause" : "play")) {
        playing = !playing;
        haveLast_ = false;
    }
    ImGui::SameLine();
    ImGui::Checkbox("loop", &loop);
    const float end = static_cast<float>(std::max(anim.duration(), 1e-3));
    float t = static_cast<float>(time);
    if (ImGui::SliderFloat("time (s)", &t, 0.0f, end, "%.3f")) time = t;
    ImGui::DragFloat("speed", &speed, 0.01f, 0.0f, 10.0f, "%.2fx");
    ImGui::TextDisabled("%zu clip(s), %zu skin(s), %zu deformed mesh(es); --scene-time %.3f", anim.clips.size(),
                        anim.skins.size(), anim.deformers.size(), time);
}

}  // namespace dw::ui
