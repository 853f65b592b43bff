// deferred-workbench list scenes|buffers|knobs|passes|presets: needs no GL context.
#include <cstdio>
#include <iostream>

#include "app/CommandLine.h"
#include "app/Commands.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/Pipeline.h"
#include "renderer/knobs/Preset.h"
#include "renderer/scene/BuiltinScenes.h"

namespace dw {

int runListCommand(int argc, char** argv) {
    CommandLine cl(argc, argv, 2);
    if (cl.flag("--help")) {
        std::cout << "usage: deferred-workbench list scenes|buffers|knobs|passes|presets\n"
                     "  scenes   the built-in scenes\n"
                     "  buffers  every named output: kind, the pass that writes it, what it holds\n"
                     "  knobs    every knob: default, range, unit, what it does\n"
                     "  passes   the passes in order, with what each reads and writes\n"
                     "  presets  the built-in presets and their knob values\n";
        return 0;
    }
    cl.finish("list");
    const auto words = cl.positional();
    const std::string what = words.empty() ? "" : words[0];
    KnobRegistry knobs;
    Pipeline pipeline(knobs);
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
            std::printf("%s  [%s]\n", p.name.c_str(), toString(p.stage));
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
