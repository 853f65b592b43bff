#include "renderer/reference/ReferenceModel.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "renderer/Error.h"

namespace dw::reference {

namespace {

double number(const KnobRegistry& k, const std::string& name) {
    const auto id = k.find(name);
    return id ? k.value(*id) : 0.0;
}
bool flag(const KnobRegistry& k, const std::string& name) { return number(k, name) != 0.0; }
std::string choice(const KnobRegistry& k, const std::string& name) {
    const auto id = k.find(name);
    if (!id) return {};
    const KnobSpec& s = k.spec(*id);
    const int i = static_cast<int>(k.value(*id));
    return i >= 0 && i < static_cast<int>(s.choices.size()) ? s.choices[i] : std::string();
}

}  // namespace

const std::vector<std::string>& ReferenceModel::honouredKnobs() {
    static const std::vector<std::string> names = {
        "shadows.enabled",      "shadows.blended_casters", "ao.enabled",        "ao.method",
        "ssao.radius",          "ssao.radius_unit",      "ssao.intensity",    "gtao.radius",
        "gtao.radius_unit",     "aov.radius",            "aov.radius_unit",       "lighting.attenuation",  "lighting.window_exponent", "lighting.threshold",
        "lighting.ambient_specular", "lighting.ambient_occlusion", "skybox.mode", "skybox.intensity",
        "skybox.rotation",      "tonemap.operator",      "tonemap.key",       "tonemap.auto_white",
        "tonemap.white",        "tonemap.exposure",      "tonemap.srgb",      "tonemap.auto_exposure",
        "tonemap.nan_guard",    "luminance.log_delta",   "luminance.background"};
    return names;
}

const std::vector<std::string>& ReferenceModel::unmodelledKnobs() {
    static const std::vector<std::string> names = {"bloom.enabled", "dof.enabled", "aa.method"};
    return names;
}

ReferenceModel ReferenceModel::fromKnobs(const KnobRegistry& k, const Scene& scene) {
    ReferenceModel m;
    m.attenuation = choice(k, "lighting.attenuation") == "windowed" ? AttenuationModel::Windowed : AttenuationModel::Classic;
    m.windowExponent = number(k, "lighting.window_exponent");
    m.threshold = number(k, "lighting.threshold");
    m.shadows = flag(k, "shadows.enabled");
    m.blendedCasters = flag(k, "shadows.blended_casters");
    m.ambientSpecular = flag(k, "lighting.ambient_specular");
    const std::string ao = choice(k, "lighting.ambient_occlusion");
    m.bakedOcclusion = ao == "both" || ao == "baked";
    m.rayTracedAo = flag(k, "ao.enabled") && (ao == "both" || ao == "screen");
    // The radius (and intensity) of the method ao.method names: <method>.radius
    // in <method>.radius_unit (world when it has none), <method>.intensity (1
    // when it has none), so the rays see the neighbourhood the method sees.
    std::string method = choice(k, "ao.method");
    if (method.empty() || !k.find(method + ".radius")) method = "ssao";
    m.aoRadius = number(k, method + ".radius");
    if (k.find(method + ".radius_unit") && choice(k, method + ".radius_unit") != "world")
        m.aoRadius *= sceneLengthUnit(scene.bounds());
    m.aoIntensity = k.find(method + ".intensity") ? number(k, method + ".intensity") : 1.0;

    const std::string mode = choice(k, "skybox.mode");
    const bool hasEnvironment = scene.sky.equirect.width > 0 || !scene.sky.cubeFaces.empty();
    const bool color = mode == "scene" ? scene.sky.kind == Sky::Kind::Color : mode == "color";
    const bool procedural = mode == "scene" ? scene.sky.kind == Sky::Kind::Procedural : mode == "procedural";
    m.sky = color || (!procedural && !hasEnvironment) ? SkyChoice::Color
            : procedural                              ? SkyChoice::Procedural
            : scene.sky.cubeFaces.empty()             ? SkyChoice::Equirect
                                                      : SkyChoice::Cube;
    m.skyIntensity = number(k, "skybox.intensity") * scene.sky.intensity;
    m.skyRotationDegrees = number(k, "skybox.rotation") + scene.sky.rotationDegrees;

    const std::string op = choice(k, "tonemap.operator");
    m.toneOperator = op == "simple"    ? ToneOperator::Simple
                     : op == "aces"    ? ToneOperator::Aces
                     : op == "neutral" ? ToneOperator::Neutral
                     : op == "clamp"   ? ToneOperator::Clamp
                                       : ToneOperator::Reinhard;
    m.key = number(k, "tonemap.key");
    m.white = number(k, "tonemap.white");
    m.exposure = number(k, "tonemap.exposure");
    m.autoWhite = flag(k, "tonemap.auto_white");
    m.autoExposure = flag(k, "tonemap.auto_exposure");
    m.srgb = flag(k, "tonemap.srgb");
    m.nanGuard = flag(k, "tonemap.nan_guard");
    m.logDelta = number(k, "luminance.log_delta");
    m.backgroundInStatistics = choice(k, "luminance.background") != "exclude";
    return m;
}

PixelFilter pixelFilterNamed(const std::string& name) {
    if (name == "box") return PixelFilter::Box;
    if (name == "tent") return PixelFilter::Tent;
    throw Error("--filter: expected box or tent, got '" + name + "'");
}

const char* pixelFilterName(PixelFilter filter) { return filter == PixelFilter::Tent ? "tent" : "box"; }

std::string ReferenceModel::canonical() const {
    std::ostringstream s;
    s.precision(17);
    s << "attenuation=" << static_cast<int>(attenuation) << ";window=" << windowExponent << ";shadows=" << shadows << ";blended_casters=" << blendedCasters
      << ";ambient_specular=" << ambientSpecular << ";baked=" << bakedOcclusion << ";ao=" << rayTracedAo
      << ";sky=" << static_cast<int>(sky) << ";sky_intensity=" << skyIntensity << ";sky_rotation=" << skyRotationDegrees
      << ";op=" << static_cast<int>(toneOperator) << ";key=" << key << ";white=" << white << ";exposure=" << exposure
      << ";auto_white=" << autoWhite << ";auto_exposure=" << autoExposure << ";srgb=" << srgb << ";nan_guard=" << nanGuard
      << ";log_delta=" << logDelta << ";background=" << backgroundInStatistics << ";";
    // Values that change nothing under the model are left out, so they do not split the cache.
    if (attenuation == AttenuationModel::Windowed) s << "threshold=" << threshold << ";";
    if (rayTracedAo) s << "ao_radius=" << aoRadius << ";ao_intensity=" << aoIntensity << ";ao_rays=" << aoRays << ";seed=" << seed << ";";
    // The pixel's centre alone (1 sample) keeps the key it always had.
    if (pixelSamples > 1) s << "spp=" << pixelSamples << ";filter=" << pixelFilterName(pixelFilter) << ";pixel_seed=" << seed << ";";
    return s.str();
}

KnobReport reportKnobs(const KnobRegistry& knobs, const ReferenceModel& model, bool finalImage) {
    KnobReport r;
    if (const auto id = knobs.find("lighting.threshold"); id && model.attenuation == AttenuationModel::Classic) {
        ++r.ignoredTotal;
        if (!knobs.isDefault(*id))
            r.ignoredChanged.push_back("lighting.threshold=" + knobs.format(*id) + " (the classic model has no cut-off)");
    }
    const auto& honoured = ReferenceModel::honouredKnobs();
    const auto& unmodelled = ReferenceModel::unmodelledKnobs();
    for (size_t id = 0; id < knobs.size(); ++id) {
        const std::string& name = knobs.spec(static_cast<int>(id)).name;
        if (std::find(honoured.begin(), honoured.end(), name) != honoured.end()) continue;
        if (std::find(unmodelled.begin(), unmodelled.end(), name) != unmodelled.end()) {
            // An enum (aa.method) is off at its first choice (none) and said with its value.
            const bool isEnum = knobs.spec(static_cast<int>(id)).type == KnobType::Enum;
            if (finalImage && knobs.value(static_cast<int>(id)) != 0.0)
                r.unmodelledOn.push_back(isEnum ? name + "=" + knobs.format(static_cast<int>(id)) : name);
            continue;
        }
        ++r.ignoredTotal;
        if (!knobs.isDefault(static_cast<int>(id)))
            r.ignoredChanged.push_back(name + "=" + knobs.format(static_cast<int>(id)));
    }
    return r;
}

std::string KnobReport::text() const {
    std::string s = "the reference ignores " + std::to_string(ignoredTotal) +
                    " knobs that choose GPU approximations (list knobs; docs/reference.md)";
    if (!ignoredChanged.empty()) {
        s += "; of them set here:";
        for (const auto& c : ignoredChanged) s += " " + c;
    }
    if (!unmodelledOn.empty()) {
        s += "\nnot modelled (effects after the L-buffer; the reference's final image is without them):";
        for (const auto& c : unmodelledOn) s += " " + c;
    }
    return s;
}

}  // namespace dw::reference
