#pragma once
// Keeps the window from freezing on an Ambient Occlusion Volumes frame that
// would take minutes (issue 22): before each frame, when the knobs, the
// scene, the camera or the render size changed (ViewportComposer::targetSize:
// the size this frame renders at, so the first frames and every resize of the
// panel or step of the resolution scale), it estimates AOV's volume fragments
// per pixel on the CPU (AovCostEstimate, O(triangles)). Above either limit
// (AovCostEstimate::exceeds) it puts the knobs back to the last state that was
// under it (or, if that one is over it too with this camera and size,
// switches ao.method back to its default), says so in the message log (the
// banner over the viewport), and shows a small window with the estimate and
// two buttons: render the new state anyway (it is then kept until the knobs
// change again or the frame grows past the size it was confirmed at) or keep
// the previous one. The A/B split's preset side is estimated where it
// renders (ViewportComposer: B refused, A kept); the Pareto panel's quick
// sweep estimates each of its values before it starts and asks first
// (ParetoPanel::startSweep).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace dw {
class RenderSession;
}

namespace dw::ui {

struct UiState;

class AovCostGuard {
public:
    // Before the frame renders; may change the session's knobs.
    void beforeFrame(UiState& state, RenderSession& session);
    // The confirmation window (inside an ImGui frame), when a state was refused.
    void draw(UiState& state, RenderSession& session);
    bool refusing() const { return !refused_.empty(); }
    // The window's buttons: render the refused state anyway (kept until the
    // knobs change), or keep the previous one.
    void confirm(UiState& state, RenderSession& session);
    void dismiss(UiState& state);
    const std::string& message() const { return message_; }

private:
    std::vector<double> values(const RenderSession& session) const;
    void restore(RenderSession& session, const std::vector<double>& v) const;

    std::vector<double> lastGood_;   // knob values last seen under the limit
    std::vector<double> refused_;    // the state put back, until confirmed or dismissed
    std::vector<double> confirmed_;  // a state the user chose to render anyway
    std::uint64_t checkedGeneration_ = ~0ull;
    const void* checkedScene_ = nullptr;  // with its source: a new scene may reuse the address
    std::string checkedSource_;
    glm::vec3 checkedEye_{0.0f}, checkedTarget_{0.0f};
    float checkedFov_ = 0.0f;
    glm::ivec2 checkedSize_{0, 0};     // the render size last estimated at
    double refusedPixels_ = 0.0;       // the refused state's frame size (pixels)
    double confirmedPixels_ = 0.0;     // the largest frame the confirmation covers
    double checkedAt_ = -1e9;
    std::string message_;
};

}  // namespace dw::ui
