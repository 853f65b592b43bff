#include "ui/InputQueue.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <set>

namespace dw::ui {

bool InputQueue::isModifier(int key) {
    return key == GLFW_KEY_LEFT_CONTROL || key == GLFW_KEY_RIGHT_CONTROL || key == GLFW_KEY_LEFT_SHIFT ||
           key == GLFW_KEY_RIGHT_SHIFT || key == GLFW_KEY_LEFT_ALT || key == GLFW_KEY_RIGHT_ALT ||
           key == GLFW_KEY_LEFT_SUPER || key == GLFW_KEY_RIGHT_SUPER;
}

bool InputQueue::typesOnly(const Event& e) {
    if (e.kind != Event::Key) return false;
    if (e.mods & (GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER)) return false;
    const int k = e.code;
    return (k >= GLFW_KEY_SPACE && k <= GLFW_KEY_GRAVE_ACCENT) || k == GLFW_KEY_WORLD_1 || k == GLFW_KEY_WORLD_2 ||
           (k >= GLFW_KEY_KP_0 && k <= GLFW_KEY_KP_EQUAL && k != GLFW_KEY_KP_ENTER);
}

void InputQueue::key(int key, bool down, int mods) {
    if (key < 0 || key >= 512) return;  // io.KeysDown has 512 entries; GLFW_KEY_UNKNOWN is -1
    queue_.push_back({Event::Key, key, down, mods, {}});
}

void InputQueue::character(unsigned codepoint) { queue_.push_back({Event::Char, static_cast<int>(codepoint), true, 0, {}}); }

void InputQueue::button(int button, bool down, float x, float y) {
    if (button < 0 || button >= kButtons) return;
    queue_.push_back({Event::Button, button, down, 0, ImVec2(x, y)});
}

bool InputQueue::keyDown(int key) const { return std::find(keysDown_.begin(), keysDown_.end(), key) != keysDown_.end(); }

std::vector<std::pair<int, int>> InputQueue::feed(ImGuiIO& io) {
    std::vector<std::pair<int, int>> presses;
    std::set<int> keysChanged;
    bool buttonChanged[kButtons] = {};
    bool anyButton = false, text = false, editingKey = false;
    while (!queue_.empty()) {
        const Event e = queue_.front();
        if (e.kind == Event::Button) {
            if (buttonChanged[e.code] || text || editingKey) break;
            // A press away from where the pointer was last frame: the move
            // first, the press next frame (widgets that overlap others take
            // a press only where they were hovered the frame before).
            if (e.down && e.pos.x > -FLT_MAX && (e.pos.x != lastPos_.x || e.pos.y != lastPos_.y)) {
                io.MousePos = e.pos;
                lastPos_ = e.pos;
                break;
            }
            buttonChanged[e.code] = anyButton = true;
            buttonsDown_[e.code] = e.down;
            if (e.pos.x > -FLT_MAX) io.MousePos = e.pos;
        } else if (e.kind == Event::Char) {
            if (anyButton || editingKey) break;
            io.AddInputCharacter(static_cast<unsigned>(e.code));
            text = true;
        } else {
            const bool free = typesOnly(e);
            if (anyButton || editingKey) break;
            if (!free && (keysChanged.count(e.code) || text)) break;
            if (!free) {
                keysChanged.insert(e.code);
                // A modifier changed: text may follow (it types the same either way).
                if (!isModifier(e.code)) editingKey = true;
            }
            auto it = std::find(keysDown_.begin(), keysDown_.end(), e.code);
            if (e.down && it == keysDown_.end()) keysDown_.push_back(e.code);
            if (!e.down && it != keysDown_.end()) keysDown_.erase(it);
            if (e.down) presses.emplace_back(e.code, e.mods);
        }
        queue_.pop_front();
    }
    // The state after this frame's events: what ImGui reads.
    std::fill(std::begin(io.KeysDown), std::end(io.KeysDown), false);
    for (int k : keysDown_) io.KeysDown[k] = true;
    // A tap of a typing key inside this frame shows as down for the frame
    // (shortcuts that read ImGui see it; the release comes with the next press).
    for (const auto& [k, m] : presses) io.KeysDown[k] = true;
    io.KeyCtrl = keyDown(GLFW_KEY_LEFT_CONTROL) || keyDown(GLFW_KEY_RIGHT_CONTROL);
    io.KeyShift = keyDown(GLFW_KEY_LEFT_SHIFT) || keyDown(GLFW_KEY_RIGHT_SHIFT);
    io.KeyAlt = keyDown(GLFW_KEY_LEFT_ALT) || keyDown(GLFW_KEY_RIGHT_ALT);
    io.KeySuper = keyDown(GLFW_KEY_LEFT_SUPER) || keyDown(GLFW_KEY_RIGHT_SUPER);
    for (int b = 0; b < kButtons; ++b) io.MouseDown[b] = buttonsDown_[b];
    lastPos_ = io.MousePos;
    return presses;
}

}  // namespace dw::ui
