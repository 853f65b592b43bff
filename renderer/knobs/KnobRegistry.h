#pragma once
// The one declaration of every tunable parameter (DESIGN.md, "One knob
// registry"): name, type, default, range, unit, the pass that reads it and
// whether it trades speed for quality. The ImGui widget, the preset field, the
// CLI override (--set name=value) and the tradeoff sweep axis all come from it.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace dw {

enum class KnobType { Bool, Int, Float, Enum };

struct KnobSpec {
    std::string name;         // "lighting.threshold": <pass>.<parameter>
    KnobType type = KnobType::Float;
    double defaultValue = 0.0;
    double minValue = 0.0;
    double maxValue = 1.0;
    std::vector<std::string> choices;  // Enum: the value is an index into this
    std::string unit;         // shown after the value ("px", "deg", "EV", ...)
    std::string pass;         // the pass that reads it
    std::string description;  // one sentence, shown as a tooltip and by `list knobs`
    bool tradeoff = false;    // trades speed for quality (a tradeoff sweep axis)
    bool logarithmic = false; // slider and sweep on a log scale
};

// A renamed knob or value still accepted where knobs are set by name
// (presets, scene settings, --set), with a warning: `oldName` stands for
// `newName`; for a value alias, `knob`'s value `oldName` for `newName`.
struct KnobAlias {
    std::string knob;     // empty for a knob alias; the knob for a value alias
    std::string oldName;
    std::string newName;
    std::string note;     // why ("renamed in issue 22: ...")
    std::string warning() const;
};

struct BoolKnob { int id = -1; };
struct IntKnob { int id = -1; };
struct FloatKnob { int id = -1; };
struct EnumKnob { int id = -1; };

class KnobRegistry {
public:
    BoolKnob addBool(std::string name, bool def, std::string pass, std::string description);
    IntKnob addInt(std::string name, int def, int min, int max, std::string pass, std::string description,
                   std::string unit = {}, bool tradeoff = false);
    FloatKnob addFloat(std::string name, double def, double min, double max, std::string pass,
                       std::string description, std::string unit = {}, bool tradeoff = false,
                       bool logarithmic = false);
    EnumKnob addEnum(std::string name, std::vector<std::string> choices, int def, std::string pass,
                     std::string description, bool tradeoff = false);
    // The default by name; throws dw::Error if it is not one of the choices.
    EnumKnob addEnum(std::string name, std::vector<std::string> choices, const std::string& defaultChoice,
                     std::string pass, std::string description, bool tradeoff = false);

    // One more choice for an enum knob that several passes share (aa.method:
    // each anti-aliasing pass adds its own name), appended so the indices of
    // the earlier choices stay; `makeDefault` makes it the default and the
    // value. The description gets "; <choice>: <what>". Throws dw::Error if
    // the knob is not an enum or already has the choice.
    void addChoice(EnumKnob k, std::string choice, const std::string& what, bool makeDefault = false);

    // Another pass's knob, by name, checked once (RenderPass::connect): throws
    // dw::Error if it is not declared or is of another type.
    BoolKnob requireBool(const std::string& name) const { return {require(name, KnobType::Bool)}; }
    IntKnob requireInt(const std::string& name) const { return {require(name, KnobType::Int)}; }
    FloatKnob requireFloat(const std::string& name) const { return {require(name, KnobType::Float)}; }
    EnumKnob requireEnum(const std::string& name) const { return {require(name, KnobType::Enum)}; }

    bool get(BoolKnob k) const { return values_[k.id] != 0.0; }
    int get(IntKnob k) const { return static_cast<int>(values_[k.id]); }
    float get(FloatKnob k) const { return static_cast<float>(values_[k.id]); }
    int get(EnumKnob k) const { return static_cast<int>(values_[k.id]); }
    std::string choice(EnumKnob k) const { return specs_[k.id].choices[get(k)]; }
    // The index of choice `name`, looked up once by a pass that branches on
    // the value in C++; throws dw::Error naming the choices if there is none.
    int choiceIndex(EnumKnob k, const std::string& name) const;
    // The choices as GLSL defines, so shaders compare with names whose values
    // come from this one declaration: tonemap.operator's choices simple,
    // reinhard, ... give {"TONEMAP_OPERATOR_SIMPLE=0", "TONEMAP_OPERATOR_REINHARD=1", ...}.
    std::vector<std::string> choiceDefines(EnumKnob k) const;
    // "tonemap.operator", "reinhard" -> "TONEMAP_OPERATOR_REINHARD": upper
    // case, anything but letters and digits becomes '_'.
    static std::string choiceDefineName(const std::string& knob, const std::string& choice);

    size_t size() const { return specs_.size(); }
    const KnobSpec& spec(int id) const { return specs_[id]; }
    const std::vector<KnobSpec>& specs() const { return specs_; }
    std::optional<int> find(const std::string& name) const;
    double value(int id) const { return values_[id]; }
    bool isDefault(int id) const { return values_[id] == specs_[id].defaultValue; }

    // Sets a value, clamped to the range and rounded for integer types.
    void set(int id, double v);
    void reset(int id) { set(id, specs_[id].defaultValue); }
    void resetAll();
    // Takes every value of `other`, a registry with the same declarations (a
    // copy worked on elsewhere); generation() moves on only if one changed.
    void copyValues(const KnobRegistry& other);
    // Parses "true", "16", "0.02", "reinhard" by the knob's type. Throws
    // dw::Error naming the knob and the accepted values; never clamps silently.
    void setFromString(const std::string& name, const std::string& text);
    // Renames (KnobAlias): setFromString accepts the old knob name or
    // value for the new one and warns through the warning handler.
    void addAlias(std::string oldName, std::string newName, std::string note);
    void addValueAlias(std::string knob, std::string oldValue, std::string newValue, std::string note);
    const std::vector<KnobAlias>& aliases() const { return aliases_; }
    // The declared name an old knob name stands for (with the alias's
    // warning); any other name unchanged. Lets lookups by name (replay, the
    // window's Open record, Python's Session.get) take the old names too.
    std::string canonicalName(const std::string& name) const;
    // The declared name an old knob name stands for, without a warning;
    // empty for any other name.
    std::string aliasTarget(const std::string& name) const;
    // Where alias warnings go (the CLI prints them; a test collects them).
    // The default prints "warning: TEXT" to stderr, each text once per process.
    // Returns the previous handler; an empty function restores the default.
    using WarningHandler = std::function<void(const std::string&)>;
    static WarningHandler setWarningHandler(WarningHandler handler);
    // "name=value", as --set takes it.
    void applyAssignment(const std::string& assignment);
    std::string format(int id) const { return formatValue(id, values_[id]); }
    std::string formatValue(int id, double value) const;
    std::string formatRange(int id) const;
    // Bumped on every change, so views can cache derived state.
    std::uint64_t generation() const { return generation_; }

    // While set, every knob looked up (find, require*) is appended to `log`:
    // the Pipeline learns which pass reads which knob while it makes and
    // connects each pass. nullptr stops it.
    void logLookups(std::vector<int>* log) const { readLog_ = log; }

private:
    int add(KnobSpec spec);
    int require(const std::string& name, KnobType type) const;
    std::vector<KnobSpec> specs_;
    std::vector<double> values_;
    std::vector<KnobAlias> aliases_;
    std::uint64_t generation_ = 0;
    mutable std::vector<int>* readLog_ = nullptr;
};

}  // namespace dw
