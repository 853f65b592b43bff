#pragma once
// A domain of the MemoryLedger (gl/MemoryLedger.h): the allocations made on
// this thread while a MemoryDomain scope is alive belong to its key (a
// RenderSession: its address), with live and peak bytes of their own, so one
// session's peak is read in a process that holds several (bench: a session
// per render size). Deletion gives the bytes back to the domain that
// allocated them, wherever it happens.
#include <cstddef>

namespace dw::gl {

class MemoryDomain {
public:
    explicit MemoryDomain(const void* key);
    ~MemoryDomain();
    MemoryDomain(const MemoryDomain&) = delete;
    MemoryDomain& operator=(const MemoryDomain&) = delete;
};

// Live bytes of `key`'s domain now, and the largest since resetDomainPeak(key).
std::size_t domainLiveBytes(const void* key);
std::size_t domainPeakBytes(const void* key);
// Starts `key`'s new peak at its live bytes (a session's next configuration).
void resetDomainPeak(const void* key);

}  // namespace dw::gl
