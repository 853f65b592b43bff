// deferred-workbench [gui]: the workbench window.
#include <filesystem>
#include <iostream>

#include "app/CommandLine.h"
#include "app/Commands.h"
#include "app/GuiApp.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/Pipeline.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

int runGuiCommand(int argc, char** argv) {
    const int first = argc > 1 && std::string(argv[1]) == "gui" ? 2 : 1;
    CommandLine cl(argc, argv, first);
    if (cl.flag("--help")) {
        std::cout << "usage: deferred-workbench [gui] [--scene NAME|FILE] [--preset NAME|FILE] [--presets DIR]\n"
                     "                          [--set knob=value]... [--size WxH]\n"
                     "                          [--frames N [--screenshot out.png]]\n"
                     "  --presets    folder of preset files (default ~/.config/deferred-workbench/presets)\n"
                     "  --frames     quit after N frames (for scripts and tests)\n"
                     "  --screenshot with --frames: save the window to a PNG after the last frame\n";
        return 0;
    }
    GuiOptions o;
    o.scene = cl.value("--scene").value_or("default");
    o.preset = cl.value("--preset").value_or("");
    o.presetsDir = cl.value("--presets").value_or("");
    o.sets = cl.values("--set");
    if (auto s = cl.value("--size")) std::tie(o.width, o.height) = CommandLine::parseSize(*s);
    o.frames = CommandLine::parseInt("--frames", cl.value("--frames").value_or("0"), 0, 1000000);
    o.screenshot = cl.value("--screenshot").value_or("");
    cl.finish("gui");
    if (!cl.positional().empty()) throw UsageError("gui: unexpected argument '" + cl.positional()[0] + "'");
    if (!o.screenshot.empty() && o.frames == 0) throw UsageError("--screenshot needs --frames N");
#ifdef DW_SCENES_DIR
    if (std::filesystem::is_directory(DW_SCENES_DIR)) o.scenesDir = DW_SCENES_DIR;
#endif
    // Bad input is reported before a window opens.
    {
        KnobRegistry knobs;
        Pipeline declarations(knobs);
        for (const auto& s : o.sets) knobs.applyAssignment(s);
    }
    Scene scene = loadScene(o.scene);
    return runGui(o, std::move(scene));
}

}  // namespace dw
