#include "renderer/scene/ClipChoice.h"

#include <algorithm>
#include <cctype>

#include "renderer/Error.h"
#include "renderer/scene/Animation.h"

namespace dw {

std::string clipList(const SceneAnimation& anim) {
    if (anim.clips.empty()) return "none";
    std::string out;
    for (std::size_t c = 0; c < anim.clips.size(); ++c)
        out += (c ? ", " : "") + std::to_string(c) + " '" + anim.clips[c].name + "'";
    return out;
}

std::string clipChoiceOf(const SceneAnimation& anim) {
    if (anim.clips.empty() || anim.playing.empty()) return "";
    const int playing = anim.playing[0];
    if (playing < 0) return "none";
    for (std::size_t c = 0; c < anim.clips.size(); ++c)
        if (anim.clips[c].file == 0) return static_cast<int>(c) == playing ? "" : std::to_string(playing);
    return std::to_string(playing);
}

namespace {

bool allDigits(const std::string& s) {
    return !s.empty() && s.size() < 10 && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

// The clip `spec` names, or -1 with `why` set.
int findClip(const SceneAnimation& anim, const std::string& spec) {
    if (allDigits(spec)) {
        const int index = std::stoi(spec);
        return index < static_cast<int>(anim.clips.size()) ? index : -1;
    }
    for (std::size_t c = 0; c < anim.clips.size(); ++c)
        if (anim.clips[c].name == spec) return static_cast<int>(c);
    return -1;
}

}  // namespace

void chooseClip(SceneAnimation& anim, const std::string& spec) {
    if (spec.empty()) return;
    if (spec == "none") {
        std::fill(anim.playing.begin(), anim.playing.end(), -1);
        anim.posedAt = -1.0;
        return;
    }
    const int clip = findClip(anim, spec);
    if (clip < 0 && anim.clips.empty())
        throw Error("--animation '" + spec + "': the scene has no animation clips (only none)");
    if (clip < 0)
        throw Error("--animation '" + spec + "': the scene has no such clip; its clips: " + clipList(anim) +
                    " (or none)");
    const auto file = static_cast<std::size_t>(anim.clips[static_cast<std::size_t>(clip)].file);
    if (anim.playing.size() <= file) anim.playing.resize(file + 1, -1);
    anim.playing[file] = clip;
    anim.posedAt = -1.0;
}

}  // namespace dw
