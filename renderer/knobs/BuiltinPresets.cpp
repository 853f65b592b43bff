// The presets that ship with the workbench, in knob values: the quality
// levels of seed 002 section 7, the SSAO settings of seed 000 table 6.4,
// GTAO at XeGTAO's quality levels, and light-volume thresholds. Render size is not a knob (it follows the window,
// or render --size), so the seed's resolutions are only named in descriptions, which say a preset cannot set them.
// The quality levels cover every knob group (what they do not name goes back
// to its default); the light-volume presets cover only "lighting", so they
// can be combined with a quality level.
#include "renderer/knobs/Preset.h"

namespace dw {

const std::vector<Preset>& builtinPresets() {
    static const std::vector<Preset> presets = [] {
        std::vector<Preset> v;
        auto add = [&](std::string name, std::string description, std::vector<std::pair<std::string, std::string>> knobs,
                       std::vector<std::string> groups = {}) {
            Preset p;
            p.name = std::move(name);
            p.description = std::move(description);
            p.knobs = std::move(knobs);
            p.groups = std::move(groups);
            v.push_back(std::move(p));
        };
        // Seed 002 section 7: SSAO, the stencil-routed A-buffer's samples (4 / 8 / 8;
        // oit.samples is capped by the device, 4 on llvmpipe, and the oit
        // pass's statistics say so) and the sun's shadow map. The seed's
        // resolutions are render sizes, which no preset sets (--size, the
        // window): the descriptions say so.
        // Quality levels, not AO methods: they leave ao.method as it is, so a
        // GTAO or AOV level combines with them either way round.
        const std::string size = " (render size, not set by a preset: --size or the window)";
        add("Low", "seed 002: 800x600" + size + ", SSAO at 1/16 size with 16 samples and a 21-wide bilateral blur, the "
                   "stencil-routed A-buffer with 4 samples, one 512^2 sun shadow map",
            {{"ao.enabled", "true"}, {"ssao.resolution", "quarter"}, {"ssao.samples", "16"}, {"ssao_blur.mode", "bilateral"},
             {"ssao_blur.width", "21"}, {"oit.method", "abuffer"}, {"oit.samples", "4"}, {"shadows.map_size", "512"}});
        add("Medium", "seed 002: 1280x720" + size + ", SSAO at 1/4 size with 16 samples and a 61-wide bilateral blur, the "
                      "stencil-routed A-buffer with 8 samples, a 1024^2 shadow map",
            {{"ao.enabled", "true"}, {"ssao.resolution", "half"}, {"ssao.samples", "16"}, {"ssao_blur.mode", "bilateral"},
             {"ssao_blur.width", "61"}, {"oit.method", "abuffer"}, {"oit.samples", "8"}, {"shadows.map_size", "1024"}});
        add("High", "seed 002: 1920x1080" + size + ", full-size SSAO with 16 samples and a 61-wide bilateral blur, the "
                    "stencil-routed A-buffer with 8 samples, a 2048^2 shadow map",
            {{"ao.enabled", "true"}, {"ssao.resolution", "full"}, {"ssao.samples", "16"}, {"ssao_blur.mode", "bilateral"},
             {"ssao_blur.width", "61"}, {"oit.method", "abuffer"}, {"oit.samples", "8"}, {"shadows.map_size", "2048"}});
        // Seed 000 table 6.4: occlusion buffer, samples, radius, blur width. Named
        // for SSAO, they render SSAO whatever the scene or an earlier preset chose.
        const char* ssao[5][4] = {{"quarter", "8", "1", "10"}, {"quarter", "16", "1", "15"}, {"half", "16", "1", "20"},
                                  {"half", "32", "1", "20"}, {"full", "32", "1", "30"}};
        for (int i = 0; i < 5; ++i)
            add("SSAO" + std::to_string(i + 1),
                std::string("seed 000 table 6.4: ") + ssao[i][0] + " resolution, " + ssao[i][1] + " samples, radius " +
                    ssao[i][2] + ", blur width " + ssao[i][3],
                {{"ao.enabled", "true"}, {"ao.method", "ssao"}, {"ssao.resolution", ssao[i][0]}, {"ssao.samples", ssao[i][1]},
                 {"ssao.radius", ssao[i][2]}, {"ssao.radius_unit", "world"}, {"ssao_blur.mode", "bilateral"},
                 {"ssao_blur.width", ssao[i][3]}});
        // GTAO at XeGTAO's quality levels (slices x steps per side: low 1 x 2,
        // medium 2 x 2, high 3 x 3, ultra 9 x 3), full size. They cover only
        // the ao and gtao groups, so they combine with a quality level.
        const char* gtao[4][3] = {{"low", "1", "2"}, {"medium", "2", "2"}, {"high", "3", "3"}, {"ultra", "9", "3"}};
        for (const auto& g : gtao)
            add(std::string("GTAO ") + g[0],
                std::string("GTAO at XeGTAO's ") + g[0] + " level: " + g[1] + " slices x " + g[2] +
                    " steps per side, full size, the shared bilateral blur",
                {{"ao.enabled", "true"}, {"ao.method", "gtao"}, {"gtao.slices", g[1]}, {"gtao.steps", g[2]},
                 {"gtao.resolution", "full"}, {"gtao.denoise", "shared"}},
                {"ao", "gtao"});
        // Seed 000 table 6.5: Ambient Occlusion Volumes, radius 1, falloff 1, at w x h, w/2, w/4.
        // Like the GTAO levels they cover only the ao and aov groups.
        const char* aov[3] = {"full", "half", "quarter"};
        for (int i = 0; i < 3; ++i)
            add("AOV" + std::to_string(i + 1),
                std::string("seed 000 table 6.5: Ambient Occlusion Volumes, radius 1, falloff 1, ") + aov[i] +
                    " resolution",
                {{"ao.enabled", "true"}, {"ao.method", "aov"}, {"aov.radius", "1"}, {"aov.radius_unit", "world"}, {"aov.falloff", "1"},
                 {"aov.resolution", aov[i]}},
                {"ao", "aov"});
        // Seed 000 section 6.5, the whole system ("overall performance"): SSAO3
        // (half size, 16 samples, radius 1, blur 20), the stencil-routed A-buffer at
        // 8 samples, Reinhard, a 2048^2 shadow map for the sun, on the built-in
        // atrium (several hundred objects, transparent ones among them). The seed's
        // 1280x720 and its 20 / 25 point lights are a render size and generated
        // lights, which no preset sets: bench --size 1280x720 --lights 25
        // --keep-scene-lights (docs/bench.md).
        add("Overall",
            "seed 000 section 6.5: 1280x720" + size + ", SSAO3 (half size, 16 samples, radius 1, blur width 20), "
            "the stencil-routed A-buffer with 8 samples, Reinhard, a 2048^2 sun shadow map, on the atrium scene; "
            "its 25 point lights: bench --lights 25 --keep-scene-lights",
            {{"ao.enabled", "true"}, {"ao.method", "ssao"}, {"ssao.resolution", "half"}, {"ssao.samples", "16"},
             {"ssao.radius", "1"}, {"ssao.radius_unit", "world"}, {"ssao_blur.mode", "bilateral"}, {"ssao_blur.width", "20"},
             {"oit.method", "abuffer"}, {"oit.samples", "8"}, {"tonemap.operator", "reinhard"}, {"shadows.enabled", "true"},
             {"shadows.map_size", "2048"}});
        v.back().scene = "atrium";
        // Light-volume cost against accuracy: where volumes end.
        add("lights: exact (threshold 1/1024)", "light volumes end where a light falls to 1/1024",
            {{"lighting.threshold", "0.0009765625"}}, {"lighting"});
        add("lights: 8-bit (threshold 1/255)", "seed 001: light volumes end at 1/255, one step of an 8-bit display",
            {{"lighting.threshold", "0.003921569"}}, {"lighting"});
        add("lights: coarse (threshold 5/256)", "seed 003: light volumes end at 5/256", {{"lighting.threshold", "0.01953125"}}, {"lighting"});
        add("lights: brute force", "every light over every pixel", {{"lighting.strategy", "fullscreen"}}, {"lighting"});
        return v;
    }();
    return presets;
}

}  // namespace dw
