// --animation NAME|INDEX|none (issue 36): which clip plays, by name, index
// or none; an unknown choice is one line naming the scene's clips.
#include <gtest/gtest.h>

#include "renderer/Error.h"
#include "renderer/scene/Animation.h"
#include "renderer/scene/ClipChoice.h"

namespace dw {
namespace {

SceneAnimation twoFiles() {
    SceneAnimation a;
    a.nodes.resize(1);
    a.files = {"a.gltf", "b.gltf"};
    for (const auto& [name, file] : {std::pair{"walk", 0}, {"run", 0}, {"wave", 1}}) {
        AnimationClip c;
        c.name = name;
        c.file = file;
        a.clips.push_back(c);
    }
    a.playing = {0, 2};  // each file's first
    a.posedAt = 0.0;
    return a;
}

TEST(ClipChoice, ByNameIndexOrNone) {
    SceneAnimation a = twoFiles();
    chooseClip(a, "");
    EXPECT_EQ(a.playing, (std::vector<int>{0, 2}));
    EXPECT_EQ(a.posedAt, 0.0);  // nothing chosen: the pose stands
    chooseClip(a, "run");
    EXPECT_EQ(a.playing, (std::vector<int>{1, 2}));  // in place of its file's first; the other file keeps its own
    EXPECT_LT(a.posedAt, 0.0);                        // posed again
    chooseClip(a, "0");
    EXPECT_EQ(a.playing, (std::vector<int>{0, 2}));
    chooseClip(a, "none");
    EXPECT_EQ(a.playing, (std::vector<int>{-1, -1}));
    chooseClip(a, "2");
    EXPECT_EQ(a.playing, (std::vector<int>{-1, 2}));
}

TEST(ClipChoice, TheWindowsChoiceAsTheOptionThatGivesIt) {
    SceneAnimation a = twoFiles();
    EXPECT_EQ(clipChoiceOf(a), "");  // the first file's first clip: the default
    a.playing[0] = 1;
    EXPECT_EQ(clipChoiceOf(a), "1");
    a.playing[0] = -1;
    EXPECT_EQ(clipChoiceOf(a), "none");
    EXPECT_EQ(clipChoiceOf(SceneAnimation{}), "");
}

TEST(ClipChoice, AnUnknownClipIsOneLineNamingTheClips) {
    SceneAnimation a = twoFiles();
    for (const char* bad : {"jump", "3", "-1", "Walk"}) {
        try {
            chooseClip(a, bad);
            ADD_FAILURE() << bad << " accepted";
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()), std::string("--animation '") + bad +
                                                 "': the scene has no such clip; its clips: 0 'walk', 1 'run', "
                                                 "2 'wave' (or none)");
        }
    }
    EXPECT_EQ(a.playing, (std::vector<int>{0, 2}));  // unchanged
    SceneAnimation still;
    chooseClip(still, "none");  // none on a scene without clips: nothing to stop
    EXPECT_THROW(chooseClip(still, "0"), Error);
    EXPECT_EQ(clipList(still), "none");
}

}  // namespace
}  // namespace dw
