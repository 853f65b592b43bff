// The input queue against real Dear ImGui widgets (a context without a
// window): keys pressed and released inside one frame, as a fast typist, a
// slow frame or xdotool gives them, reach text fields in order.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#include <imgui.h>

#include <cstring>
#include <functional>
#include <string>

#include "tests/gui/HeadlessImGui.h"
#include "ui/InputQueue.h"
#include "ui/Widgets.h"

using namespace dw;

namespace {

// A headless ImGui context fed through an input queue.
class QueuedImGui {
public:
    QueuedImGui() : context_(ImVec2(800, 600)) {}
    // One frame: this frame's share of the queue, then `draw` in a window at (0, 0).
    void frame(const std::function<void()>& draw) {
        presses = queue.feed(ImGui::GetIO());
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(600, 200));
        ImGui::Begin("test", nullptr, ImGuiWindowFlags_NoSavedSettings);
        draw();
        ImGui::End();
        ImGui::Render();
    }
    void tap(int key, int mods = 0) {
        if (mods & GLFW_MOD_CONTROL) queue.key(GLFW_KEY_LEFT_CONTROL, true, mods);
        queue.key(key, true, mods);
        queue.key(key, false, mods);
        if (mods & GLFW_MOD_CONTROL) queue.key(GLFW_KEY_LEFT_CONTROL, false, 0);
    }
    // Keys and characters as a keyboard gives them for lower-case ASCII.
    void type(const std::string& text) {
        for (char c : text) {
            const int key = c >= 'a' && c <= 'z' ? GLFW_KEY_A + (c - 'a') : c == '/' ? GLFW_KEY_SLASH : c == '.' ? GLFW_KEY_PERIOD : -1;
            if (key >= 0) queue.key(key, true, 0);
            queue.character(static_cast<unsigned char>(c));
            if (key >= 0) queue.key(key, false, 0);
        }
    }
    void click(float x, float y) {
        queue.button(0, true, x, y);
        queue.button(0, false, x, y);
    }
    ui::InputQueue queue;
    std::vector<std::pair<int, int>> presses;

private:
    test::HeadlessImGui context_;
};

}  // namespace

TEST(InputQueue, AKeyPressedAndReleasedInOneFrameIsSeenDownForAFrameThenUp) {
    QueuedImGui imgui;
    imgui.tap(GLFW_KEY_ENTER);
    bool pressed = false;
    imgui.frame([&] { pressed = ImGui::IsKeyPressed(GLFW_KEY_ENTER); });
    EXPECT_TRUE(pressed) << "the tap was lost, as ImGui 1.86's own GLFW callbacks lose it";
    EXPECT_EQ(imgui.presses.size(), 1u);
    imgui.frame([&] { pressed = ImGui::IsKeyDown(GLFW_KEY_ENTER); });
    EXPECT_FALSE(pressed);
    EXPECT_EQ(imgui.queue.pending(), 0u);
}

TEST(InputQueue, CtrlAThenTextThenEnterReplacesAFieldsTextAndEndsTheEdit) {
    QueuedImGui imgui;
    char buffer[256];
    std::snprintf(buffer, sizeof(buffer), "%s", "old/path.gltf");
    bool entered = false;
    ImVec2 field;
    auto draw = [&] {
        entered |= ui::inputTextEnter("##path", "", buffer, sizeof(buffer));
        field = ImVec2((ImGui::GetItemRectMin().x + ImGui::GetItemRectMax().x) * 0.5f,
                       (ImGui::GetItemRectMin().y + ImGui::GetItemRectMax().y) * 0.5f);
    };
    imgui.frame(draw);
    // Everything in one go, as one slow frame receives it: click into the
    // field, select all, type over it, Enter.
    imgui.click(field.x, field.y);
    imgui.tap(GLFW_KEY_A, GLFW_MOD_CONTROL);
    imgui.type("new/scene.json");
    imgui.tap(GLFW_KEY_ENTER);
    int frames = 0;
    while ((imgui.queue.pending() > 0 || frames < 2) && frames < 100) {
        imgui.frame(draw);
        ++frames;
    }
    EXPECT_STREQ(buffer, "new/scene.json");
    EXPECT_TRUE(entered) << "Enter did not end the edit";
    EXPECT_LE(frames, 12) << "a word should take a frame, not a frame a letter";
}

TEST(InputQueue, HomeAndEndMoveTheCursorBeforeTheTextTypedAfterThem) {
    QueuedImGui imgui;
    char buffer[256] = "";
    ImVec2 field;
    auto draw = [&] {
        ImGui::InputText("##f", buffer, sizeof(buffer));
        field = ImGui::GetItemRectMin();
    };
    imgui.frame(draw);
    imgui.click(field.x + 4, field.y + 4);
    imgui.type("middle");
    imgui.tap(GLFW_KEY_HOME);
    imgui.type("a/");
    imgui.tap(GLFW_KEY_END);
    imgui.type(".z");
    for (int i = 0; i < 60 && imgui.queue.pending() > 0; ++i) imgui.frame(draw);
    imgui.frame(draw);
    EXPECT_STREQ(buffer, "a/middle.z");
}

TEST(InputQueue, TextWaitsForTheClickBeforeItAndAKeyOfTheSameNameForTheNextFrame) {
    QueuedImGui imgui;
    imgui.click(10, 10);
    imgui.type("ab");
    imgui.frame([] {});
    // The pointer moves over the point first, the press a frame later.
    EXPECT_FALSE(ImGui::GetIO().MouseDown[0]);
    EXPECT_EQ(ImGui::GetIO().MousePos.x, 10.0f);
    imgui.frame([] {});
    // The click alone: its press this frame, and nothing typed yet.
    EXPECT_TRUE(ImGui::GetIO().MouseDown[0]);
    EXPECT_TRUE(imgui.presses.empty());
    imgui.frame([] {});
    EXPECT_FALSE(ImGui::GetIO().MouseDown[0]);
    EXPECT_TRUE(imgui.presses.empty()) << "a key went in the frame of the release";
    imgui.frame([] {});
    ASSERT_EQ(imgui.presses.size(), 2u) << "typing keys carry no order against text: one frame for the word";
    EXPECT_EQ(imgui.presses[0].first, GLFW_KEY_A);
    EXPECT_EQ(imgui.presses[1].first, GLFW_KEY_B);
    // An editing key twice in one batch: once a frame.
    imgui.tap(GLFW_KEY_BACKSPACE);
    imgui.tap(GLFW_KEY_BACKSPACE);
    imgui.frame([] {});
    EXPECT_EQ(imgui.presses.size(), 1u);
    imgui.frame([] {});
    EXPECT_EQ(imgui.presses.size(), 0u);  // the first one's release
    imgui.frame([] {});
    EXPECT_EQ(imgui.presses.size(), 1u);
}
