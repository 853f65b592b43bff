// graph/MethodSet: the one mechanism every method family (lighting
// strategies, OIT methods, AO methods) registers through. A toy family, so a
// broken rule shows here without GL: the knob's choices and description,
// which method a value picks, extras after the built-ins, who owns an output,
// the refusal of another method's output, a duplicate name refused.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "renderer/Error.h"
#include "renderer/graph/MethodSet.h"

namespace dw {
namespace {

class ToyMethod {
public:
    explicit ToyMethod(KnobRegistry&) {}
    virtual ~ToyMethod() = default;
    virtual const char* name() const = 0;
    virtual std::string description() const = 0;
    virtual std::vector<OutputDecl> outputs() const { return {}; }
};

class Plain : public ToyMethod {
public:
    using ToyMethod::ToyMethod;
    const char* name() const override { return "plain"; }
    std::string description() const override { return "nothing of its own"; }
};

class WithOutput : public ToyMethod {
public:
    explicit WithOutput(KnobRegistry& knobs) : ToyMethod(knobs) { knobs.addInt("toy.taps", 4, 1, 8, "toy", "taps"); }
    const char* name() const override { return "fancy"; }
    std::string description() const override { return "writes toy.extra"; }
    std::vector<OutputDecl> outputs() const override { return {{"toy.extra", OutputKind::Scalar, "its own"}}; }
};

class Registered : public ToyMethod {
public:
    using ToyMethod::ToyMethod;
    const char* name() const override { return "plugin"; }
    std::string description() const override { return "from outside"; }
};

class PlainAgain : public Plain {
public:
    using Plain::Plain;
};

std::vector<MethodFactory<ToyMethod>> builtins() {
    return {makeMethod<ToyMethod, Plain>(), makeMethod<ToyMethod, WithOutput>()};
}

const RegisterMethod<ToyMethod, Registered> registerPlugin;

TEST(MethodSet, BuildsTheBuiltInsThenTheRegisteredOnesAndTheKnobThatPicksThem) {
    KnobRegistry knobs;
    const MethodSet<ToyMethod> set(knobs, builtins(),
                                   MethodKnob{"toy.method", "toy", "how toys are made:", {{"auto", "any"}}, true});
    ASSERT_EQ(set.all().size(), 3u);
    EXPECT_STREQ(set.all()[2]->name(), "plugin");  // after the built-ins
    const KnobSpec& spec = knobs.spec(set.knob().id);
    EXPECT_EQ(spec.choices, (std::vector<std::string>{"plain", "fancy", "plugin", "auto"}));
    EXPECT_EQ(spec.description,
              "how toys are made: plain: nothing of its own; fancy: writes toy.extra; plugin: from outside; auto: any");
    EXPECT_TRUE(knobs.find("toy.taps").has_value());  // each method declared its own knobs
    EXPECT_STREQ(set.picked(knobs)->name(), "plain");  // the first is the default
    knobs.setFromString("toy.method", "plugin");
    EXPECT_STREQ(set.picked(knobs)->name(), "plugin");
    knobs.setFromString("toy.method", "auto");
    EXPECT_EQ(set.picked(knobs), nullptr);  // an extra choice picks no method
    EXPECT_STREQ(set.named("fancy")->name(), "fancy");
    EXPECT_EQ(set.named("none"), nullptr);
}

TEST(MethodSet, OutputsBelongToTheirMethodAndAnotherMethodsOutputIsRefusedByName) {
    KnobRegistry knobs;
    const MethodSet<ToyMethod> set(knobs, builtins(), MethodKnob{"toy.method", "toy", "how:", {}, false});
    std::vector<OutputDecl> out = {{"toy.shared", OutputKind::Scalar, "the pass's own"}};
    set.appendOutputs(out);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[1].name, "toy.extra");
    EXPECT_STREQ(set.ownerOf("toy.extra")->name(), "fancy");
    EXPECT_EQ(set.ownerOf("toy.shared"), nullptr);
    const ToyMethod& plain = *set.picked(knobs);
    EXPECT_NO_THROW(set.refuseOthersOutputs(plain, {"toy.shared"}));
    try {
        set.refuseOthersOutputs(plain, {"toy.extra"});
        ADD_FAILURE() << "toy.extra is fancy's";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "toy.extra is written only with toy.method=fancy (now plain)");
    }
}

TEST(MethodSet, TwoMethodsOfOneNameAreRefused) {
    KnobRegistry knobs;
    std::vector<MethodFactory<ToyMethod>> twice = {makeMethod<ToyMethod, Plain>(), makeMethod<ToyMethod, PlainAgain>()};
    try {
        MethodSet<ToyMethod> set(knobs, twice, MethodKnob{"toy.method", "toy", "how:", {}, false});
        ADD_FAILURE() << "two methods named plain";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "toy.method: two methods are named 'plain'");
    }
}

}  // namespace
}  // namespace dw
