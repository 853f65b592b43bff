#include "ui/Widgets.h"

#include <imgui_internal.h>

#include <algorithm>
#include <cstdarg>
#include <cstdio>

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

namespace {
std::map<std::string, DrawnItem>& itemTable() {
    static std::map<std::string, DrawnItem> items;
    return items;
}
}  // namespace

void noteItem(const std::string& name) { noteRect(name, ImGui::GetItemRectMin(), ImGui::GetItemRectMax()); }

void noteRect(const std::string& name, ImVec2 a, ImVec2 b) {
    DrawnItem d;
    d.x = a.x, d.y = a.y, d.w = b.x - a.x, d.h = b.y - a.y;
    d.frame = ImGui::GetFrameCount();
    const ImGuiWindow* w = ImGui::GetCurrentWindowRead();
    if (w) {
        // The root panel (an item in a table or child belongs to the panel around it).
        const ImGuiWindow* root = w->RootWindow ? w->RootWindow : w;
        d.window = root->Name;
        const ImRect clip = w->ClipRect;
        d.clipX = clip.Min.x, d.clipY = clip.Min.y, d.clipW = clip.GetWidth(), d.clipH = clip.GetHeight();
    }
    itemTable()[name] = d;
}

const std::map<std::string, DrawnItem>& drawnItems() { return itemTable(); }

void numberCell(double value, int decimals) {
    char text[48];
    std::snprintf(text, sizeof(text), "%.*f", decimals, value);
    // Right-aligned in its column, so digits line up and neighbours never touch.
    const float w = ImGui::CalcTextSize(text).x, avail = ImGui::GetContentRegionAvail().x;
    if (avail > w) ImGui::SetCursorPosX(ImGui::GetCursorPosX() + avail - w);
    ImGui::TextUnformatted(text);
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
    if (ImGui::IsItemHovered()) tooltip("%s", text.c_str());
}

void tooltip(const char* format, ...) {
    char text[4096];
    va_list args;
    va_start(args, format);
    std::vsnprintf(text, sizeof(text), format, args);
    va_end(args);
    const ImGuiStyle& style = ImGui::GetStyle();
    const float margin = 2.0f * (style.WindowPadding.x + style.DisplaySafeAreaPadding.x) + 8.0f;
    const float wrap = std::max(ImGui::GetFontSize() * 10.0f,
                                std::min(ImGui::GetFontSize() * 45.0f, ImGui::GetIO().DisplaySize.x - margin));
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(wrap);
    ImGui::TextUnformatted(text);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

std::vector<std::string> breakName(const std::string& name, float width) {
    std::vector<std::string> lines;
    std::string rest = name;
    while (!rest.empty() && ImGui::CalcTextSize(rest.c_str()).x > width) {
        // The longest head that fits, ending after a '_' or '.' if one does.
        size_t fits = 1, breakAt = 0;
        while (fits < rest.size() && ImGui::CalcTextSize(rest.substr(0, fits + 1).c_str()).x <= width) ++fits;
        for (size_t i = fits; i > 0; --i)
            if (rest[i - 1] == '_' || rest[i - 1] == '.') {
                breakAt = i;
                break;
            }
        const size_t take = breakAt ? breakAt : fits;
        lines.push_back(rest.substr(0, take));
        rest = rest.substr(take);
    }
    if (!rest.empty()) lines.push_back(rest);
    return lines;
}

}  // namespace dw::ui
