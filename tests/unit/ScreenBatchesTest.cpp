// Batches of light volumes for one instanced stencil draw
// (renderer/lighting/ScreenBatches.h): no two rectangles of a batch share a
// pixel, every rectangle is in exactly one batch, disjoint rectangles share
// one batch, and a volume's screen rectangle holds every pixel its mesh
// projects to (or is the whole screen when the camera is in or behind it).
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "renderer/lighting/AutoStrategy.h"
#include "renderer/lighting/LightVolume.h"
#include "renderer/lighting/ScreenBatches.h"
#include "renderer/passes/LightingPass.h"

using namespace dw;

namespace {
bool overlap(const PixelRect& a, const PixelRect& b) {
    return !a.empty() && !b.empty() && a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}
}  // namespace

TEST(ScreenBatches, NoTwoRectanglesOfABatchOverlap) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> x(0, 639), y(0, 359), size(1, 80);
    std::vector<PixelRect> rects;
    for (int i = 0; i < 1000; ++i) {
        const int x0 = x(rng), y0 = y(rng);
        rects.push_back({x0, y0, std::min(640, x0 + size(rng)), std::min(360, y0 + size(rng))});
    }
    rects.push_back({0, 0, 640, 360});  // the camera inside a volume
    rects.push_back({5, 5, 5, 9});      // empty
    const std::vector<int> batch = disjointBatches(rects, 640, 360);
    ASSERT_EQ(batch.size(), rects.size());
    int batches = 0;
    for (std::size_t i = 0; i < rects.size(); ++i) {
        batches = std::max(batches, batch[i] + 1);
        for (std::size_t j = i + 1; j < rects.size(); ++j)
            if (batch[i] == batch[j]) {
                EXPECT_FALSE(overlap(rects[i], rects[j])) << i << " and " << j;
            }
    }
    // The whole-screen rectangle is alone in its batch.
    EXPECT_EQ(std::count(batch.begin(), batch.end(), batch[1000]), 1);
    std::printf("1000 random rectangles on 640x360: %d batches\n", batches);
    EXPECT_LT(batches, 200);
}

TEST(ScreenBatches, DisjointRectanglesShareOneBatch) {
    std::vector<PixelRect> rects;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 5; ++j) rects.push_back({i * 64, j * 72, i * 64 + 50, j * 72 + 60});  // gaps of a grid cell (10 px)
    const std::vector<int> batch = disjointBatches(rects, 640, 360);
    EXPECT_EQ(*std::max_element(batch.begin(), batch.end()), 0);
    // Two identical rectangles never share one.
    EXPECT_EQ(disjointBatches({{10, 10, 20, 20}, {10, 10, 20, 20}}, 64, 36), (std::vector<int>{0, 1}));
}

// The batches are first fit over the grid cells: each rectangle goes into the
// lowest batch none of whose rectangles shares a cell with it. Checked against
// that rule written out plainly, with more than 64 batches (the bit table's
// first word) and the grid's cells wider than a pixel.
TEST(ScreenBatches, AreFirstFitOverTheCells) {
    std::mt19937 rng(11);
    const int W = 640, H = 360, cell = 10;  // a 64 x 36 grid
    std::uniform_int_distribution<int> x(0, W - 1), y(0, H - 1), size(1, 120);
    std::vector<PixelRect> rects;
    for (int i = 0; i < 1500; ++i) {
        const int x0 = x(rng), y0 = y(rng);
        rects.push_back({x0, y0, std::min(W, x0 + size(rng)), std::min(H, y0 + size(rng))});
    }
    for (int i = 0; i < 150; ++i) rects.push_back({300, 150, 340, 170});  // 150 on one spot
    const std::vector<int> batch = disjointBatches(rects, W, H);
    auto cellsMeet = [&](const PixelRect& a, const PixelRect& b) {
        return a.x0 / cell <= (b.x1 - 1) / cell && b.x0 / cell <= (a.x1 - 1) / cell && a.y0 / cell <= (b.y1 - 1) / cell &&
               b.y0 / cell <= (a.y1 - 1) / cell;
    };
    std::vector<int> expected(rects.size(), 0);
    std::vector<std::vector<std::size_t>> members;
    for (std::size_t i = 0; i < rects.size(); ++i) {
        std::size_t b = 0;
        while (b < members.size() &&
               std::any_of(members[b].begin(), members[b].end(), [&](std::size_t j) { return cellsMeet(rects[i], rects[j]); }))
            ++b;
        if (b == members.size()) members.emplace_back();
        members[b].push_back(i);
        expected[i] = static_cast<int>(b);
    }
    std::printf("%zu rectangles: %zu batches\n", rects.size(), members.size());
    EXPECT_GT(members.size(), 150u);
    EXPECT_EQ(batch, expected);
}

TEST(ScreenBatches, RectangleHoldsTheProjectedVolume) {
    const int W = 320, H = 180;
    const glm::dmat4 proj = glm::perspective(glm::radians(60.0), double(W) / H, 0.1, 100.0);
    const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 2, 8), glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0));
    const VolumeMesh& sphere = unitSphereVolume();
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : sphere.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    for (const glm::dvec3 centre : {glm::dvec3(0, 0, 0), glm::dvec3(3, 1, -4), glm::dvec3(-5, 0, 2)}) {
        const glm::dmat4 model = glm::scale(glm::translate(glm::dmat4(1.0), centre), glm::dvec3(1.5));
        const PixelRect r = screenRect(proj * view * model, lo, hi, W, H);
        ASSERT_FALSE(r.empty());
        for (const glm::vec3& p : sphere.positions) {
            const glm::dvec4 c = proj * view * model * glm::dvec4(glm::dvec3(p), 1.0);
            const double px = (c.x / c.w * 0.5 + 0.5) * W, py = (c.y / c.w * 0.5 + 0.5) * H;
            if (px < 0 || py < 0 || px >= W || py >= H) continue;
            EXPECT_GE(px, r.x0);
            EXPECT_LT(px, r.x1);
            EXPECT_GE(py, r.y0);
            EXPECT_LT(py, r.y1);
        }
        EXPECT_LT((r.x1 - r.x0) * (r.y1 - r.y0), W * H / 4) << "a small sphere gets a small rectangle";
    }
    // The eye inside the volume: the whole image.
    const glm::dmat4 around = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 2, 8)), glm::dvec3(1.5));
    const PixelRect whole = screenRect(proj * view * around, lo, hi, W, H);
    EXPECT_EQ(whole.x0, 0);
    EXPECT_EQ(whole.y0, 0);
    EXPECT_EQ(whole.x1, W);
    EXPECT_EQ(whole.y1, H);
}

TEST(AutoStrategy, VolumesTiledOrClusteredByScreenCoverage) {
    // The defaults (LightingPass::kAutoCoverage, kAutoClusterCoverage) on the
    // measured cases (docs/bench.md, "auto"): lights in view, coverage, and
    // the faster strategy on llvmpipe.
    const AutoStrategyThresholds at{LightingPass::kAutoCoverage, LightingPass::kAutoClusterCoverage};
    EXPECT_STREQ(chooseLightingStrategy({25, 0.32}, at).strategy, "stencil_volumes");
    EXPECT_STREQ(chooseLightingStrategy({83, 1.48}, at).strategy, "stencil_volumes");
    EXPECT_STREQ(chooseLightingStrategy({27, 1.20}, at).strategy, "stencil_volumes");
    EXPECT_STREQ(chooseLightingStrategy({250, 4.60}, at).strategy, "stencil_volumes");
    EXPECT_STREQ(chooseLightingStrategy({87, 6.05}, at).strategy, "stencil_volumes");
    EXPECT_STREQ(chooseLightingStrategy({29, 5.29}, at).strategy, "stencil_volumes");
    EXPECT_STREQ(chooseLightingStrategy({419, 7.75}, at).strategy, "stencil_volumes");  // even: 15.6 against 14.7 ms
    EXPECT_STREQ(chooseLightingStrategy({131, 8.35}, at).strategy, "stencil_volumes");
    EXPECT_STREQ(chooseLightingStrategy({595, 10.91}, at).strategy, "tiled");
    EXPECT_STREQ(chooseLightingStrategy({48, 11.29}, at).strategy, "tiled");
    EXPECT_STREQ(chooseLightingStrategy({177, 11.66}, at).strategy, "tiled");
    EXPECT_STREQ(chooseLightingStrategy({856, 14.97}, at).strategy, "tiled");
    EXPECT_STREQ(chooseLightingStrategy({893, 55.91}, at).strategy, "tiled");
    EXPECT_STREQ(chooseLightingStrategy({2923, 657.39}, at).strategy, "tiled");
    EXPECT_STREQ(chooseLightingStrategy({0, 0.0}, at).strategy, "stencil_volumes");
    // No light in view: nothing to choose between, and the reason says so
    // (not a threshold comparison that reads as met).
    EXPECT_EQ(chooseLightingStrategy({0, 0.0}, {0.0, 0.0}).why, "no bounded lights in view");
    // Where clustered is set to win, from K on; both thresholds are inclusive.
    const AutoStrategyThresholds withClusters{4.0, 65.0};
    EXPECT_STREQ(chooseLightingStrategy({500, 4.0}, withClusters).strategy, "tiled");
    EXPECT_STREQ(chooseLightingStrategy({500, 64.9}, withClusters).strategy, "tiled");
    EXPECT_STREQ(chooseLightingStrategy({500, 65.0}, withClusters).strategy, "clustered");
    EXPECT_EQ(chooseLightingStrategy({96, 23.41}, withClusters).why,
              "96 lights in view, screen coverage 23.41 (>= 4.00, < 65.00), 0.2439 of the screen each");
}
