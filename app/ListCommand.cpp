// deferred-workbench list scenes|buffers|knobs|passes|presets: needs no GL context.
#include <cstdio>
#include <iostream>
#include <optional>
#include <tuple>

#include "app/Commands.h"
#include "headless/CommandLine.h"
#include "headless/HeadlessGlContext.h"
#include "renderer/RenderSession.h"
#include "renderer/bench/SceneStatistics.h"
#include "renderer/graph/Pipeline.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/knobs/Preset.h"
#include "renderer/scene/BuiltinScenes.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

namespace {

// list scenes --stats: seed 000 table 6.1's columns for every built-in scene
// and the --scene given (a glTF, a scene JSON), LPP rendered at `size` over
// the walk-through (SceneStatistics).
void printSceneStatistics(RunConfig run, std::pair<int, int> size, int poses) {
    std::vector<std::string> specs;
    for (const auto& s : builtinScenes()) specs.push_back(s.name);
    if (!run.scene.empty() && !isBuiltinScene(run.scene)) specs.push_back(run.scene);
    auto context = HeadlessGlContext::create();
    RenderSession session;
    session.resize(size.first, size.second);
    std::printf("scene statistics (seed 000 table 6.1), LPP at %dx%d over %d pose(s) of the camera path or orbit "
                "on %s\n",
                size.first, size.second, poses, context->platform().c_str());
    std::printf("| scene | objects | triangles | lights | directional / point / spot | LPP | LPP range over poses | LPP lit |\n"
                "| --- | ---: | ---: | ---: | --- | ---: | --- | ---: |\n");
    for (const std::string& spec : specs) {
        run.scene = spec;
        session.loadScene(spec, run);
        for (const auto& w : session.scene().warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
        SceneStatistics st = countScene(session.scene());
        measureLightsPerPixel(session, poses, st);
        std::printf("| %s | %zu | %zu | %d | %d / %d / %d | %.3f | [%.3f, %.3f] | %.3f |\n", spec.c_str(), st.objects,
                    st.triangles, st.lights, st.directional, st.point, st.spot, st.lpp, st.lppMin, st.lppMax, st.lppLit);
        std::fflush(stdout);
    }
}

}  // namespace

int runListCommand(int argc, char** argv) {
    CommandLine cl(argc, argv, 2, "list");
    if (cl.flag("--help")) {
        std::cout << "usage: deferred-workbench list scenes|buffers|knobs|passes|presets\n"
                     "       deferred-workbench list passes --scene S [--preset P] [--set k=v]... [--size WxH]\n"
                     "       deferred-workbench list scenes --stats [--scene FILE] [--preset P] [--set k=v]... [--size WxH]\n"
                     "                                      [--poses N]\n"
                     "  scenes   the built-in scenes; --stats: seed 000 table 6.1 for each (and FILE): objects,\n"
                     "           triangles, lights, lights per pixel over the camera path or N orbit poses\n"
                     "           (default 8) rendered at --size (default 640x360); needs OpenGL\n"
                     "  buffers  every named output: kind, the pass that writes it, what it holds\n"
                     "  knobs    every knob: default, range, unit, what it does\n"
                     "  passes   the passes in order, with what each reads and writes; with --scene, also\n"
                     "           which would be skipped for that scene and its camera, and why\n"
                     "  presets  the built-in presets and their knob values\n"
                  << CommandLine::rangesHelp("list");
        return 0;
    }
    RunConfig run = cl.runConfig();
    const auto size = cl.size();
    const bool stats = cl.flag("--stats");
    const auto poses = cl.whole("--poses");
    cl.finish("list");
    const auto words = cl.positional();
    const std::string what = words.empty() ? "" : words[0];
    const bool withScene = !run.scene.empty() || run.preset();
    if (stats && what != "scenes") throw UsageError("list: --stats applies to 'list scenes' only");
    if (poses && !stats) throw UsageError("list: --poses applies to 'list scenes --stats' only");

    if ((withScene || size) && what != "passes" && !stats)
        throw UsageError("list: --scene, --preset, --set and --size apply to 'list passes' and 'list scenes --stats' only");
    KnobRegistry knobs;
    if (stats) {
        run.validate(knobs);
        printSceneStatistics(run, size.value_or(std::pair{640, 360}), poses.value_or(8));
        return 0;
    }
    Pipeline pipeline(knobs);
    // list passes --scene: the scene's knobs (settings, preset, --set) and its camera decide the skips.
    std::optional<Scene> scene;
    if (withScene) {
        run.validate(knobs);
        scene = loadScene(run.sceneSpec());
        run.applyKnobs(knobs, *scene);
        std::tie(run.width, run.height) = size.value_or(std::pair{1280, 720});
    }
    if (what == "scenes") {
        for (const auto& s : builtinScenes()) std::printf("%-10s %s\n", s.name.c_str(), s.description.c_str());
    } else if (what == "buffers") {
        for (const auto& o : pipeline.outputs().all())
            std::printf("%-24s %-10s %-14s %s\n", o.decl.name.c_str(), toString(o.decl.kind), o.pass.c_str(),
                        o.decl.description.c_str());
    } else if (what == "knobs") {
        for (size_t i = 0; i < knobs.size(); ++i) {
            const KnobSpec& s = knobs.spec(static_cast<int>(i));
            const std::string def = knobs.format(static_cast<int>(i));
            std::printf("%-28s %-10s %-32s %s%s%s\n", s.name.c_str(), def.c_str(), knobs.formatRange(static_cast<int>(i)).c_str(),
                        s.unit.empty() ? "" : ("[" + s.unit + "] ").c_str(), s.tradeoff ? "(speed/quality) " : "",
                        s.description.c_str());
        }
    } else if (what == "passes") {
        // In pipeline order under the default knobs; the post chain's image resolved.
        for (const PassInfo& p : pipeline.passList()) {
            std::string skipped;
            if (scene) {
                const RenderPass* pass = pipeline.findPass(p.name);
                skipped = pass->skipReason(knobs, *scene);
                if (skipped.empty())
                    skipped = pass->viewSkipReason(knobs, *scene,
                                                   Pipeline::cameraUniforms(run.camera(*scene), run.width, run.height));
            }
            std::printf("%s  [%s]%s\n", p.name.c_str(), toString(p.stage),
                        skipped.empty() ? "" : ("  (skipped: " + skipped + ")").c_str());
            for (const auto& in : p.reads) std::printf("  reads    %s\n", in.c_str());
            for (const auto& in : p.optionalReads) std::printf("  reads    %s (when produced)\n", in.c_str());
            for (const auto& in : p.modifies) std::printf("  modifies %s\n", in.c_str());
            for (const auto& o : p.writes)
                std::printf("  writes   %s%s%s\n", o.name.c_str(), o.resource.managed() ? "" : " (pass-owned)",
                            o.onDemand ? " (on demand)" : "");
        }
    } else if (what == "presets") {
        for (const auto& p : builtinPresets()) {
            std::printf("%-14s %s\n", p.name.c_str(), p.description.c_str());
            std::string line;
            for (const auto& [k, v] : p.knobs) line += (line.empty() ? "" : " ") + k + "=" + v;
            std::printf("%-14s %s\n", "", line.c_str());
        }
    } else {
        throw UsageError("usage: deferred-workbench list scenes|buffers|knobs|passes|presets");
    }
    return 0;
}

}  // namespace dw
