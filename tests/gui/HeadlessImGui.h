#pragma once
// A Dear ImGui context with a font atlas and no platform or renderer backend,
// its key map the GLFW backend's (GLFW key codes index io.KeysDown), for
// driving panels and widgets in tests.
#ifndef GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_NONE  // only key codes: the GL header is epoxy's
#endif
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <utility>

namespace dw::test {

class HeadlessImGui {
public:
    explicit HeadlessImGui(ImVec2 display = ImVec2(1600, 900)) {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = display;
        io.DeltaTime = 1.0f / 60.0f;
        io.IniFilename = nullptr;
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
        const std::pair<ImGuiKey, int> map[] = {
            {ImGuiKey_Tab, GLFW_KEY_TAB},     {ImGuiKey_LeftArrow, GLFW_KEY_LEFT}, {ImGuiKey_RightArrow, GLFW_KEY_RIGHT},
            {ImGuiKey_UpArrow, GLFW_KEY_UP},  {ImGuiKey_DownArrow, GLFW_KEY_DOWN}, {ImGuiKey_Home, GLFW_KEY_HOME},
            {ImGuiKey_End, GLFW_KEY_END},     {ImGuiKey_Delete, GLFW_KEY_DELETE},  {ImGuiKey_Backspace, GLFW_KEY_BACKSPACE},
            {ImGuiKey_Enter, GLFW_KEY_ENTER}, {ImGuiKey_Escape, GLFW_KEY_ESCAPE},  {ImGuiKey_KeyPadEnter, GLFW_KEY_KP_ENTER},
            {ImGuiKey_A, GLFW_KEY_A},         {ImGuiKey_C, GLFW_KEY_C},            {ImGuiKey_V, GLFW_KEY_V},
            {ImGuiKey_X, GLFW_KEY_X},         {ImGuiKey_Y, GLFW_KEY_Y},            {ImGuiKey_Z, GLFW_KEY_Z}};
        for (const auto& [k, g] : map) io.KeyMap[k] = g;
    }
    ~HeadlessImGui() { ImGui::DestroyContext(); }
    HeadlessImGui(const HeadlessImGui&) = delete;
    HeadlessImGui& operator=(const HeadlessImGui&) = delete;
    template <typename F>
    void frame(F&& draw) {
        ImGui::NewFrame();
        draw();
        ImGui::Render();
    }
};

}  // namespace dw::test
