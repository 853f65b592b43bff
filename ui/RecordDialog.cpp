#include "ui/RecordDialog.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "renderer/OptionLimits.h"
#include "renderer/metrics/Bootstrap.h"
#include "renderer/record/ExperimentRecord.h"
#include "ui/ScenePanel.h"
#include "ui/Widgets.h"

namespace dw::ui {

namespace fs = std::filesystem;

namespace {

constexpr const char* kPopup = "Experiment record";

bool pressedCtrl(const UiState& state, int key) {
    constexpr int kCommand = GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER;
    for (const auto& [k, m] : state.keyPresses)
        if (k == key && (m & kCommand) == GLFW_MOD_CONTROL) return true;
    return false;
}

// ImGui's InputText over a std::string (imgui_stdlib is not in Debian's libimgui-dev).
int growString(ImGuiInputTextCallbackData* data) {
    if (data->EventFlag == ImGuiInputTextFlags_CallbackResize) {
        auto* s = static_cast<std::string*>(data->UserData);
        s->resize(static_cast<size_t>(data->BufTextLen));
        data->Buf = s->data();
    }
    return 0;
}

}  // namespace

bool saveRecord(UiState& state, RenderSession& session, const std::string& path, int frames, int warmup) {
    return state.recordRun.start(state, session, path, frames, warmup);
}

bool openRecord(UiState& state, RenderSession& session, const std::string& path) {
    ExperimentRecord r;
    KnobRegistry knobs = session.knobs();
    std::vector<std::string> skipped;
    try {
        r = ExperimentRecord::read(path);
        // Every value checked before anything changes: a record this build
        // cannot take in part is reported, the rest applied.
        for (const auto& [recordedName, value] : r.knobs) {
            const std::string name = knobs.canonicalName(recordedName);  // an old name: the knob it became
            if (!knobs.find(name)) {
                skipped.push_back(name + " (not in this build)");
                continue;
            }
            try {
                knobs.setFromString(name, value);
            } catch (const Error& e) {
                skipped.push_back(e.what());
            }
        }
    } catch (const std::exception& e) {
        state.log.error(std::string("cannot open record: ") + e.what(), state.time, "open record");
        return false;
    }
    if (!RunConfig::namesScene(r.sceneSpec, session.scene())) {
        if (!openScene(state, session, r.sceneSpec)) {
            // openScene said why; the record's own message names the record too.
            const std::string why = state.log.banner() ? state.log.banner()->text : "cannot open scene " + r.sceneSpec;
            state.log.error("cannot open record " + path + ": " + why + "; nothing changed", state.time, "open record");
            return false;
        }
        // The knobs checked above were the old scene's; the record sets every one of them anyway.
        KnobRegistry fresh = session.knobs();
        for (const auto& [name, value] : r.knobs)
            if (fresh.find(fresh.canonicalName(name))) try {
                    fresh.setFromString(name, value);
                } catch (const Error&) {
                }
        knobs = fresh;
    }
    session.knobs() = knobs;
    session.camera() = r.camera;
    if (session.pipeline().outputs().find(r.buffer)) state.viewport.show(r.buffer);
    state.log.info("record " + path + ": scene " + session.scene().name + ", camera and " +
                       std::to_string(r.knobs.size() - skipped.size()) + " knobs restored",
                   state.time);
    if (!skipped.empty()) {
        std::string all = "record " + path + ": " + std::to_string(skipped.size()) + " knob(s) not restored:";
        for (const auto& s : skipped) all += "\n  " + s;
        state.log.error(all, state.time, "open record");
    } else {
        state.log.succeeded("open record");
    }
    return true;
}

void RecordDialog::draw(UiState& state, RenderSession& session) {
    if (pressedCtrl(state, GLFW_KEY_S)) requested_ = Mode::Save;
    if (pressedCtrl(state, GLFW_KEY_R)) requested_ = Mode::Open;
    if (requested_ != Mode::Closed) {
        mode_ = requested_;
        requested_ = Mode::Closed;
        if (path_.empty()) path_ = state.exportDir + "/record.json";
        ImGui::OpenPopup(kPopup);
    }
    if (!ImGui::BeginPopupModal(kPopup, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::TextUnformatted(mode_ == Mode::Save ? "Measure this view and save its experiment record to:"
                                               : "Open the experiment record (scene, camera, knobs) from:");
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(520.0f);
    const bool enter = ImGui::InputText("##record path", path_.data(), path_.capacity() + 1,
                                        ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CallbackResize,
                                        growString, &path_);
    if (mode_ == Mode::Save) {
        // The frames replay times again; bench's defaults give each timing an interval (6 frames at least).
        ImGui::SetNextItemWidth(110.0f);
        ImGui::InputInt("counted frames", &frames_);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(110.0f);
        ImGui::InputInt("warm-up", &warmup_);
        frames_ = std::clamp(frames_, limits::kFrames.min, limits::kFrames.max);
        warmup_ = std::clamp(warmup_, limits::kWarmup.min, limits::kWarmup.max);
        if (frames_ < static_cast<int>(kMinIntervalSamples))
            ImGui::TextColored(kErrorColor, "under %d counted frames the timings get no interval", static_cast<int>(kMinIntervalSamples));
        if (state.recordRun.running()) ImGui::TextColored(kErrorColor, "a record is being measured: cancel it first");
    }
    const bool go = ImGui::Button(mode_ == Mode::Save ? "Save" : "Open") || enter;
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    if (go) {
        if (mode_ == Mode::Save) saveRecord(state, session, path_, frames_, warmup_);
        else openRecord(state, session, path_);
    }
    if (go || cancel) {
        mode_ = Mode::Closed;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void RecordDialog::progressBar(UiState& state, RenderSession& session) {
    RecordMeasurement& m = state.recordRun;
    if (!m.running()) return;
    char text[96];
    std::snprintf(text, sizeof text, "record %d/%d frames", m.rendered(), m.total());
    ImGui::ProgressBar(static_cast<float>(m.progress()), ImVec2(170, 0), text);
    noteItem("record.progress");
    if (ImGui::IsItemHovered()) tooltip("measuring %s (File > Save record...)", m.path().c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("cancel##record")) m.cancel(state, session);
    noteItem("record.cancel");
}

}  // namespace dw::ui
