#pragma once
// File > Save record... and Open record... (Ctrl+S, Ctrl+R): a path in a
// small modal window. Saving measures the state on show (RecordMeasurement:
// warm-up and counted frames, bench's 1 and 10 unless changed in the window,
// rendered in the background with a progress bar and *cancel* in the menu
// bar) and then writes its experiment record (renderer/record/
// ExperimentRecord, command "gui": the scene and its files' sha256, camera,
// every knob, the viewport's output and its pixels' sha256, each timing
// series with its median and 95% interval, build, GL, CPU);
// `deferred-workbench replay` measures it again headless. Opening restores a
// record's scene, camera and knobs as a preset is applied; a bad record (not
// JSON, a newer version, another format, a scene that does not load) is an
// error message and nothing changes.
#include <string>

#include "renderer/RenderSession.h"
#include "ui/UiState.h"

namespace dw::ui {

// Both log what they did (or why not) and return whether it worked;
// saveRecord whether the measurement started (state.recordRun writes the file).
bool saveRecord(UiState& state, RenderSession& session, const std::string& path,
                int frames = RecordMeasurement::kDefaultFrames, int warmup = RecordMeasurement::kDefaultWarmup);
bool openRecord(UiState& state, RenderSession& session, const std::string& path);

class RecordDialog {
public:
    enum class Mode { Closed, Save, Open };
    void request(Mode mode) { requested_ = mode; }
    // The shortcuts, the modal and its action; call once per frame, after the panels.
    void draw(UiState& state, RenderSession& session);
    // The measurement's progress and *cancel*, in the menu bar while it runs.
    static void progressBar(UiState& state, RenderSession& session);

private:
    Mode requested_ = Mode::Closed;
    Mode mode_ = Mode::Closed;
    std::string path_;
    int frames_ = RecordMeasurement::kDefaultFrames, warmup_ = RecordMeasurement::kDefaultWarmup;
};

}  // namespace dw::ui
