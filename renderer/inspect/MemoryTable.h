#pragma once
// Every byte of GPU memory the renderer holds, as the inspector's memory table
// and `render --memory` show it: one row per frame-graph resource (its bytes
// from its descriptor, resourceBytes) and one per owner of what passes,
// services and the scene allocated themselves (shadow maps, light lists, the
// light table, TAA history, bloom mips, scene geometry and textures, the
// reference images ...: the MemoryLedger's owner labels), and their total.
// Bytes are logical (gl/MemoryLedger.h), exact counts: no interval. The
// total equals the ledger's live bytes when this process holds one session
// (a test asserts it); `ledgerLive` is the ledger's own count to compare.
#include <cstddef>
#include <string>
#include <vector>

#include "renderer/graph/ResourcePool.h"

namespace dw {

struct MemoryRow {
    std::string owner;   // "frame graph: gbuffer.normal", "shadow maps", "pass oit" ...
    bool frameGraph = false;
    std::size_t bytes = 0;
    int objects = 0;
    std::string detail;  // a frame-graph resource's descriptor; empty otherwise
};

struct MemoryTable {
    std::vector<MemoryRow> rows;  // frame-graph resources by name, then owners by name
    std::size_t total = 0;        // the rows' sum
    std::size_t ledgerLive = 0;   // MemoryLedger::liveBytes() when built
    std::size_t ledgerPeak = 0;   // MemoryLedger::peakBytes() when built

    // The table of `resources` (Pipeline::resources()) and the ledger's
    // owners other than the frame graph's.
    static MemoryTable build(const std::vector<ResourceRecord>& resources);
    // The row of `owner`; nullptr if it holds nothing.
    const MemoryRow* find(const std::string& owner) const;
    // Bytes of the frame-graph resources and of the other owners.
    std::size_t frameGraphBytes() const;
    // Text lines: a header, one line per row (MiB and KiB), the total and the peak.
    std::string text() const;
};

}  // namespace dw
