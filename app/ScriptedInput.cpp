#include "app/ScriptedInput.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <sstream>

#include "app/CommandLine.h"
#include "renderer/io/TextFile.h"

namespace dw {

int glfwKeyFromName(const std::string& name) {
    if (name.size() == 1) {
        const char c = name[0];
        if (c >= 'a' && c <= 'z') return GLFW_KEY_A + (c - 'a');
        if (c >= 'A' && c <= 'Z') return GLFW_KEY_A + (c - 'A');
        if (c >= '0' && c <= '9') return GLFW_KEY_0 + (c - '0');
    }
    if (name.size() >= 2 && (name[0] == 'F' || name[0] == 'f')) {
        int n = 0;
        for (size_t i = 1; i < name.size(); ++i) {
            if (name[i] < '0' || name[i] > '9') return -1;
            n = n * 10 + (name[i] - '0');
        }
        return n >= 1 && n <= 12 ? GLFW_KEY_F1 + n - 1 : -1;
    }
    if (name == "Escape") return GLFW_KEY_ESCAPE;
    if (name == "Enter") return GLFW_KEY_ENTER;
    if (name == "Space") return GLFW_KEY_SPACE;
    return -1;
}

ScriptedInput ScriptedInput::load(const std::string& path) {
    return parse(readWholeFile(path, "events file not found", "cannot read events file"), path);
}

ScriptedInput ScriptedInput::parse(const std::string& text, const std::string& source) {
    ScriptedInput s;
    std::istringstream lines(text);
    std::string line;
    int number = 0;
    auto add = [&](int frame, ScriptedFrameInput in) { s.events_.push_back({frame, std::move(in)}); };
    while (std::getline(lines, line)) {
        ++number;
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        int frame = 0;
        std::string what;
        if (!(words >> frame)) {
            if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
            throw UsageError(source + ": line " + std::to_string(number) + ": expected '<frame> <action> ...'");
        }
        auto bad = [&](const std::string& why) {
            return UsageError(source + ": line " + std::to_string(number) + ": " + why);
        };
        if (frame < 0) throw bad("the frame must be 0 or more");
        if (!(words >> what)) throw bad("no action after the frame number");
        ScriptedFrameInput in;
        float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        if (what == "move" || what == "click") {
            if (!(words >> x0 >> y0)) throw bad(what + " takes X Y");
            in.mouseX = x0;
            in.mouseY = y0;
            if (what == "click") {
                in.leftDown = true;
                add(frame, in);
                ScriptedFrameInput up;
                up.leftDown = false;
                add(frame + 1, up);
                continue;
            }
        } else if (what == "drag") {
            int steps = 4;
            if (!(words >> x0 >> y0 >> x1 >> y1)) throw bad("drag takes X0 Y0 X1 Y1 [frames]");
            if (words >> steps) {
                if (steps < 1 || steps > 1000) throw bad("drag takes 1 to 1000 frames");
            }
            in.mouseX = x0;
            in.mouseY = y0;
            add(frame, in);  // over the start first, so the press lands there
            ScriptedFrameInput press;
            press.leftDown = true;
            add(frame + 1, press);
            for (int i = 1; i <= steps; ++i) {
                ScriptedFrameInput m;
                m.mouseX = x0 + (x1 - x0) * static_cast<float>(i) / static_cast<float>(steps);
                m.mouseY = y0 + (y1 - y0) * static_cast<float>(i) / static_cast<float>(steps);
                add(frame + 1 + i, m);
            }
            ScriptedFrameInput release;
            release.leftDown = false;
            add(frame + 2 + steps, release);
            continue;
        } else if (what == "wheel") {
            if (!(words >> in.wheel)) throw bad("wheel takes a number of notches");
        } else if (what == "key") {
            std::string name;
            if (!(words >> name)) throw bad("key takes a key name");
            const int key = glfwKeyFromName(name);
            if (key < 0) throw bad("unknown key '" + name + "' (a-z, 0-9, F1-F12, Escape, Enter, Space)");
            in.keys.push_back(key);
        } else if (what == "resize") {
            int w = 0, h = 0;
            if (!(words >> w >> h) || w < 64 || h < 64 || w > 16384 || h > 16384)
                throw bad("resize takes a width and a height from 64 to 16384");
            in.resize = std::make_pair(w, h);
        } else if (what == "ctrl") {
            std::string state;
            if (!(words >> state) || (state != "down" && state != "up")) throw bad("ctrl takes down or up");
            in.ctrl = state == "down";
        } else {
            throw bad("unknown action '" + what + "' (move, click, drag, wheel, key, resize, ctrl)");
        }
        std::string extra;
        if (words >> extra) throw bad("unexpected '" + extra + "'");
        add(frame, in);
    }
    std::stable_sort(s.events_.begin(), s.events_.end(), [](const Event& a, const Event& b) { return a.frame < b.frame; });
    return s;
}

ScriptedFrameInput ScriptedInput::at(int frame) const {
    ScriptedFrameInput out;
    for (const auto& e : events_) {
        if (e.frame != frame) continue;
        if (e.input.mouseX) out.mouseX = e.input.mouseX;
        if (e.input.mouseY) out.mouseY = e.input.mouseY;
        if (e.input.leftDown) out.leftDown = e.input.leftDown;
        out.wheel += e.input.wheel;
        out.keys.insert(out.keys.end(), e.input.keys.begin(), e.input.keys.end());
        if (e.input.resize) out.resize = e.input.resize;
        if (e.input.ctrl) out.ctrl = e.input.ctrl;
    }
    return out;
}

int ScriptedInput::lastFrame() const { return events_.empty() ? -1 : events_.back().frame; }

}  // namespace dw
