#include "app/ScriptedInput.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <functional>
#include <sstream>

#include "headless/CommandLine.h"
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
    static const std::pair<const char*, int> named[] = {
        {"Escape", GLFW_KEY_ESCAPE}, {"Enter", GLFW_KEY_ENTER},         {"Space", GLFW_KEY_SPACE},
        {"Tab", GLFW_KEY_TAB},       {"Backspace", GLFW_KEY_BACKSPACE}, {"Delete", GLFW_KEY_DELETE},
        {"Home", GLFW_KEY_HOME},     {"End", GLFW_KEY_END},             {"Left", GLFW_KEY_LEFT},
        {"Right", GLFW_KEY_RIGHT},   {"Up", GLFW_KEY_UP},               {"Down", GLFW_KEY_DOWN},
        {"PageUp", GLFW_KEY_PAGE_UP}, {"PageDown", GLFW_KEY_PAGE_DOWN}};
    for (const auto& [n, k] : named)
        if (name == n) return k;
    return -1;
}

ScriptedKey scriptedKeyForChar(char32_t c) {
    if (c >= 'a' && c <= 'z') return {GLFW_KEY_A + static_cast<int>(c - 'a'), 0};
    if (c >= 'A' && c <= 'Z') return {GLFW_KEY_A + static_cast<int>(c - 'A'), GLFW_MOD_SHIFT};
    if (c >= '0' && c <= '9') return {GLFW_KEY_0 + static_cast<int>(c - '0'), 0};
    static const std::pair<char32_t, ScriptedKey> keys[] = {
        {' ', {GLFW_KEY_SPACE, 0}},  {'.', {GLFW_KEY_PERIOD, 0}},           {'/', {GLFW_KEY_SLASH, 0}},
        {'-', {GLFW_KEY_MINUS, 0}},  {'_', {GLFW_KEY_MINUS, GLFW_MOD_SHIFT}}, {',', {GLFW_KEY_COMMA, 0}},
        {'=', {GLFW_KEY_EQUAL, 0}},  {'+', {GLFW_KEY_EQUAL, GLFW_MOD_SHIFT}}, {':', {GLFW_KEY_SEMICOLON, GLFW_MOD_SHIFT}}};
    for (const auto& [ch, k] : keys)
        if (ch == c) return k;
    return {};
}

namespace {

// UTF-8 to code points; a malformed byte stands for itself.
std::u32string decodeUtf8(const std::string& s) {
    std::u32string out;
    for (size_t i = 0; i < s.size();) {
        const auto b = static_cast<unsigned char>(s[i]);
        const int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
        char32_t c = extra ? (b & (0x3F >> extra)) : b;
        bool ok = i + extra < s.size();
        for (int k = 1; ok && k <= extra; ++k) {
            const auto n = static_cast<unsigned char>(s[i + k]);
            ok = (n & 0xC0) == 0x80;
            c = (c << 6) | (n & 0x3F);
        }
        if (!ok) c = b;
        out.push_back(c);
        i += ok ? extra + 1 : 1;
    }
    return out;
}

// The rest of the line after the action word and one space.
std::string restOfLine(std::istringstream& words) {
    std::string rest;
    std::getline(words, rest);
    if (!rest.empty() && rest[0] == ' ') rest.erase(0, 1);
    while (!rest.empty() && (rest.back() == '\r' || rest.back() == '\n')) rest.pop_back();
    return rest;
}

}  // namespace

ScriptedInput ScriptedInput::load(const std::string& path) {
    return parse(readWholeFile(path, "events file not found", "cannot read events file"), path);
}

namespace {

using Add = std::function<void(int, ScriptedFrameInput)>;
using Bad = std::function<UsageError(const std::string&)>;

// A click: over the point first, as a hand gets there (a widget that wants
// to have been hovered the frame before, ImGui's overlapping selectables,
// takes the press a frame later), then press and release.
void addClick(int frame, float x, float y, const Add& add) {
    ScriptedFrameInput over;
    over.mouseX = x;
    over.mouseY = y;
    add(frame, over);
    ScriptedFrameInput down;
    down.leftDown = true;
    add(frame + 1, down);
    ScriptedFrameInput up;
    up.leftDown = false;
    add(frame + 2, up);
}

// A drag: over the start first, so the press lands there; `steps` moves; release.
void addDrag(int frame, std::istringstream& words, const Add& add, const Bad& bad) {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int steps = 4;
    if (!(words >> x0 >> y0 >> x1 >> y1)) throw bad("drag takes X0 Y0 X1 Y1 [frames]");
    if (words >> steps) {
        if (steps < 1 || steps > 1000) throw bad("drag takes 1 to 1000 frames");
    }
    ScriptedFrameInput start;
    start.mouseX = x0;
    start.mouseY = y0;
    add(frame, start);
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
}

// "ctrl+shift+F5": the key and its modifiers.
std::pair<int, int> parseKey(std::istringstream& words, const Bad& bad) {
    std::string name;
    if (!(words >> name)) throw bad("key takes a key name");
    int mods = 0;
    for (size_t plus; (plus = name.find('+')) != std::string::npos && plus + 1 < name.size();) {
        const std::string mod = name.substr(0, plus);
        if (mod == "ctrl") mods |= GLFW_MOD_CONTROL;
        else if (mod == "shift") mods |= GLFW_MOD_SHIFT;
        else if (mod == "alt") mods |= GLFW_MOD_ALT;
        else if (mod == "super") mods |= GLFW_MOD_SUPER;
        else throw bad("unknown modifier '" + mod + "' (ctrl, shift, alt, super)");
        name.erase(0, plus + 1);
    }
    const int key = glfwKeyFromName(name);
    if (key < 0)
        throw bad("unknown key '" + name +
                  "' (a-z, 0-9, F1-F12, Escape, Enter, Space, Tab, Backspace, Delete, Home, End, arrows, PageUp, PageDown)");
    return {key, mods};
}

// `type TEXT` / `drop PATH`: the rest of the line, at most kMaxTypedBytes.
void addTypedOrDropped(int frame, const std::string& what, std::istringstream& words, const Add& add, const Bad& bad) {
    const std::string rest = restOfLine(words);
    if (rest.empty()) throw bad(what + (what == "type" ? " takes the text to type" : " takes a file path"));
    // A person types a line at a time: a line of megabytes became
    // gigabytes of queued key events (10 MB: 1.15 GB resident).
    if (rest.size() > kMaxTypedBytes)
        throw bad(what + " takes at most " + std::to_string(kMaxTypedBytes) + " bytes on a line, got " +
                  std::to_string(rest.size()));
    ScriptedFrameInput in;
    if (what == "type") in.text = decodeUtf8(rest);
    else in.drops.push_back(rest);
    add(frame, in);
}

// The one-frame actions (move, wheel, key, resize, set, ctrl) into `in`.
void parseFrameAction(const std::string& what, std::istringstream& words, ScriptedFrameInput& in, const Bad& bad) {
    if (what == "move") {
        float x = 0, y = 0;
        if (!(words >> x >> y)) throw bad(what + " takes X Y");
        in.mouseX = x;
        in.mouseY = y;
    } else if (what == "wheel") {
        if (!(words >> in.wheel)) throw bad("wheel takes a number of notches");
    } else if (what == "key") {
        in.keys.push_back(parseKey(words, bad));
    } else if (what == "resize") {
        int w = 0, h = 0;
        if (!(words >> w >> h) || w < 64 || h < 64 || w > 16384 || h > 16384)
            throw bad("resize takes a width and a height from 64 to 16384");
        in.resize = std::make_pair(w, h);
    } else if (what == "set") {
        // A knob edited as the Parameters panel edits it (no widget positions to chase).
        std::string assignment;
        if (!(words >> assignment) || assignment.find('=') == std::string::npos) throw bad("set takes knob=value");
        in.sets.push_back(assignment);
    } else if (what == "ctrl") {
        std::string state;
        if (!(words >> state) || (state != "down" && state != "up")) throw bad("ctrl takes down or up");
        in.ctrl = state == "down";
    } else {
        throw bad("unknown action '" + what + "' (move, click, drag, wheel, key, type, drop, resize, ctrl, set)");
    }
    std::string extra;
    if (words >> extra) throw bad("unexpected '" + extra + "'");
}

}  // namespace

ScriptedInput ScriptedInput::parse(const std::string& text, const std::string& source) {
    ScriptedInput s;
    std::istringstream lines(text);
    std::string line;
    int number = 0;
    const Add add = [&](int frame, ScriptedFrameInput in) { s.events_.push_back({frame, std::move(in)}); };
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
        const Bad bad = [&](const std::string& why) {
            return UsageError(source + ": line " + std::to_string(number) + ": " + why);
        };
        if (frame < 0) throw bad("the frame must be 0 or more");
        if (!(words >> what)) throw bad("no action after the frame number");
        if (what == "click") {
            float x = 0, y = 0;
            if (!(words >> x >> y)) throw bad(what + " takes X Y");
            addClick(frame, x, y, add);
        } else if (what == "drag") {
            addDrag(frame, words, add, bad);
        } else if (what == "type" || what == "drop") {
            addTypedOrDropped(frame, what, words, add, bad);
        } else {
            ScriptedFrameInput in;
            parseFrameAction(what, words, in, bad);
            add(frame, in);
        }
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
        out.text += e.input.text;
        out.drops.insert(out.drops.end(), e.input.drops.begin(), e.input.drops.end());
        if (e.input.resize) out.resize = e.input.resize;
        if (e.input.ctrl) out.ctrl = e.input.ctrl;
        out.sets.insert(out.sets.end(), e.input.sets.begin(), e.input.sets.end());
    }
    return out;
}

int ScriptedInput::lastFrame() const { return events_.empty() ? -1 : events_.back().frame; }

}  // namespace dw
