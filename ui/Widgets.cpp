#include "ui/Widgets.h"

namespace dw::ui {

const ImVec4 kErrorColor(1.0f, 0.42f, 0.38f, 1.0f);
const ImVec4 kDimColor(0.6f, 0.6f, 0.62f, 1.0f);
const ImVec4 kOkColor(0.55f, 0.85f, 0.55f, 1.0f);

void image(unsigned texture, ImVec2 size) { ImGui::Image(textureId(texture), size, ImVec2(0, 1), ImVec2(1, 0)); }

void helpMarker(const std::string& text) {
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
        ImGui::TextUnformatted(text.c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

void wrappedColored(const ImVec4& color, const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, color);
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

}  // namespace dw::ui

namespace dw::ui {

bool beginPanel(const char* title, bool* open, ImGuiWindowFlags extra) {
    return ImGui::Begin(title, open,
                        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                            ImGuiWindowFlags_NoSavedSettings | extra);
}

bool inputTextEnter(const char* label, const char* hint, char* buffer, size_t size, int flags) {
    ImGui::InputTextWithHint(label, hint, buffer, size, flags);
    return ImGui::IsItemDeactivated() && (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)) ||
                                          ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter)));
}

void recordItemRect(std::map<std::string, glm::vec4>& rects, const std::string& name) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    rects[name] = glm::vec4(a.x, a.y, b.x - a.x, b.y - a.y);
}

void sameLineIfFits(float width) {
    const float right = ImGui::GetWindowContentRegionMax().x + ImGui::GetWindowPos().x;
    ImGui::SameLine();
    if (ImGui::GetCursorScreenPos().x + width > right) ImGui::NewLine();
}

void clippedText(const std::string& text, float width) {
    if (ImGui::CalcTextSize(text.c_str()).x <= width) {
        ImGui::TextUnformatted(text.c_str());
        return;
    }
    std::string cut = text;
    while (!cut.empty() && ImGui::CalcTextSize((cut + "...").c_str()).x > width) cut.pop_back();
    ImGui::TextUnformatted((cut + "...").c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text.c_str());
}

}  // namespace dw::ui
