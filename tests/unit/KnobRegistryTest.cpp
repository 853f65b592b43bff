#include <gtest/gtest.h>

#include <set>

#include "renderer/Error.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/Pipeline.h"

using namespace dw;

TEST(KnobRegistry, EveryPipelineKnobIsDeclaredOnceWithPassAndDescription) {
    KnobRegistry knobs;
    Pipeline pipeline(knobs);  // declares every pass's knobs; needs no GL
    ASSERT_GT(knobs.size(), 5u);
    std::set<std::string> names;
    for (const auto& s : knobs.specs()) {
        EXPECT_TRUE(names.insert(s.name).second) << s.name;
        EXPECT_FALSE(s.pass.empty()) << s.name;
        EXPECT_FALSE(s.description.empty()) << s.name;
        EXPECT_EQ(s.name.rfind(s.pass + ".", 0), 0u) << s.name << " should start with its pass";
        EXPECT_GE(s.defaultValue, s.minValue) << s.name;
        EXPECT_LE(s.defaultValue, s.maxValue) << s.name;
        if (s.type == KnobType::Enum) {
            EXPECT_EQ(s.maxValue, static_cast<double>(s.choices.size() - 1));
        }
    }
    EXPECT_TRUE(knobs.find("lighting.threshold"));
    EXPECT_TRUE(knobs.find("tonemap.operator"));
}

TEST(KnobRegistry, ParsesEachTypeAndRejectsBadValuesWithoutChangingThem) {
    KnobRegistry k;
    const FloatKnob f = k.addFloat("p.f", 0.5, 0.0, 1.0, "p", "a float");
    const IntKnob i = k.addInt("p.i", 8, 1, 64, "p", "an int");
    const BoolKnob b = k.addBool("p.b", false, "p", "a bool");
    const EnumKnob e = k.addEnum("p.e", {"one", "two", "three"}, 0, "p", "an enum");

    k.setFromString("p.f", "0.25");
    EXPECT_FLOAT_EQ(k.get(f), 0.25f);
    k.applyAssignment("p.i=16");
    EXPECT_EQ(k.get(i), 16);
    k.setFromString("p.b", "on");
    EXPECT_TRUE(k.get(b));
    // Bools in any case, as 1/0 and yes/no too.
    for (const char* no : {"FALSE", "False", "0", "Off", "NO"}) {
        k.setFromString("p.b", "true");
        k.setFromString("p.b", no);
        EXPECT_FALSE(k.get(b)) << no;
    }
    for (const char* yes : {"TRUE", "True", "1", "ON", "Yes"}) {
        k.setFromString("p.b", "false");
        k.setFromString("p.b", yes);
        EXPECT_TRUE(k.get(b)) << yes;
    }
    k.setFromString("p.e", "three");
    EXPECT_EQ(k.get(e), 2);
    EXPECT_EQ(k.choice(e), "three");

    auto message = [&](const std::string& assignment) {
        try {
            k.applyAssignment(assignment);
        } catch (const Error& ex) {
            return std::string(ex.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message("p.f=2").find("out of range [0, 1]"), std::string::npos);
    EXPECT_NE(message("p.i=2.5").find("whole number"), std::string::npos);
    EXPECT_NE(message("p.i=abc").find("expects a number"), std::string::npos);
    EXPECT_NE(message("p.b=maybe").find("true or false"), std::string::npos);
    EXPECT_NE(message("p.e=four").find("one, two, three"), std::string::npos);
    EXPECT_NE(message("p.x=1").find("unknown knob 'p.x'"), std::string::npos);
    EXPECT_NE(message("p.ff=1").find("did you mean 'p.f'"), std::string::npos);
    EXPECT_NE(message("nonsense").find("name=value"), std::string::npos);
    // Failed assignments left the values alone.
    EXPECT_FLOAT_EQ(k.get(f), 0.25f);
    EXPECT_EQ(k.get(i), 16);
    EXPECT_EQ(k.get(e), 2);
}

TEST(KnobRegistry, SetClampsRoundsAndCountsChanges) {
    KnobRegistry k;
    const IntKnob i = k.addInt("p.i", 8, 1, 64, "p", "an int");
    const auto g0 = k.generation();
    k.set(i.id, 100.0);
    EXPECT_EQ(k.get(i), 64);
    k.set(i.id, 3.6);
    EXPECT_EQ(k.get(i), 4);
    EXPECT_GT(k.generation(), g0);
    const auto g1 = k.generation();
    k.set(i.id, 4.0);  // unchanged value: no new generation
    EXPECT_EQ(k.generation(), g1);
    k.resetAll();
    EXPECT_EQ(k.get(i), 8);
    EXPECT_TRUE(k.isDefault(i.id));
    EXPECT_THROW(k.addInt("p.i", 1, 0, 2, "p", "dup"), Error);
}

TEST(KnobRegistry, EnumChoicesAreNamedOnceForDefaultsBranchesAndShaderDefines) {
    KnobRegistry k;
    const EnumKnob e = k.addEnum("my_pass.blend-mode", {"add", "alpha 2"}, "alpha 2", "my_pass", "an enum");
    EXPECT_EQ(k.get(e), 1);
    EXPECT_EQ(k.choiceIndex(e, "add"), 0);
    EXPECT_EQ(k.choiceIndex(e, "alpha 2"), 1);
    try {
        k.choiceIndex(e, "multiply");
        ADD_FAILURE() << "no error for an unknown choice";
    } catch (const Error& ex) {
        EXPECT_NE(std::string(ex.what()).find("add, alpha 2"), std::string::npos) << ex.what();
    }
    EXPECT_EQ(k.choiceDefines(e), (std::vector<std::string>{"MY_PASS_BLEND_MODE_ADD=0", "MY_PASS_BLEND_MODE_ALPHA_2=1"}));
    EXPECT_THROW(k.addEnum("my_pass.other", {"a", "b"}, "c", "my_pass", "bad default"), Error);
}

TEST(KnobRegistry, EveryPipelineEnumGivesDistinctShaderDefines) {
    KnobRegistry knobs;
    Pipeline pipeline(knobs);
    std::set<std::string> names;
    for (size_t id = 0; id < knobs.size(); ++id) {
        if (knobs.spec(static_cast<int>(id)).type != KnobType::Enum) continue;
        for (const std::string& d : knobs.choiceDefines(EnumKnob{static_cast<int>(id)})) {
            const std::string name = d.substr(0, d.find('='));
            EXPECT_TRUE(names.insert(name).second) << name << " would be defined twice";
        }
    }
    EXPECT_TRUE(names.count("TONEMAP_OPERATOR_REINHARD"));
}
