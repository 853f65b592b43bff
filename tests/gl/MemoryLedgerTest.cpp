// Every byte of GPU memory accounted (issue 36 part 5): the GL wrapper's
// ledger (gl/MemoryLedger.h) against the inspector's memory table
// (inspect/MemoryTable.h) after a frame of the glass scene with shadows,
// the linked-list OIT, AO volumes and TAA; each owner the issue names holds
// bytes; a session's deletion gives every byte back; the logical size of
// textures of every shape by hand.
#include <gtest/gtest.h>

#include <set>

#include "renderer/gl/MemoryLedger.h"
#include "renderer/inspect/MemoryTable.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

constexpr int kW = 160, kH = 90;

// Shadows, the linked-list OIT, AO volumes, TAA and the clustered light lists.
void renderEverything(RenderSession& s) {
    s.loadScene("glass");
    s.knobs().setFromString("shadows.enabled", "true");
    s.knobs().setFromString("oit.method", "linked_list");
    s.knobs().setFromString("ao.enabled", "true");
    s.knobs().setFromString("ao.method", "aov");
    s.knobs().setFromString("aa.method", "taa");
    s.knobs().setFromString("lighting.strategy", "clustered");
    s.render();
    s.render();  // TAA's second frame, with a history
}

std::set<std::uint64_t> tickets() {
    std::set<std::uint64_t> t;
    for (const auto& e : gl::MemoryLedger::instance().entries()) t.insert(e.ticket);
    return t;
}

}  // namespace

TEST(MemoryLedger, InspectorTotalEqualsTheWrapperCountAndEveryAllocationHasAnOwner) {
    gl::MemoryLedger& ledger = gl::MemoryLedger::instance();
    const std::size_t start = ledger.liveBytes();
    const std::set<std::uint64_t> before = tickets();
    {
        auto s = test::makeSession(kW, kH);
        renderEverything(*s);
        const MemoryTable t = MemoryTable::build(s->pipeline().resources());
        EXPECT_GT(t.total, start);
        // The frame graph's descriptors and the owners' rows add up to what
        // the wrapper allocated, to the byte.
        EXPECT_EQ(t.total, ledger.liveBytes());
        EXPECT_EQ(t.total, t.ledgerLive);
        EXPECT_GE(t.ledgerPeak, t.ledgerLive);
        for (const auto& e : ledger.entries()) {
            if (before.count(e.ticket)) continue;
            EXPECT_NE(e.owner, "unowned") << e.kind << " " << e.id << " of " << e.bytes << " bytes";
        }
        EXPECT_TRUE(ledger.unknownFormats().empty()) << "a format missing from texelBytes: 0x" << std::hex
                                                     << ledger.unknownFormats().front();
        EXPECT_NE(t.text().find("total"), std::string::npos);
    }
    // No leak: the session's objects all gave their bytes back.
    EXPECT_EQ(ledger.liveBytes(), start);
    EXPECT_EQ(tickets(), before);
}

TEST(MemoryLedger, EachOwnerTheIssueNamesHoldsBytes) {
    auto s = test::makeSession(kW, kH);
    renderEverything(*s);
    const MemoryTable t = MemoryTable::build(s->pipeline().resources());
    auto bytes = [&](const std::string& owner) {
        const MemoryRow* r = t.find(owner);
        return r ? r->bytes : 0;
    };
    EXPECT_GT(bytes("shadow maps"), 0u) << t.text();
    EXPECT_GT(bytes("light lists"), 0u) << t.text();
    EXPECT_GT(bytes("light table"), 0u) << t.text();
    EXPECT_GT(bytes("taa history"), 0u) << t.text();
    EXPECT_EQ(bytes("taa history"), static_cast<std::size_t>(kW) * kH * 4) << t.text();  // RGBA8
    EXPECT_GT(bytes("scene geometry"), 0u) << t.text();
    EXPECT_GT(bytes("scene textures"), 0u) << t.text();
    // OIT storage and the AO volumes are frame-graph resources of their passes.
    EXPECT_GT(bytes("frame graph: oit.list_nodes"), 0u) << t.text();
    EXPECT_EQ(bytes("frame graph: oit.list_heads"), static_cast<std::size_t>(kW) * kH * 4) << t.text();  // R32UI
    EXPECT_GT(bytes("frame graph: aov.occlusion"), 0u) << t.text();
    // Switched off, the owners give their memory back at the next frame.
    s->knobs().setFromString("oit.method", "weighted");
    s->render();
    EXPECT_EQ(MemoryTable::build(s->pipeline().resources()).find("frame graph: oit.list_nodes"), nullptr);
}

TEST(MemoryLedger, TextureBytesCountEveryLevelLayerAndSample) {
    // 8x4 RGBA8 with its 4 levels: 8x4 + 4x2 + 2x1 + 1x1 texels.
    EXPECT_EQ(gl::textureStorageBytes(GL_TEXTURE_2D, GL_RGBA8, 8, 4, 1, 4, 0), (32u + 8u + 2u + 1u) * 4u);
    EXPECT_EQ(gl::textureStorageBytes(GL_TEXTURE_CUBE_MAP, GL_RGBA16F, 4, 4, 1, 1, 0), 6u * 16u * 8u);
    EXPECT_EQ(gl::textureStorageBytes(GL_TEXTURE_CUBE_MAP_ARRAY, GL_DEPTH_COMPONENT32F, 4, 4, 12, 1, 0), 12u * 16u * 4u);
    EXPECT_EQ(gl::textureStorageBytes(GL_TEXTURE_2D_MULTISAMPLE, GL_RGBA16F, 4, 2, 1, 1, 8), 8u * 8u * 8u);
    // A 3D texture's depth halves with the level; an array's layers do not.
    EXPECT_EQ(gl::textureStorageBytes(GL_TEXTURE_3D, GL_R8, 4, 4, 4, 2, 0), 64u + 8u);
    EXPECT_EQ(gl::textureStorageBytes(GL_TEXTURE_2D_ARRAY, GL_R8, 4, 4, 4, 2, 0), 64u + 16u);
    EXPECT_EQ(gl::texelBytes(GL_DEPTH32F_STENCIL8), 5u);

    // The wrapper counts what it creates, under the owner in scope, and gives it back.
    gl::MemoryLedger& ledger = gl::MemoryLedger::instance();
    const std::size_t start = ledger.liveBytes();
    {
        gl::MemoryOwner owner("test owner");
        gl::Texture ms = gl::Texture::create2DMultisample(GL_RGBA8, 16, 8, 4);
        gl::Buffer b = gl::Buffer::create(100, nullptr, true, "test");
        EXPECT_EQ(ledger.liveBytes(), start + 16u * 8u * 4u * 4u + 100u);
        b.ensureSize(1000);  // re-created: the old storage given back
        EXPECT_EQ(ledger.liveBytes(), start + 16u * 8u * 4u * 4u + 1000u);
        EXPECT_GE(ledger.peakBytes(), ledger.liveBytes());
        std::size_t owned = 0;
        for (const auto& o : ledger.byOwner())
            if (o.owner == "test owner") owned = o.bytes;
        EXPECT_EQ(owned, 16u * 8u * 4u * 4u + 1000u);
        // A view owns no storage.
        gl::Texture plain = gl::Texture::create2D(GL_R8, 4, 4);
        const std::size_t withPlain = ledger.liveBytes();
        gl::Texture view = gl::Texture::createView(plain, GL_TEXTURE_2D, 0, 1);
        EXPECT_EQ(ledger.liveBytes(), withPlain);
    }
    EXPECT_EQ(ledger.liveBytes(), start);
    ledger.resetPeak();
    EXPECT_EQ(ledger.peakBytes(), start);
}
