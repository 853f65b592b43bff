#include "ui/UiState.h"

namespace dw::ui {

namespace {
constexpr size_t kMaxMessages = 200;
}

void MessageLog::push(Message m) {
    messages_.push_back(std::move(m));
    if (messages_.size() > kMaxMessages) {
        messages_.pop_front();
        if (bannerIndex_ >= 0) --bannerIndex_;
        if (toastIndex_ >= 0) --toastIndex_;
    }
}

void MessageLog::info(const std::string& text, double time) { push({time, false, text, {}}); }

void MessageLog::error(const std::string& text, double time, const std::string& action) {
    push({time, true, text, action});
    bannerIndex_ = static_cast<long>(messages_.size() - 1);
}

void MessageLog::done(const std::string& text, double time, const std::string& action) {
    push({time, false, text, action});
    toastIndex_ = static_cast<long>(messages_.size() - 1);
    succeeded(action);
}

void MessageLog::succeeded(const std::string& action) {
    if (const Message* b = banner(); b && !action.empty() && b->action == action) dismissBanner();
}

const Message* MessageLog::toast(double now) const {
    if (toastIndex_ < 0) return nullptr;
    const Message& m = messages_[static_cast<size_t>(toastIndex_)];
    return now - m.time <= kToastSeconds ? &m : nullptr;
}

}  // namespace dw::ui
