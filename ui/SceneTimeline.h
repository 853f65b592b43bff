#pragma once
// The window's timeline for a scene's glTF animation (issue 36): play,
// pause, scrub, speed, loop, and which of each file's animations plays. The
// scene time it keeps is what RenderSession poses the scene at
// (RenderSession::setSceneTime); a frame renders when the time moved (the
// pose changed) and, while playing, every frame, as the lights' animator.
#include <chrono>

namespace dw {
class RenderSession;
}

namespace dw::ui {

struct SceneTimeline {
    bool playing = false;
    bool loop = true;
    float speed = 1.0f;   // scene seconds per wall-clock second
    double time = 0.0;    // the scene time, seconds

    bool running() const { return playing; }
    // Moves the time on by the wall clock while playing (wrapping at the
    // playing clips' end when looping, else stopping there) and hands it to
    // the session; returns whether the scene's pose changed (a frame is due).
    bool advance(RenderSession& session);
    // The Scene panel's section: nothing for a scene without animation.
    void draw(RenderSession& session);
    // A scene opened: back to 0, paused.
    void reset();

private:
    std::chrono::steady_clock::time_point last_{};
    bool haveLast_ = false;
};

}  // namespace dw::ui
