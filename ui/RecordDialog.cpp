#include "ui/RecordDialog.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <filesystem>

#include "renderer/record/ExperimentRecord.h"
#include "ui/ScenePanel.h"

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

bool saveRecord(UiState& state, RenderSession& session, const std::string& path) {
    std::error_code ec;
    const std::string shown = fs::absolute(path, ec).string();
    try {
        // The output the viewport shows, as the last frame rendered it; a
        // preview mode (textured, wireframe) is no pipeline output: final then.
        std::string buffer = state.viewport.mode == DisplayMode::Deferred ? state.viewport.output : "final";
        if (buffer.empty() || !session.pipeline().outputs().find(buffer)) buffer = "final";
        if (!session.pipeline().outputs().find(buffer))
            throw Error("no frame rendered yet: nothing to record");
        RunConfig run = state.run;
        run.width = session.pipeline().width();
        run.height = session.pipeline().height();
        run.frames = 1;
        run.warmup = 0;
        ExperimentRecord r = ExperimentRecord::capture(session, run, buffer, state.report.frameIndex, "window");
        r.command = "gui";
        r.sceneSpec = session.scene().source;  // what is open now, not what the window started with
        r.write(path);
        state.log.done("saved record " + shown + " (deferred-workbench replay measures it again)", state.time,
                       "save record");
        return true;
    } catch (const std::exception& e) {
        state.log.error(std::string("cannot save record: ") + e.what(), state.time, "save record");
        return false;
    }
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
        if (!openScene(state, session, r.sceneSpec)) return false;
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
    ImGui::TextUnformatted(mode_ == Mode::Save ? "Save the experiment record of this frame to:"
                                               : "Open the experiment record (scene, camera, knobs) from:");
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(520.0f);
    const bool enter = ImGui::InputText("##record path", path_.data(), path_.capacity() + 1,
                                        ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CallbackResize,
                                        growString, &path_);
    const bool go = ImGui::Button(mode_ == Mode::Save ? "Save" : "Open") || enter;
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    if (go) {
        if (mode_ == Mode::Save) saveRecord(state, session, path_);
        else openRecord(state, session, path_);
    }
    if (go || cancel) {
        mode_ = Mode::Closed;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace dw::ui
