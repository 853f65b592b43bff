#include "ui/UiState.h"

namespace dw::ui {

namespace {
constexpr size_t kMaxMessages = 200;
}

void MessageLog::info(const std::string& text, double time) {
    messages_.push_back({time, false, text});
    if (messages_.size() > kMaxMessages) {
        messages_.pop_front();
        if (bannerIndex_ >= 0) --bannerIndex_;
    }
}

void MessageLog::error(const std::string& text, double time) {
    info(text, time);
    messages_.back().error = true;
    bannerIndex_ = static_cast<long>(messages_.size() - 1);
}

}  // namespace dw::ui
