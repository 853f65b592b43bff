// deferred-workbench [gui]: the workbench window.
#include <filesystem>
#include <iostream>
#include <tuple>

#include "app/Commands.h"
#include "app/GuiApp.h"
#include "app/RenderDocCapture.h"
#include "headless/CommandLine.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

int runGuiCommand(int argc, char** argv) {
    const int first = argc > 1 && std::string(argv[1]) == "gui" ? 2 : 1;
    CommandLine cl(argc, argv, first, "gui");
    if (cl.flag("--help")) {
        std::cout << "usage: deferred-workbench [gui] [--scene NAME|FILE] [--preset NAME|FILE]... [--presets DIR]\n"
                     "                          [--set knob=value]... [--size WxH]\n"
                     "                          [--frames N [--screenshot out.png] [--events FILE]] [--layout-out FILE]\n"
                     "                          [--layout FILE]\n"
                     "                          [--view OUTPUT] [--resolution full|1/2|1/4|auto] [--record] [--renderdoc]\n"
                     "                          [--open-record FILE] [--save-record FILE]\n"
                     "                          [--dump-knobs FILE] [--export-dir DIR]\n"
                     "                          [--ab pinned|reference|preset=NAME [--ab-display split|difference|flip]]\n"
                     "  --scene, --preset, --set, --size as in render: --scene wins over the preset's scene;\n"
                     "               knobs start at defaults, then the scene's settings, the preset, --set\n"
                     "               (again whenever another scene is opened in the window)\n"
                     "  --presets    folder of preset files (default ~/.config/deferred-workbench/presets)\n"
                     "  --frames     quit after N frames (for scripts and tests)\n"
                     "  --screenshot with --frames: save the window to a PNG after the last frame\n"
                     "  --events     with --frames: replay input, one action a line: '<frame> move X Y', 'click X Y',\n"
                     "               'drag X0 Y0 X1 Y1 [N]', 'wheel D', 'key [ctrl+]NAME', 'type TEXT', 'drop PATH',\n"
                     "               'resize W H', 'ctrl down|up' (window pixels), 'set knob=value'\n"
                     "  --layout-out after the last frame (with --frames) or when the window closes, write each\n"
                     "               open panel's rectangle, the window size, the probe, the scene and errors as JSON\n"
                     "  --layout     start from this layout.json instead of the saved one (also with --frames;\n"
                     "               a file that cannot be used is reported and the default layout shown)\n"
                     "  --dump-knobs at exit, write every knob's value as name=value lines (as render does)\n"
                     "  --open-record restore an experiment record at start (scene, camera, knobs), as File > Open\n"
                     "               record... does; one that cannot be opened is a message in the window\n"
                     "  --save-record at exit, measure the window's last state (1 warm-up, 10 counted frames) and\n"
                     "               write its experiment record, as File > Save record... does\n"
                     "               (`deferred-workbench replay FILE` measures it again)\n"
                     "  --view NAME  the output the viewport shows at start (see list buffers)\n"
                     "  --resolution full|1/2|1/4|auto  render resolution against the viewport panel\n"
                     "               (auto: steps to keep the GPU frame under 100 ms). Default: full, but on a\n"
                     "               CPU rasteriser (llvmpipe) without --frames auto from 1/4 with a 150 ms target\n"
                     "  --record     time every frame from the start (otherwise a frame is rendered only\n"
                     "               when something it shows changed)\n"
                     "  --renderdoc  run under RenderDoc (starts again with librenderdoc.so preloaded,\n"
                     "               Debian package librenderdoc): Render > Capture frame or F11 saves a\n"
                     "               capture of the next frame to the export folder\n"
                     "  --ab         start with the viewport's A/B split on, B from: pinned (Pin or p takes the image),\n"
                     "               reference (the CPU reference, F9), or preset=NAME (a built-in preset or a preset\n"
                     "               file over the current settings); with --layout-out the report holds its numbers\n"
                     "               and the two images are written beside it (FILE.a.png, FILE.b.png)\n"
                     "  --ab-display what B's side shows: split (B itself, the default), difference (|A-B| heat map)\n"
                     "               or flip (FLIP heat map)\n"
                     "  --export-dir where screenshots and timing CSVs go\n"
                     "               (default ~/.local/share/deferred-workbench/exports)\n"
                     "The panel layout and which panels are open are saved at exit in\n"
                     "~/.config/deferred-workbench/layout.json (not in scripted runs).\n"
                  << CommandLine::rangesHelp("gui");
        return 0;
    }
    GuiOptions o;
    o.run = cl.runConfig();
    o.run.width = 1600;
    o.run.height = 900;
    if (auto s = cl.size()) std::tie(o.run.width, o.run.height) = *s;
    o.run.frames = cl.whole("--frames", 0);
    o.presetsDir = cl.value("--presets").value_or("");
    o.screenshot = cl.value("--screenshot").value_or("");
    o.dumpKnobs = cl.value("--dump-knobs").value_or("");
    o.events = cl.value("--events").value_or("");
    o.layoutIn = cl.value("--layout").value_or("");
    o.layoutOut = cl.value("--layout-out").value_or("");
    o.exportDir = cl.value("--export-dir").value_or("");
    o.view = cl.value("--view").value_or("");
    o.resolution = cl.value("--resolution").value_or("");
    if (!o.resolution.empty() && o.resolution != "full" && o.resolution != "1/2" && o.resolution != "1/4" && o.resolution != "auto")
        throw UsageError("--resolution takes full, 1/2, 1/4 or auto, not '" + o.resolution + "'");
    o.ab = cl.value("--ab").value_or("");
    if (!o.ab.empty() && o.ab != "pinned" && o.ab != "reference" && (o.ab.rfind("preset=", 0) != 0 || o.ab.size() == 7))
        throw UsageError("--ab takes pinned, reference or preset=NAME, not '" + o.ab + "'");
    o.abDisplay = cl.value("--ab-display").value_or("");
    if (!o.abDisplay.empty() && o.abDisplay != "split" && o.abDisplay != "difference" && o.abDisplay != "flip")
        throw UsageError("--ab-display takes split, difference or flip, not '" + o.abDisplay + "'");
    if (!o.abDisplay.empty() && o.ab.empty()) throw UsageError("--ab-display needs --ab");
    o.record = cl.flag("--record");
    o.openRecord = cl.value("--open-record").value_or("");
    o.saveRecord = cl.value("--save-record").value_or("");
    o.renderdoc = cl.flag("--renderdoc");
    cl.finish("gui");
    if (!cl.positional().empty()) throw UsageError("gui: unexpected argument '" + cl.positional()[0] + "'");
    if (!o.screenshot.empty() && o.run.frames == 0) throw UsageError("--screenshot needs --frames N");
    if (!o.events.empty() && o.run.frames == 0) throw UsageError("--events needs --frames N");
    // No file the window writes may replace another, its scene, preset or events.
    CommandLine::NamedFiles writes, reads = CommandLine::inputFiles(o.run);
    if (!o.screenshot.empty()) writes.emplace_back("--screenshot", o.screenshot);
    if (!o.layoutOut.empty()) writes.emplace_back("--layout-out", o.layoutOut);
    if (!o.dumpKnobs.empty()) writes.emplace_back("--dump-knobs", o.dumpKnobs);
    if (!o.saveRecord.empty()) writes.emplace_back("--save-record", o.saveRecord);
    if (!o.openRecord.empty()) reads.emplace_back("--open-record", o.openRecord);
    if (!o.events.empty()) reads.emplace_back("--events", o.events);
    if (!o.layoutIn.empty()) reads.emplace_back("--layout", o.layoutIn);
    CommandLine::requireDistinctFiles(writes, reads);
    // Every file the window writes at the end is checked before the first
    // frame, as render does: a --save-record into a missing folder failed
    // after the measured frames.
    for (const auto& [what, path] : writes) CommandLine::requireWritable(path, what + " file");
#ifdef DW_SCENES_DIR
    if (std::filesystem::is_directory(DW_SCENES_DIR)) o.scenesDir = DW_SCENES_DIR;
#endif
    if (o.renderdoc) {
        // RenderDoc has to hook GL from the start: this process starts again under it.
        if (const std::string why = RenderDocCapture::relaunchUnderRenderDoc(argv); !why.empty()) throw Error("--renderdoc: " + why);
    }
    // Bad input is reported before a window opens, as render reports it.
    o.run.validate();
    Scene scene = loadScene(o.run.sceneSpec());
    return runGui(o, std::move(scene));
}

}  // namespace dw
