#include "renderer/inspect/MemoryTable.h"

#include <cstdio>

#include "renderer/gl/MemoryLedger.h"

namespace dw {

namespace {
const std::string kFrameGraphPrefix = "frame graph: ";

double mib(std::size_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); }
}  // namespace

MemoryTable MemoryTable::build(const std::vector<ResourceRecord>& resources) {
    MemoryTable t;
    for (const ResourceRecord& r : resources)
        t.rows.push_back({kFrameGraphPrefix + r.name, true, r.bytes, 1, describe(r.desc, r.desc.width, r.desc.height)});
    const gl::MemoryLedger& ledger = gl::MemoryLedger::instance();
    for (const gl::OwnerBytes& o : ledger.byOwner())
        if (o.owner.rfind(kFrameGraphPrefix, 0) != 0) t.rows.push_back({o.owner, false, o.bytes, o.objects, {}});
    for (const MemoryRow& r : t.rows) t.total += r.bytes;
    t.ledgerLive = ledger.liveBytes();
    t.ledgerPeak = ledger.peakBytes();
    return t;
}

const MemoryRow* MemoryTable::find(const std::string& owner) const {
    for (const MemoryRow& r : rows)
        if (r.owner == owner) return &r;
    return nullptr;
}

std::size_t MemoryTable::frameGraphBytes() const {
    std::size_t b = 0;
    for (const MemoryRow& r : rows) b += r.frameGraph ? r.bytes : 0;
    return b;
}

std::string MemoryTable::text() const {
    std::string out = "GPU memory (logical bytes: format x size x levels x layers x samples; exact counts):\n";
    char line[320];
    for (const MemoryRow& r : rows) {
        std::snprintf(line, sizeof line, "  %-40s %9.2f MiB %4d object%s%s%s\n", r.owner.c_str(), mib(r.bytes),
                      r.objects, r.objects == 1 ? " " : "s", r.detail.empty() ? "" : "  ", r.detail.c_str());
        out += line;
    }
    std::snprintf(line, sizeof line,
                  "  total %.2f MiB (%zu bytes: frame graph %.2f MiB, passes, services and scene %.2f MiB); "
                  "allocated now %zu bytes, peak %.2f MiB\n",
                  mib(total), total, mib(frameGraphBytes()), mib(total - frameGraphBytes()), ledgerLive, mib(ledgerPeak));
    out += line;
    return out;
}

}  // namespace dw
