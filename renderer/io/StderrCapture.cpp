#include "renderer/io/StderrCapture.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace dw {

namespace {

constexpr bool sanitized() {
#if defined(__SANITIZE_ADDRESS__)
    return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return true;
#else
    return false;
#endif
#else
    return false;
#endif
}

}  // namespace

StderrCapture::StderrCapture() {
    if (sanitized()) return;
    std::fflush(stderr);
    char name[] = "/tmp/dw-stderr-XXXXXX";
    file_ = ::mkstemp(name);
    if (file_ < 0) return;
    ::unlink(name);
    saved_ = ::dup(2);
    if (saved_ < 0 || ::dup2(file_, 2) < 0) {
        if (saved_ >= 0) ::close(saved_);
        ::close(file_);
        saved_ = file_ = -1;
    }
}

StderrCapture::~StderrCapture() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_, 2);
    ::close(saved_);
    ::close(file_);
}

std::string StderrCapture::text() {
    if (file_ < 0) return {};
    std::fflush(stderr);
    std::string out;
    char buf[512];
    for (off_t at = 0;;) {
        const ssize_t n = ::pread(file_, buf, sizeof buf, at);
        if (n <= 0) break;
        out.append(buf, static_cast<size_t>(n));
        at += n;
    }
    return out;
}

}  // namespace dw
