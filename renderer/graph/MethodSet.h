#pragma once
// A family of interchangeable methods inside one pass, chosen per frame by an
// enum knob: the lighting pass's strategies (lighting.strategy), the oit
// pass's transparency methods (oit.method) and the ao pass's AO methods
// (ao.method). One mechanism for all of them, as PassCatalog is for passes:
//
// - a method is one class (its name(), description(), outputs() and work)
//   and one line in its family's Builtin*.cpp list; from outside the library
//   (tests, plug-ins) `static dw::RegisterMethod<Family, MyMethod> r;` adds one
//   after the built-ins (MethodCatalog<Family>::extra());
// - MethodSet builds one instance of each (built-ins in order, then the
//   extras), registers the knob whose choices are their names (the first is
//   the default), and answers which method a knob value picks, which method
//   owns an output, every method's outputs, and whether a frame asks for an
//   output only another method writes.
//
// `Family` needs: const char* name() const, std::string description() const,
// std::vector<OutputDecl> outputs() const, void setup(gl::ShaderLibrary&),
// and a constructor from KnobRegistry& (for make()).
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "renderer/Error.h"
#include "renderer/graph/OutputRegistry.h"
#include "renderer/knobs/KnobRegistry.h"

namespace dw {

namespace gl {
class ShaderLibrary;
}

template <typename Family>
using MethodFactory = std::function<std::unique_ptr<Family>(KnobRegistry&)>;

// The factory of method T of a family.
template <typename Family, typename T>
MethodFactory<Family> makeMethod() {
    return [](KnobRegistry& knobs) { return std::make_unique<T>(knobs); };
}

// Methods of a family registered from outside the library, after the built-ins.
template <typename Family>
class MethodCatalog {
public:
    static MethodCatalog& extra() {
        static MethodCatalog catalog;
        return catalog;
    }
    void add(MethodFactory<Family> make) { factories_.push_back(std::move(make)); }
    const std::vector<MethodFactory<Family>>& factories() const { return factories_; }

private:
    std::vector<MethodFactory<Family>> factories_;
};

template <typename Family, typename T>
struct RegisterMethod {
    RegisterMethod() { MethodCatalog<Family>::extra().add(makeMethod<Family, T>()); }
};

// What the family's knob is: its name, its pass (the knob's group), the
// sentence before the methods' own descriptions, choices after the methods'
// (lighting.strategy's "auto", with their descriptions) and whether
// `tradeoff` sweeps it by default.
struct MethodKnob {
    std::string name;
    std::string pass;
    std::string lead;  // "how ... :"; each method then adds " name: description", separated by ';'
    std::vector<std::pair<std::string, std::string>> extraChoices;  // {choice, its description}
    bool tradeoff = false;
};

template <typename Family>
class MethodSet {
public:
    // Builds `builtins` then the registered extras, each with `knobs`, and
    // adds the knob. Throws dw::Error when two methods share a name.
    MethodSet(KnobRegistry& knobs, const std::vector<MethodFactory<Family>>& builtins, const MethodKnob& knob)
        : knobName_(knob.name) {
        std::vector<MethodFactory<Family>> factories = builtins;
        for (const auto& f : MethodCatalog<Family>::extra().factories()) factories.push_back(f);
        std::string description = knob.lead;
        for (const auto& make : factories) {
            methods_.push_back(make(knobs));
            const std::string name = methods_.back()->name();
            for (const auto& n : names_)
                if (n == name) throw Error(knob.name + ": two methods are named '" + name + "'");
            names_.push_back(name);
            description += std::string(names_.size() > 1 ? ";" : "") + " " + name + ": " + methods_.back()->description();
        }
        std::vector<std::string> choices = names_;
        for (const auto& [choice, what] : knob.extraChoices) {
            choices.push_back(choice);
            description += "; " + choice + ": " + what;
        }
        knob_ = knobs.addEnum(knob.name, choices, 0, knob.pass, description, knob.tradeoff);
    }

    EnumKnob knob() const { return knob_; }
    // The methods, in the knob's order.
    const std::vector<std::unique_ptr<Family>>& all() const { return methods_; }
    // The method the knob picks; nullptr for an extra choice (lighting's auto).
    Family* picked(const KnobRegistry& knobs) const {
        const auto i = static_cast<std::size_t>(knobs.get(knob_));
        return i < methods_.size() ? methods_[i].get() : nullptr;
    }
    // The method of that name; nullptr when none is.
    Family* named(const std::string& name) const {
        for (const auto& m : methods_)
            if (name == m->name()) return m.get();
        return nullptr;
    }
    // The method that declares `output`; nullptr for the pass's own outputs.
    const Family* ownerOf(const std::string& output) const {
        for (const auto& m : methods_)
            for (const auto& o : m->outputs())
                if (o.name == output) return m.get();
        return nullptr;
    }
    // Every method's outputs, appended to `out` (the pass's own first).
    void appendOutputs(std::vector<OutputDecl>& out) const {
        for (const auto& m : methods_)
            for (auto& o : m->outputs()) out.push_back(o);
    }
    void setup(gl::ShaderLibrary& shaders) {
        for (auto& m : methods_) m->setup(shaders);
    }
    // Throws dw::Error when the frame wants (FrameContext::wanted) an output
    // that only a method other than `chosen` writes, naming the knob value that writes it.
    void refuseOthersOutputs(const Family& chosen, const std::set<std::string>& wanted) const {
        for (const auto& m : methods_)
            if (m.get() != &chosen)
                for (const auto& o : m->outputs())
                    if (wanted.count(o.name))
                        throw Error(o.name + " is written only with " + knobName_ + "=" + m->name() + " (now " +
                                    chosen.name() + ")");
    }

private:
    std::string knobName_;
    std::vector<std::unique_ptr<Family>> methods_;
    std::vector<std::string> names_;
    EnumKnob knob_;
};

}  // namespace dw
