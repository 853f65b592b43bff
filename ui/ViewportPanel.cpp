#include "ui/ViewportPanel.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>

#include "renderer/scene/CameraController.h"
#include "ui/AbSplitView.h"
#include "ui/ImageViewer.h"
#include "ui/Widgets.h"

namespace dw::ui {

namespace {

const char* modeName(DisplayMode m) {
    switch (m) {
        case DisplayMode::Deferred: return "deferred";
        case DisplayMode::Textured: return "textured (forward)";
        case DisplayMode::Wireframe: return "wireframe (forward)";
    }
    return "";
}

void toggleAnimation(UiState& state, RenderSession& session) {
    if (state.animator.running()) state.animator.stop(session.mutableScene());
    else state.animator.start(session.scene());
}

// The toolbar: the display mode, the output, the overlays, the animation,
// the resolution scale and the camera line; it wraps where the panel is narrow.
void toolbar(UiState& state, RenderSession& session) {
    ViewportView& v = state.viewport;
    ImGui::SetNextItemWidth(150);
    if (ImGui::BeginCombo("##mode", modeName(v.mode))) {
        for (DisplayMode m : {DisplayMode::Deferred, DisplayMode::Textured, DisplayMode::Wireframe})
            if (ImGui::Selectable(modeName(m), v.mode == m)) v.mode = m;
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::BeginDisabled(v.mode != DisplayMode::Deferred);
    ImGui::SetNextItemWidth(170);
    if (ImGui::BeginCombo("##output", v.output.c_str())) {
        for (const auto& o : session.pipeline().outputs().all())
            if (ImGui::Selectable(o.decl.name.c_str(), o.decl.name == v.output)) v.show(o.decl.name);
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    // The toolbar wraps where the panel is narrow: nothing is cut off.
    const ImGuiStyle& style = ImGui::GetStyle();
    auto checkboxWidth = [&](const char* label) {
        return ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
    };
    sameLineIfFits(checkboxWidth("volumes") + style.ItemSpacing.x + ImGui::GetFontSize() * 6.0f);
    ImGui::Checkbox("volumes", &v.overlay.lightVolumes);
    ImGui::SameLine();
    const char* filters[] = {"at probe", "all", "selected"};
    int filter = static_cast<int>(v.volumes);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
    if (ImGui::Combo("##volumes", &filter, filters, 3)) v.volumes = static_cast<VolumeFilter>(filter);
    if (ImGui::IsItemHovered())
        tooltip("which light volumes: those containing the probed pixel's surface (hover or pin),\n"
                          "every light's, or the one selected in the Lights panel");
    sameLineIfFits(checkboxWidth("axes"));
    ImGui::Checkbox("axes", &v.overlay.axes);
    sameLineIfFits(checkboxWidth("animate lights"));
    bool animate = state.animator.running();
    if (ImGui::Checkbox("animate lights", &animate)) toggleAnimation(state, session);
    const bool autoScale = v.resolution == ResolutionScale::Auto;
    const bool software = !v.softwareStart.empty() && autoScale;
    sameLineIfFits(ImGui::GetFontSize() * (autoScale ? 9.5f : 4.5f) + style.ItemSpacing.x +
                   (software ? ImGui::CalcTextSize("software GL: reduced full").x + 3 * style.ItemSpacing.x : 0.0f));
    const char* scales[] = {"full", "1/2", "1/4", "auto"};
    int scale = static_cast<int>(v.resolution);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 4.5f);
    if (ImGui::Combo("##resolution", &scale, scales, 4)) v.resolution = static_cast<ResolutionScale>(scale);
    if (ImGui::IsItemHovered())
        tooltip("render resolution against the panel: full, half, quarter, or auto, which steps the scale\n"
                          "to keep the GPU frame under %.0f ms (frozen while timings are recorded)",
                          static_cast<double>(v.frameTargetMs));
    if (autoScale) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5.0f);
        ImGui::DragFloat("##target", &v.frameTargetMs, 5.0f, 10.0f, 5000.0f, "%.0f ms");
    }
    if (software) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1.0f), "software GL: reduced");
        if (ImGui::IsItemHovered())
            tooltip("%s rasterises on the CPU: a full-resolution frame takes seconds, so the viewport\n"
                              "renders at a scale that keeps a frame under %.0f ms. 'full' renders every pixel.",
                              v.softwareStart.c_str(), static_cast<double>(v.frameTargetMs));
        ImGui::SameLine();
        if (ImGui::SmallButton("full")) v.resolution = ResolutionScale::Full;
        noteItem("viewport.full_resolution");
    }
    char info[160];
    std::snprintf(info, sizeof(info), "| %s camera | %dx%d (x%.2g)%s", v.camera == CameraMode::Orbit ? "orbit" : "fly",
                  state.renderSize.x, state.renderSize.y, static_cast<double>(v.scale()), state.timingCapture ? " | recording" : "");
    // Fitted by its widest form, so a new render size cannot wrap the toolbar
    // and so change the render size again.
    sameLineIfFits(ImGui::CalcTextSize("| orbit camera | 00000x00000 (x0.00) | recording").x);
    ImGui::TextDisabled("%s", info);
}

// The camera from the mouse over the image (Ctrl belongs to the image's zoom and pan).
void cameraFromMouse(const ViewportView& v, Camera& cam, bool hovered, bool active, bool dividerHeld) {
    ImGuiIO& io = ImGui::GetIO();
    if (active && !io.KeyCtrl && !dividerHeld) {
        const ImVec2 d = io.MouseDelta;
        if (v.camera == CameraMode::Orbit) {
            if (ImGui::IsMouseDown(ImGuiMouseButton_Middle) || (ImGui::IsMouseDown(ImGuiMouseButton_Left) && io.KeyShift))
                camera::pan(cam, -d.x * 0.0015f, d.y * 0.0015f);
            else if (ImGui::IsMouseDown(ImGuiMouseButton_Left))
                camera::orbit(cam, -d.x * 0.004f, d.y * 0.004f);
        } else if (ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
            camera::look(cam, d.x * 0.004f, -d.y * 0.004f);
        }
    }
    if (hovered && io.MouseWheel != 0.0f && !io.KeyCtrl) {
        if (v.camera == CameraMode::Orbit) camera::zoom(cam, std::pow(0.88f, io.MouseWheel));
        else camera::fly(cam, glm::vec3(0, 0, io.MouseWheel * std::max(camera::distance(cam), 1.0f) * 0.1f));
    }
}

// Probe: hover reads the pixel under the cursor, a click (not a drag) pins
// it; a pinned pixel is marked (on `dl`). `origin`, `avail`: the image box.
void probeFromMouse(UiState& state, ImVec2 origin, ImVec2 avail, const ImagePlacement& placed, bool hovered, bool dividerHeld,
                    ImDrawList* dl) {
    ImGuiIO& io = ImGui::GetIO();
    const ImVec2 imgMin(placed.min.x, placed.min.y), imgSize(placed.size.x, placed.size.y);
    state.probe.hovering = false;
    if (hovered && imgSize.x > 0 && state.renderSize.x > 0) {
        const float u = (io.MousePos.x - imgMin.x) / imgSize.x, w = (io.MousePos.y - imgMin.y) / imgSize.y;
        const bool inBox = io.MousePos.x >= origin.x && io.MousePos.y >= origin.y && io.MousePos.x < origin.x + avail.x &&
                           io.MousePos.y < origin.y + avail.y;
        if (inBox && u >= 0 && u < 1 && w >= 0 && w < 1) {
            const glm::ivec2 px(static_cast<int>(u * state.renderSize.x), static_cast<int>(w * state.renderSize.y));
            if (!state.probe.pinned) {
                state.probe.pixel = px;
                state.probe.uv = glm::vec2(u, w);
            }
            state.probe.hovering = true;
            // ImGui tracks how far the mouse went while the button was down;
            // an orbit (a drag past the drag threshold) must not pin the probe.
            const float still = io.MouseDragThreshold * io.MouseDragThreshold;
            if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] <= still &&
                !dividerHeld) {
                state.probe.pinned = true;
                state.probe.pixel = px;
                state.probe.uv = glm::vec2(u, w);
            }
        }
    }
    if (state.probe.pinned && imgSize.x > 0) {
        const ImVec2 p(imgMin.x + state.probe.uv.x * imgSize.x, imgMin.y + state.probe.uv.y * imgSize.y);
        dl->AddCircle(p, 6.0f, IM_COL32(255, 255, 0, 255), 12, 1.5f);
    }
}

// The newest error, over the image box (`origin`, `avail`), until dismissed.
void errorBanner(UiState& state, ImVec2 origin, ImVec2 avail) {
    const Message* m = state.log.banner();
    if (!m) return;
    const ImGuiStyle& style = ImGui::GetStyle();
    ImGui::SetCursorScreenPos(ImVec2(origin.x + 8, origin.y + 8));
    ImGui::PushStyleColor(ImGuiCol_ChildBg, ImVec4(0.35f, 0.05f, 0.05f, 0.92f));
    const float width = std::max(avail.x - 16, 50.0f);
    const float textHeight = ImGui::CalcTextSize(m->text.c_str(), nullptr, false, width - 2 * style.WindowPadding.x).y;
    const float height = std::min(textHeight + ImGui::GetFrameHeightWithSpacing() + 2 * style.WindowPadding.y + 4,
                                  std::max(avail.y - 16, 40.0f));
    ImGui::BeginChild("##banner", ImVec2(width, height), true);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(m->text.c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::SmallButton("dismiss")) state.log.dismissBanner();
    ImGui::EndChild();
    ImGui::PopStyleColor();
}

}  // namespace

void ViewportPanel::draw(const char* title, bool* open, UiState& state, RenderSession& session) {
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(2, 2));
    const bool visible = beginPanel(title, open, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PopStyleVar();
    if (!visible) {
        ImGui::End();
        return;
    }
    ViewportView& v = state.viewport;
    toolbar(state, session);
    // The A/B split's controls and numbers (AbSplitView). The numbers' lines
    // take room from the image box, not from the render: turning the split on
    // once shrank the frame by a few rows, which withdrew a CPU reference just
    // traced and failed the frame that asked for it.
    const float abNumbers = v.mode == DisplayMode::Deferred ? abControls(state) : 0.0f;
    // The texture viewer's controls for what is shown, at the top of the view.
    const PublishedOutput* shownOutput =
        v.mode == DisplayMode::Deferred && v.output != "final" ? session.pipeline().outputs().find(v.output) : nullptr;
    const float belowToolbar = ImGui::GetContentRegionAvail().y + abNumbers;
    imageViewControls(v, shownOutput, state.viewportImage, "viewport");
    // The render size is the room below the toolbar and one row of the
    // viewer's controls (a buffer's combos are taller than the final image's
    // zoom buttons), which are there whatever is shown: the colour bar and
    // the histogram of a buffer take room from the image box, not from the
    // render, so looking at a buffer keeps the frame size (and the timings
    // comparable) and the image fits the smaller box.
    const ImVec2 room(ImGui::GetContentRegionAvail().x, belowToolbar - ImGui::GetFrameHeightWithSpacing());
    state.wantedSize = glm::ivec2(std::max(16, static_cast<int>(room.x)), std::max(16, static_cast<int>(room.y)));
    imageViewLegend(v, shownOutput, state.viewportImage);

    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##viewport", ImVec2(std::max(avail.x, 1.0f), std::max(avail.y, 1.0f)),
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
    const bool hovered = ImGui::IsItemHovered();
    const bool active = ImGui::IsItemActive();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    // The image fits the box, keeping its aspect ratio (the render size
    // follows the panel a frame later), then zoomed and panned by the view.
    const ImagePlacement placed = drawImageView(v, state.viewportImage, origin, ImVec2(std::max(avail.x, 1.0f), std::max(avail.y, 1.0f)),
                                                state.nearestSampler, hovered, active);
    // B right of the divider; while the divider has the mouse, the camera and the probe leave it alone.
    const bool dividerHeld = v.mode == DisplayMode::Deferred && v.output == "final" &&
                             drawAbSplit(state, origin, ImVec2(std::max(avail.x, 1.0f), std::max(avail.y, 1.0f)), placed, hovered);

    cameraFromMouse(v, session.camera(), hovered, active, dividerHeld);
    probeFromMouse(state, origin, avail, placed, hovered, dividerHeld, dl);
    errorBanner(state, origin, avail);
    ImGui::End();
}

void handleShortcuts(UiState& state, RenderSession& session, float dt) {
    ImGuiIO& io = ImGui::GetIO();
    // A key with exactly these modifiers (Shift aside) was pressed this frame.
    auto pressed = [&](int key, int mods = 0) {
        constexpr int kCommand = GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER;
        for (const auto& [k, m] : state.keyPresses)
            if (k == key && (m & kCommand) == mods) return true;
        return false;
    };
    // Ctrl shortcuts work while a text field is being typed in too.
    if (pressed(GLFW_KEY_Q, GLFW_MOD_CONTROL)) state.requestQuit = true;
    if (pressed(GLFW_KEY_O, GLFW_MOD_CONTROL)) state.requestOpenScene = true;
    // Keys typed into a text field are the field's, not shortcuts.
    if (io.WantTextInput) return;
    Camera& cam = session.camera();
    ViewportView& v = state.viewport;
    const bool flying = v.camera == CameraMode::Fly && ImGui::IsMouseDown(ImGuiMouseButton_Right);
    // Held keys move with the frame time; a tap shorter than a frame moves one step.
    auto amount = [&](int key, float perSecond, float step) {
        if (ImGui::IsKeyDown(key)) return perSecond * dt;
        return pressed(key) ? step : 0.0f;
    };
    const float step = glm::radians(5.0f);
    camera::orbit(cam, amount(GLFW_KEY_RIGHT, 1.5f, step) - amount(GLFW_KEY_LEFT, 1.5f, step),
                  amount(GLFW_KEY_UP, 1.5f, step) - amount(GLFW_KEY_DOWN, 1.5f, step));
    const float in = amount(GLFW_KEY_EQUAL, 1.0f, 0.15f) + amount(GLFW_KEY_KP_ADD, 1.0f, 0.15f);
    const float out = amount(GLFW_KEY_MINUS, 1.0f, 0.15f) + amount(GLFW_KEY_KP_SUBTRACT, 1.0f, 0.15f);
    if (in > 0.0f || out > 0.0f) camera::zoom(cam, std::pow(2.0f, out - in));
    if (flying) {
        const float speed = std::max(camera::distance(cam), 2.0f) * dt * (io.KeyShift ? 3.0f : 1.0f);
        glm::vec3 move(0.0f);
        if (ImGui::IsKeyDown(GLFW_KEY_W)) move.z += speed;
        if (ImGui::IsKeyDown(GLFW_KEY_S)) move.z -= speed;
        if (ImGui::IsKeyDown(GLFW_KEY_D)) move.x += speed;
        if (ImGui::IsKeyDown(GLFW_KEY_A)) move.x -= speed;
        if (ImGui::IsKeyDown(GLFW_KEY_E)) move.y += speed;
        if (ImGui::IsKeyDown(GLFW_KEY_Q)) move.y -= speed;
        camera::fly(cam, move);
        return;  // WASD belong to flying while the right button is held
    }
    if (pressed(GLFW_KEY_A)) v.overlay.axes = !v.overlay.axes;
    if (pressed(GLFW_KEY_D)) v.mode = DisplayMode::Deferred;
    if (pressed(GLFW_KEY_T)) v.mode = DisplayMode::Textured;
    if (pressed(GLFW_KEY_W)) v.mode = DisplayMode::Wireframe;
    if (pressed(GLFW_KEY_V)) v.overlay.lightVolumes = !v.overlay.lightVolumes;
    if (pressed(GLFW_KEY_F)) v.camera = v.camera == CameraMode::Orbit ? CameraMode::Fly : CameraMode::Orbit;
    if (pressed(GLFW_KEY_L)) toggleAnimation(state, session);
    if (pressed(GLFW_KEY_F5)) state.requestReloadShaders = true;
    if (pressed(GLFW_KEY_F12)) state.requestScreenshot = true;
    if (pressed(GLFW_KEY_F11)) state.requestRenderDocCapture = true;
    if (pressed(GLFW_KEY_F9)) state.requestReference = true;
    if (pressed(GLFW_KEY_B)) {
        state.ab.enabled = !state.ab.enabled;
        ++state.ab.generation;
    }
    if (pressed(GLFW_KEY_P)) state.ab.pinRequest = true;
    if (pressed(GLFW_KEY_ESCAPE)) state.probe.pinned = false;
}

const char* shortcutHelp() {
    return "Camera (orbit): arrows rotate, + / - zoom, left drag rotates, middle or shift+left drag pans, wheel zooms\n"
           "Camera (fly):   hold the right button: mouse looks, W A S D move, Q E down/up, shift faster; wheel moves\n"
           "f     orbit / fly camera\n"
           "d     deferred shading          t  textured (forward)        w  wireframe (forward)\n"
           "a     world axes                 v  light-volume wireframes   l  animate lights\n"
           "click pin the pixel probe        Esc unpin\n"
           "b     A/B split view (drag its divider)   p  pin the current image as B\n"
           "F5    reload changed shaders (errors show in Messages; the last good program stays)\n"
           "F9    CPU reference of this view, in the background (then reference.* and compare.error)\n"
           "F11   capture the next frame with RenderDoc (gui --renderdoc)\n"
           "F12   screenshot of the window to PNG\n"
           "Ctrl+O open a scene file (the Scene panel's path field; files dropped on the window open too)\n"
           "Ctrl+S save an experiment record of this frame   Ctrl+R open one (scene, camera, knobs)\n"
           "Ctrl+Q quit";
}

}  // namespace dw::ui
