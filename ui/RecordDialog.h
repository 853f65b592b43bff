#pragma once
// File > Save record... and Open record... (Ctrl+S, Ctrl+R): a path in a
// small modal window. Saving writes the experiment record of the last frame
// (renderer/record/ExperimentRecord, command "gui": the scene and its files'
// sha256, camera, every knob, the viewport's output and its pixels' sha256,
// the last frame's timings, build, GL, CPU); `deferred-workbench replay`
// measures it again headless. Opening restores a record's scene, camera and
// knobs as a preset is applied; a bad record is an error message and nothing
// changes.
#include <string>

#include "renderer/RenderSession.h"
#include "ui/UiState.h"

namespace dw::ui {

// Both log what they did (or why not) and return whether it worked.
bool saveRecord(UiState& state, RenderSession& session, const std::string& path);
bool openRecord(UiState& state, RenderSession& session, const std::string& path);

class RecordDialog {
public:
    enum class Mode { Closed, Save, Open };
    void request(Mode mode) { requested_ = mode; }
    // The shortcuts, the modal and its action; call once per frame, after the panels.
    void draw(UiState& state, RenderSession& session);

private:
    Mode requested_ = Mode::Closed;
    Mode mode_ = Mode::Closed;
    std::string path_;
};

}  // namespace dw::ui
