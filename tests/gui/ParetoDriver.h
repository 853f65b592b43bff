#pragma once
// The Pareto panel a frame at a time in the window's order (the reference's
// update, then the panel), and a click on a named item as a person makes it
// (the mouse over the item's centre, pressed a frame, released the next).
// Shared by the Pareto panel's tests (GuiTest.cpp, FitBudgetTest.cpp).
#include <gtest/gtest.h>
#include <imgui.h>

#include <string>

#include "renderer/RenderSession.h"
#include "tests/gui/HeadlessImGui.h"
#include "ui/ParetoPanel.h"
#include "ui/ReferenceControls.h"
#include "ui/Widgets.h"

namespace dw::test {

struct ParetoDriver {
    HeadlessImGui& imgui;
    ui::UiState& state;
    RenderSession& session;
    ui::ParetoPanel& panel;
    ui::ReferenceControls& reference;
    ImVec2 size;
    bool open = true;

    void frame() {
        imgui.frame([&] {
            reference.update(state, session);
            ImGui::SetNextWindowPos(ImVec2(0, 0));
            ImGui::SetNextWindowSize(size);
            panel.draw("Pareto", &open, state, session);
        });
    }
    void click(const std::string& name) {
        frame();
        const auto& items = ui::drawnItems();
        ASSERT_TRUE(items.count(name)) << name;
        const ui::DrawnItem& b = items.at(name);
        ASSERT_EQ(b.frame, ImGui::GetFrameCount()) << name;
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = ImVec2(b.x + b.w * 0.5f, b.y + b.h * 0.5f);
        frame();
        io.MouseDown[0] = true;
        frame();
        io.MouseDown[0] = false;
        frame();
        io.MousePos = ImVec2(-1000, -1000);
    }
};

}  // namespace dw::test
