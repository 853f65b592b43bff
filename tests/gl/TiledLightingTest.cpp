// The tiled and clustered strategies (seed 003 section 2.2.1; Olsson, Billeter
// and Assarsson 2012) light the same L-buffer as the volume strategies and the
// brute-force reference, on the default scene, with the camera inside light
// volumes, with many small lights straddling tile edges and depth slices, and
// with shadowed lights (shaded one at a time). Their per-pixel light lists
// (lighting.tile_counts, lighting.cluster_counts) are conservative: never
// shorter than the lights that really reach a pixel, empty far from every
// light, and clusters no longer than tiles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/lighting/LightVolume.h"
#include "renderer/passes/LightTablePass.h"
#include "renderer/passes/LightingPass.h"
#include "renderer/reference/ShadingReference.h"
#include "renderer/scene/ShapeBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

const char* const kStrategies[] = {"stencil_volumes", "volumes", "fullscreen", "tiled", "clustered"};

FloatImage lbufferWith(RenderSession& s, const std::string& strategy) {
    s.knobs().setFromString("lighting.strategy", strategy);
    s.render({{"lbuffer", "gbuffer.view_position"}});
    return s.readRaw("lbuffer");
}

bool sumsPerLight(const std::string& strategy) { return strategy != "tiled" && strategy != "clustered"; }

// The spacing of RGBA16F values around v >= 0 (one unit in the last place).
double ulp16(double v) {
    return v < std::ldexp(1.0, -14) ? std::ldexp(1.0, -24) : std::ldexp(1.0, static_cast<int>(std::floor(std::log2(v))) - 10);
}

// Renders with every strategy and checks each against the brute-force
// reference (every light over every pixel). Strategies that add light by
// light through the blender (stencil_volumes, volumes, fullscreen) round the
// RGBA16F sum after every light; tiled and clustered sum a pixel's lights in
// 32-bit floats and round once. Within each kind the images must agree to
// 1e-3 relative. Across kinds the blender's roundings are the difference,
// up to one unit in the last place (of RGBA16F) per light reaching the pixel
// (on llvmpipe they all go one way: the blended sums come out low, as with
// rounding towards zero, 1.2% at the default scene's worst pixel). There the
// bound is (n + 2) ulps, n counted from the light table: every light whose
// sphere holds the pixel's surface, and every unbounded one.
void expectStrategiesAgree(RenderSession& s, const std::string& what) {
    const FloatImage reference = lbufferWith(s, "fullscreen");
    const FloatImage P = s.readRaw("gbuffer.view_position");
    const LightTable& table = s.pipeline().pass<LightTablePass>()->table();
    std::vector<int> reaching(static_cast<std::size_t>(P.width * P.height), 0);
    for (int y = 0; y < P.height; ++y)
        for (int x = 0; x < P.width; ++x) {
            const glm::vec3 p(P.at(x, y, 0), P.at(x, y, 1), P.at(x, y, 2));
            for (const LightGpu& row : table.rows) {
                const float r = row.positionRadius.w;
                reaching[static_cast<std::size_t>(y * P.width + x)] +=
                    r <= 0.0f || glm::length(p - glm::vec3(row.positionRadius)) <= r * 1.0001f;
            }
        }
    EXPECT_GT(test::stats(reference, 0).max, 0.0) << what;
    struct Worst {
        double relative = 0.0, budget = 0.0, single = 0.0;
        int x = 0, y = 0;
    };
    auto compare = [&](const FloatImage& a, const FloatImage& b) {
        Worst w;
        for (int y = 0; y < a.height; ++y)
            for (int x = 0; x < a.width; ++x)
                for (int c = 0; c < 3; ++c) {
                    const double va = a.at(x, y, c), vb = b.at(x, y, c);
                    const double big = std::max(std::fabs(va), std::fabs(vb));
                    const double rel = std::fabs(va - vb) / (big + 1e-3);
                    const int n = reaching[static_cast<std::size_t>(y * a.width + x)];
                    if (rel > w.relative) w.relative = rel, w.x = x, w.y = y;
                    w.budget = std::max(w.budget, std::fabs(va - vb) / ((n + 2) * ulp16(big)));
                    if (n <= 1) w.single = std::max(w.single, rel);
                }
        return w;
    };
    FloatImage tiled;
    for (const char* strategy : kStrategies) {
        const FloatImage image = lbufferWith(s, strategy);
        const Worst w = compare(image, reference);
        std::printf("%s: %s vs fullscreen: worst relative difference %.3g at (%d, %d), %.3g where at most one light "
                    "reaches; worst |difference| / ((n + 2) ulp) %.3g\n",
                    what.c_str(), strategy, w.relative, w.x, w.y, w.single, w.budget);
        if (sumsPerLight(strategy)) {
            EXPECT_LE(w.relative, 1e-3) << what << ", " << strategy << " at " << w.x << "," << w.y;
            continue;
        }
        EXPECT_LE(w.budget, 1.0) << what << ", " << strategy;
        // Where at most one light reaches, both kinds round once (or not at all).
        EXPECT_LE(w.single, 1e-3) << what << ", " << strategy;
        if (tiled.width == 0) {
            tiled = image;
            continue;
        }
        const Worst g = compare(image, tiled);
        std::printf("%s: %s vs tiled: worst relative difference %.3g at (%d, %d)\n", what.c_str(), strategy, g.relative,
                    g.x, g.y);
        EXPECT_LE(g.relative, 1e-3) << what << ", " << strategy << " vs tiled at " << g.x << "," << g.y;
    }
}

}  // namespace

TEST(TiledLighting, EveryStrategyAgreesOnTheDefaultScene) {
    auto session = test::makeSession(160, 90);
    session->loadScene("default");
    const auto* lighting = session->pipeline().pass<LightingPass>();
    for (const char* reuse : {"true", "false"}) {
        session->knobs().setFromString("shadows.reuse_map", reuse);
        expectStrategiesAgree(*session, std::string("default scene, shadows.reuse_map = ") + reuse);
    }
    // The shadowed spot lights went one at a time, the rest through the grid.
    session->knobs().setFromString("lighting.strategy", "tiled");
    session->render({{"lbuffer"}});
    const LightingPass::Counts tiled = lighting->lastCounts();
    int shadowedBounded = 0;
    for (const LightTableEntry& e : session->pipeline().pass<LightTablePass>()->table().entries)
        shadowedBounded += e.shadowed && e.light->type != LightType::Directional;
    session->knobs().setFromString("lighting.strategy", "clustered");
    session->render({{"lbuffer"}});
    const LightingPass::Counts clustered = lighting->lastCounts();
    std::printf("default scene: tiled %d in tiles, %d one at a time, %d outside the frustum; clustered %d in clusters, "
                "%d one at a time\n",
                tiled.grid, tiled.volumes, tiled.frustumCulled, clustered.grid, clustered.volumes);
    EXPECT_GT(tiled.grid, 30);
    EXPECT_GE(shadowedBounded, 1);
    EXPECT_EQ(tiled.volumes, shadowedBounded);
    EXPECT_EQ(clustered.grid, tiled.grid);
    EXPECT_EQ(clustered.volumes, tiled.volumes);
}

TEST(TiledLighting, EveryStrategyAgreesWithTheCameraInsideVolumes) {
    auto session = test::makeSession(160, 90);
    session->setScene(test::boxesScene(false));
    session->camera().position = {0.0f, 1.0f, 3.5f};
    session->camera().target = {0.0f, 0.5f, -2.0f};
    expectStrategiesAgree(*session, "camera inside volumes");
}

TEST(TiledLighting, EveryStrategyAgreesWithManySmallLightsAcrossTilesAndSlices) {
    auto session = test::makeSession(96, 54);
    session->setScene(test::straddleScene(3));
    for (const char* tile : {"4", "12", "16", "32"}) {
        session->knobs().setFromString("lighting.tile_size", tile);
        for (const char* slices : {"3", "24"}) {
            session->knobs().setFromString("lighting.cluster_slices", slices);
            expectStrategiesAgree(*session, std::string("200 lights, tile ") + tile + ", " + slices + " slices");
        }
    }
}

// More lights than one tiled dispatch holds in its shared-memory list (4096):
// the strategy dispatches again for the rest, adding to the image and the counts.
TEST(TiledLighting, EveryStrategyAgreesWithMoreLightsThanOneDispatchHolds) {
    auto session = test::makeSession(64, 36);
    Scene s = test::planeScene(40.0f);
    s.camera.position = {0.0f, 9.0f, 9.0f};
    s.camera.target = {0.0f, 0.0f, -3.0f};
    for (int i = 0; i < 4500; ++i) {
        const glm::vec3 pos(-15.0f + (i % 75) * 0.4f, 0.2f + 0.3f * std::fmod(i * 0.618f, 1.0f), -20.0f + (i / 75) * 0.4f);
        const glm::vec3 colour(0.3f + 0.7f * std::fmod(i * 0.31f, 1.0f), 0.5f, 0.3f + 0.7f * std::fmod(i * 0.79f, 1.0f));
        const float peak = std::max(colour.r, colour.b), radius = 0.6f;
        test::addPointLight(s, pos, colour, {1.0f, 0.0f, (255.0f * peak - 1.0f) / (radius * radius)});
    }
    session->setScene(std::move(s));
    expectStrategiesAgree(*session, "4500 lights");
    session->knobs().setFromString("lighting.strategy", "tiled");
    session->render({{"lbuffer", "lighting.tile_counts", "lighting.cluster_counts"}});
    const FloatImage tiles = session->readRaw("lighting.tile_counts"), clusters = session->readRaw("lighting.cluster_counts");
    std::printf("4500 lights: largest tile list %.0f, largest cluster list %.0f\n", test::stats(tiles, 0).max,
                test::stats(clusters, 0).max);
    EXPECT_GT(test::stats(tiles, 0).max, 0.0);
}

TEST(TiledLighting, TileAndClusterCountsAreConservative) {
    const int W = 96, H = 54;
    auto session = test::makeSession(W, H);
    session->setScene(test::straddleScene(0));
    session->knobs().setFromString("lighting.tile_size", "16");
    for (const char* strategy : {"tiled", "clustered", "stencil_volumes"}) {
        session->knobs().setFromString("lighting.strategy", strategy);
        session->render({{"lbuffer", "lighting.tile_counts", "lighting.cluster_counts", "gbuffer.view_position"}});
        const FloatImage tiles = session->readRaw("lighting.tile_counts");
        const FloatImage clusters = session->readRaw("lighting.cluster_counts");
        const FloatImage P = session->readRaw("gbuffer.view_position");
        const LightTable& table = session->pipeline().pass<LightTablePass>()->table();

        // Lights whose lit region (the sphere of their radius) holds the pixel's surface.
        auto reaching = [&](int x, int y) {
            if (P.at(x, y, 3) == 0.0f) return 0;
            const glm::vec3 p(P.at(x, y, 0), P.at(x, y, 1), P.at(x, y, 2));
            int n = 0;
            for (const LightGpu& row : table.rows)
                n += row.positionRadius.w > 0.0f &&
                     glm::length(p - glm::vec3(row.positionRadius)) < row.positionRadius.w * 0.9999f;
            return n;
        };
        // Whether any light's sphere can touch tile (tx, ty) (counted from the
        // bottom left, as GL's window coordinates): its bounding box
        // projected, a pixel wider, meets the tile's rectangle, or the box
        // crosses the near plane. When it does not, the sphere lies wholly
        // beyond one of the planes through the tile's edges, which the shader's
        // test rejects (with its rounding slack of 1e-4 r).
        const glm::mat4 proj = session->camera().projection(static_cast<float>(W) / H);
        auto nearSomeLight = [&](int tx, int ty) {
            for (const LightGpu& row : table.rows) {
                const glm::vec3 c(row.positionRadius);
                const float r = 1.01f * row.positionRadius.w;
                if (-c.z - r <= session->camera().nearPlane) return true;
                glm::vec2 lo(1e30f), hi(-1e30f);
                for (int k = 0; k < 8; ++k) {
                    const glm::vec4 q = proj * glm::vec4(c + glm::vec3(k & 1 ? r : -r, k & 2 ? r : -r, k & 4 ? r : -r), 1.0f);
                    const glm::vec2 w = (glm::vec2(q) / q.w * 0.5f + 0.5f) * glm::vec2(W, H);
                    lo = glm::min(lo, w);
                    hi = glm::max(hi, w);
                }
                if (hi.x + 1 >= tx * 16 && lo.x - 1 <= (tx + 1) * 16 && hi.y + 1 >= ty * 16 && lo.y - 1 <= (ty + 1) * 16)
                    return true;
            }
            return false;
        };

        long long surface = 0, tileSum = 0, clusterSum = 0, clusterAboveTile = 0, farTiles = 0, lit = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const int t = static_cast<int>(tiles.at(x, y, 0)), c = static_cast<int>(clusters.at(x, y, 0));
                const int truth = reaching(x, y);
                lit += truth > 0;
                EXPECT_GE(t, truth) << strategy << ": tile count at " << x << "," << y;
                EXPECT_GE(c, truth) << strategy << ": cluster count at " << x << "," << y;
                // Every pixel of a tile shows the tile's count (read-back rows run top-down, tiles bottom-up).
                const int gy = H - 1 - y;
                EXPECT_EQ(t, static_cast<int>(tiles.at(x / 16 * 16, H - 1 - gy / 16 * 16, 0))) << x << "," << y;
                if (P.at(x, y, 3) == 0.0f) {
                    EXPECT_EQ(c, 0) << "background " << x << "," << y;
                    continue;
                }
                ++surface;
                tileSum += t;
                clusterSum += c;
                clusterAboveTile += c > t;
            }
        for (int ty = 0; ty * 16 < H; ++ty)
            for (int tx = 0; tx * 16 < W; ++tx) {
                if (nearSomeLight(tx, ty)) continue;
                ++farTiles;
                EXPECT_EQ(tiles.at(tx * 16, H - 1 - ty * 16, 0), 0.0f) << strategy << ": tile " << tx << "," << ty;
            }
        const double meanTile = static_cast<double>(tileSum) / surface, meanCluster = static_cast<double>(clusterSum) / surface;
        std::printf("%s: %lld lit pixels; mean lights per surface pixel: tile %.2f, cluster %.2f; cluster > tile at %lld "
                    "pixels; %lld tiles far from every light\n",
                    strategy, lit, meanTile, meanCluster, clusterAboveTile, farTiles);
        EXPECT_GT(lit, W * H / 4);
        EXPECT_GE(farTiles, 6);
        EXPECT_LT(meanCluster, meanTile);
        EXPECT_EQ(clusterAboveTile, 0);
    }
}

// How the tiled strategy's work is split and culled changes no pixel: one
// invocation per pixel, one SIMD batch per tile (llvmpipe's auto choice), a
// count that leaves a partial last round, and the 2.5D depth mask on and off
// all sum each pixel's reaching lights in candidate order. The depth mask
// drops the lights that float in a tile's depth gap (between a box near the
// camera and the floor far behind it), so with it the lists are shorter but
// still hold every light that reaches the pixel.
TEST(TiledLighting, TileThreadsDepthMaskAndWalkChangeNoPixel) {
    const int W = 96, H = 54;
    auto session = test::makeSession(W, H);
    Scene s = test::straddleScene(0);
    // A wall across the lower screen, near the camera (at (0, 7, 11), looking
    // at (0, 0, -2)); its top edge splits tiles between the wall (about 9
    // units away) and the floor beyond it (about 12).
    Mesh wall = shapes::box({30.0f, 3.0f, 1.0f});
    wall.material = 0;
    s.instances.push_back({s.addMesh(std::move(wall)), glm::translate(glm::mat4(1.0f), {0.0f, 1.5f, 6.0f})});
    // Small lights in mid-air in that gap, on the rays just past the edge,
    // touching neither surface.
    for (int i = 0; i < 40; ++i) {
        const float x = -8.0f + 0.4f * i, t = 1.12f + 0.1f * std::fmod(i * 0.618f, 1.0f);
        const glm::vec3 edge(x, 3.0f, 5.5f), eye(0.0f, 7.0f, 11.0f);
        test::addPointLight(s, eye + t * (edge - eye), {0.9f, 0.6f, 0.3f}, {1.0f, 0.0f, (255.0f * 0.9f - 1.0f) / 0.09f});
    }
    session->setScene(std::move(s));
    session->knobs().setFromString("lighting.strategy", "tiled");
    session->knobs().setFromString("lighting.tile_size", "16");

    struct Run {
        FloatImage lbuffer, overlap, counts;
    };
    auto run = [&](const char* threads, const char* mask, const char* walk = "auto") {
        session->knobs().setFromString("lighting.tile_threads", threads);
        session->knobs().setFromString("lighting.tile_depth_mask", mask);
        session->knobs().setFromString("lighting.tile_walk", walk);
        session->render({{"lbuffer", "lighting.overlap", "lighting.tile_counts", "gbuffer.view_position"}});
        return Run{session->readRaw("lbuffer"), session->readRaw("lighting.overlap"), session->readRaw("lighting.tile_counts")};
    };
    const Run base = run("256", "false", "branch");
    const FloatImage P = session->readRaw("gbuffer.view_position");
    EXPECT_GT(test::stats(base.lbuffer, 0).max, 0.0);
    // Both walks (marking first, or a test per listed light) at every
    // thread count: the marking's slack never drops a light, and the exact
    // test after it keeps the same ones in the same order.
    for (const char* walk : {"branch", "mark"})
        for (const char* threads : {"256", "0", "8", "1", "100"})
            for (const char* mask : {"false", "true"}) {
                const Run r = run(threads, mask, walk);
                const std::string what = std::string(walk) + " walk, " + threads + " threads, mask " + mask;
                EXPECT_EQ(test::maxAbsDifference(r.lbuffer, base.lbuffer, 4), 0.0) << what;
                EXPECT_EQ(test::maxAbsDifference(r.overlap, base.overlap, 1), 0.0) << what;
                if (std::string(mask) == "false") {
                    EXPECT_EQ(test::maxAbsDifference(r.counts, base.counts, 1), 0.0) << what;
                }
            }

    const Run masked = run("0", "true");
    const LightTable& table = session->pipeline().pass<LightTablePass>()->table();
    double withMask = 0.0, without = 0.0;
    int surfaces = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            if (P.at(x, y, 3) == 0.0f) continue;
            const glm::vec3 p(P.at(x, y, 0), P.at(x, y, 1), P.at(x, y, 2));
            int reaching = 0;
            for (const LightGpu& row : table.rows)
                reaching += row.positionRadius.w > 0.0f &&
                            glm::length(p - glm::vec3(row.positionRadius)) < row.positionRadius.w * 0.9999f;
            const float m = masked.counts.at(x, y, 0), b = base.counts.at(x, y, 0);
            EXPECT_GE(m, reaching) << x << "," << y;
            EXPECT_LE(m, b) << x << "," << y;
            withMask += m;
            without += b;
            ++surfaces;
        }
    std::printf("lights listed per surface pixel: %.2f with the depth mask, %.2f without\n", withMask / surfaces,
                without / surfaces);
    EXPECT_LT(withMask, 0.9 * without);
}

// The coarse pass (lighting.tile_coarse) only saves work: every tile's list,
// and so every pixel, is what culling every candidate gives, at tile sizes
// whose coarse tiles are 16 to 128 pixels, with and without the depth mask,
// and over several dispatches (the 4500 lights). The lists are not all
// alike, so a coarse mask read from the wrong coarse tile would show.
TEST(TiledLighting, CoarsePassChangesNoListAndNoPixel) {
    auto session = test::makeSession(160, 90);
    session->knobs().setFromString("lighting.strategy", "tiled");
    struct Run {
        FloatImage lbuffer, overlap, counts;
    };
    auto run = [&](const char* coarse) {
        session->knobs().setFromString("lighting.tile_coarse", coarse);
        session->render({{"lbuffer", "lighting.overlap", "lighting.tile_counts"}});
        return Run{session->readRaw("lbuffer"), session->readRaw("lighting.overlap"), session->readRaw("lighting.tile_counts")};
    };
    auto compare = [&](const std::string& what) {
        const Run all = run("false"), coarse = run("true");
        const test::ChannelStats counts = test::stats(all.counts, 0);
        EXPECT_GT(counts.max, counts.min) << what << ": the lists should differ between tiles";
        EXPECT_GT(test::stats(all.lbuffer, 0).max, 0.0) << what;
        EXPECT_EQ(test::maxAbsDifference(coarse.counts, all.counts, 1), 0.0) << what;
        EXPECT_EQ(test::maxAbsDifference(coarse.lbuffer, all.lbuffer, 4), 0.0) << what;
        EXPECT_EQ(test::maxAbsDifference(coarse.overlap, all.overlap, 1), 0.0) << what;
    };
    session->setScene(test::straddleScene(3));
    for (const char* tile : {"4", "16", "32"})
        for (const char* mask : {"false", "true"}) {
            session->knobs().setFromString("lighting.tile_size", tile);
            session->knobs().setFromString("lighting.tile_depth_mask", mask);
            compare(std::string("200 lights, tile ") + tile + ", depth mask " + mask);
        }

    Scene s = test::planeScene(40.0f);
    s.camera.position = {0.0f, 9.0f, 9.0f};
    s.camera.target = {0.0f, 0.0f, -3.0f};
    for (int i = 0; i < 4500; ++i) {
        const glm::vec3 pos(-15.0f + (i % 75) * 0.4f, 0.2f + 0.3f * std::fmod(i * 0.618f, 1.0f), -20.0f + (i / 75) * 0.4f);
        test::addPointLight(s, pos, {0.8f, 0.5f, 0.4f}, {1.0f, 0.0f, (255.0f * 0.8f - 1.0f) / 0.36f});
    }
    session->setScene(std::move(s));
    session->knobs().setFromString("lighting.tile_size", "8");
    compare("4500 lights, tile 8");
}

namespace {
// tiles.glsl's screen volume on the CPU, for a perspective camera at the
// origin looking down -z: the side planes through the eye and the rays
// through the rectangle's corners (window pixels, y up), and the box around
// the slab between view depths zNear >= zFar.
struct CpuScreenVolume {
    glm::dvec4 planes[4];
    glm::dvec3 boxMin{1e30}, boxMax{-1e30};
    CpuScreenVolume(glm::dvec2 pixelMin, glm::dvec2 pixelMax, double zNear, double zFar, glm::dvec2 size,
                    double tanHalfY) {
        const double aspect = size.x / size.y;
        auto ray = [&](glm::dvec2 w) {
            const glm::dvec2 ndc = 2.0 * w / size - 1.0;
            return glm::dvec3(ndc.x * tanHalfY * aspect, ndc.y * tanHalfY, -1.0);
        };
        const glm::dvec2 corner[4] = {pixelMin, {pixelMax.x, pixelMin.y}, pixelMax, {pixelMin.x, pixelMax.y}};
        const glm::dvec3 inside = ray(0.5 * (pixelMin + pixelMax)) * (-0.5 * (zNear + zFar));
        for (int i = 0; i < 4; ++i) {
            for (const double z : {zNear, zFar}) {
                boxMin = glm::min(boxMin, ray(corner[i]) * -z);
                boxMax = glm::max(boxMax, ray(corner[i]) * -z);
            }
            glm::dvec3 n = glm::normalize(glm::cross(ray(corner[i]), ray(corner[(i + 1) & 3])));
            if (glm::dot(n, inside) > 0.0) n = -n;
            planes[i] = glm::dvec4(n, 0.0);  // through the eye
        }
    }
    // How far the sphere is kept by the side planes and the box, as the
    // shader tests them: > 0 kept by that margin, < 0 dropped by it (in units of r).
    double planeMargin(glm::dvec3 c, double r) const {
        double m = 1e30;
        for (const glm::dvec4& p : planes) m = std::min(m, (r - (glm::dot(glm::dvec3(p), c) + p.w)) / r);
        return m;
    }
    double boxMargin(glm::dvec3 c, double r) const {
        return (r - glm::length(glm::clamp(c, boxMin, boxMax) - c)) / r;
    }
};
}  // namespace

// The side planes of every tile pass through the eye. In front of it a
// coarse tile's outside half-spaces hold its tiles', behind it they do not:
// a large light centred behind the eye can lie wholly outside one of the
// coarse tile's planes while a tile inside it keeps the light (its planes
// do not reject it behind the eye, and the light touches the box around its
// slab, which reaches beyond the slab where the tile spans a near and a far
// surface). The coarse pass must keep such a light, or the tile's list (here
// its count) differs from culling every candidate. The light is found on
// the CPU with tiles.glsl's tests, for a floor seen straight from above at
// view depth -20 and a box whose top, at depth -1, covers half of the tile
// (so the tile's and its coarse tile's depth ranges are known).
TEST(TiledLighting, CoarsePassKeepsLightsReachingBehindTheEye) {
    const int W = 64, H = 36, tile = 4, coarse = 4 * tile;
    auto session = test::makeSession(W, H);
    Scene s = test::planeScene(40.0f);
    s.lights.clear();
    s.camera.position = {0.0f, 20.0f, 0.0f};
    s.camera.target = {0.0f, 0.0f, 0.0f};
    s.camera.up = {0.0f, 0.0f, -1.0f};
    const glm::mat4 viewToWorld = glm::inverse(s.camera.view());
    const double tanHalfY = std::tan(glm::radians(static_cast<double>(s.camera.fovYDegrees)) / 2.0);
    const glm::dvec2 size(W, H);
    // Tile (5, 4) lies inside coarse tile (1, 1), away from its edges.
    const glm::ivec2 t(5, 4), ct = t * tile / coarse;
    // The box's right edge at the tile's middle column (view x at depth 1).
    const double edgeX = (2.0 * (t.x * tile + tile / 2) / W - 1.0) * tanHalfY * W / H;
    // Thin, so its side faces cover no whole pixel column of the tile.
    Mesh box = shapes::box({0.5f, 0.02f, 0.6f});  // world x, y, z; view x, -z, -y
    box.material = 0;
    const glm::vec4 boxCentre = viewToWorld * glm::vec4(static_cast<float>(edgeX) - 0.25f,
                                                        static_cast<float>((2.0 * (t.y * tile + tile / 2) / H - 1.0) * tanHalfY),
                                                        -1.01f, 1.0f);
    s.instances.push_back({s.addMesh(std::move(box)), glm::translate(glm::mat4(1.0f), glm::vec3(boxCentre))});
    const CpuScreenVolume fine(glm::dvec2(t * tile), glm::dvec2(t * tile + tile), -1.0, -20.0, size, tanHalfY);
    const CpuScreenVolume coarseVolume(glm::dvec2(ct * coarse), glm::dvec2(ct * coarse + coarse), -1.0, -20.0, size,
                                       tanHalfY);
    const CpuScreenVolume screen(glm::dvec2(0.0), size, -0.2, -150.0, size, tanHalfY);
    glm::dvec3 centre(0.0);
    double radius = 0.0;
    for (int i = 0; i < 200000 && radius == 0.0; ++i) {
        const double u = std::fmod(i * 0.6180339887, 1.0), v = std::fmod(i * 0.4142135624, 1.0);
        const double w = std::fmod(i * 0.7320508076, 1.0), q = std::fmod(i * 0.2360679775, 1.0);
        const glm::dvec3 c(-60.0 + 120.0 * u, -60.0 + 120.0 * v, 0.5 + 40.0 * w);
        const double r = 3.0 + 57.0 * q;
        // Kept by the tile and met by the view (so a candidate), dropped by
        // a coarse plane even with the coarse pass's extra slack; all with
        // margins (0.4% and 0.1% of radii of tens of units) far beyond rounding.
        if (fine.planeMargin(c, r) > 0.004 && fine.boxMargin(c, r) > 0.004 && screen.planeMargin(c, r) > 0.004 &&
            screen.boxMargin(c, r) > 0.004 && coarseVolume.planeMargin(c, r * 1.001 + 1e-4) < -0.001) {
            centre = c;
            radius = r;
        }
    }
    ASSERT_GT(radius, 0.0) << "no light of that kind found";
    const float rf = static_cast<float>(radius);
    test::addPointLight(s, glm::vec3(viewToWorld * glm::vec4(glm::vec3(centre), 1.0f)), {0.01f, 0.01f, 0.01f},
                        {1.0f, 0.0f, (255.0f * 0.01f - 1.0f) / (rf * rf)});
    std::printf("light at view (%.2f, %.2f, %.2f), radius %.2f\n", centre.x, centre.y, centre.z, radius);
    session->setScene(std::move(s));
    session->knobs().setFromString("lighting.strategy", "tiled");
    session->knobs().setFromString("lighting.tile_size", std::to_string(tile));
    auto counts = [&](const char* withCoarse) {
        session->knobs().setFromString("lighting.tile_coarse", withCoarse);
        session->render({{"lighting.tile_counts"}});
        return session->readRaw("lighting.tile_counts");
    };
    const FloatImage all = counts("false"), withCoarse = counts("true");
    // Read-back rows run top-down, window coordinates bottom-up.
    const int x = t.x * tile + 1, y = H - 1 - (t.y * tile + 1);
    EXPECT_EQ(all.at(x, y, 0), 1.0f) << "the tile keeps the light";
    EXPECT_EQ(withCoarse.at(x, y, 0), all.at(x, y, 0)) << "with the coarse pass";
    EXPECT_EQ(test::maxAbsDifference(withCoarse, all, 1), 0.0);
}

// lighting.overlap under tiled and clustered counts the lights each pixel
// shaded: those of its tile's or cluster's list that reach the pixel's
// surface (the grid tests the radius, and a spot light's cone, before
// shading: the tests attenuate() and shadeLight make). Lists are conservative, so that is every light that
// reaches the surface: the stencil strategy's count up to the volume mesh,
// and never more than the list.
TEST(TiledLighting, OverlapCountsTheLightsEachPixelEvaluated) {
    const int W = 96, H = 54;
    auto session = test::makeSession(W, H);
    session->setScene(test::straddleScene(0));
    for (const char* strategy : {"tiled", "clustered"}) {
        session->knobs().setFromString("lighting.strategy", strategy);
        session->render({{"lbuffer", "lighting.overlap", "lighting.tile_counts", "lighting.cluster_counts",
                          "gbuffer.view_position"}});
        const FloatImage overlap = session->readRaw("lighting.overlap");
        const FloatImage lists = session->readRaw(std::string(strategy) == "tiled" ? "lighting.tile_counts" : "lighting.cluster_counts");
        const FloatImage P = session->readRaw("gbuffer.view_position");
        const LightTable& table = session->pipeline().pass<LightTablePass>()->table();
        double sum = 0.0, listed = 0.0;
        int off = 0, surfaces = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const float o = overlap.at(x, y, 0);
                sum += o;
                if (P.at(x, y, 3) == 0.0f) {
                    EXPECT_EQ(o, 0.0f) << strategy << " at " << x << "," << y;
                    continue;
                }
                ++surfaces;
                listed += lists.at(x, y, 0);
                EXPECT_LE(o, lists.at(x, y, 0)) << strategy << " at " << x << "," << y;
                const glm::vec3 p(P.at(x, y, 0), P.at(x, y, 1), P.at(x, y, 2));
                int reaching = 0;
                for (const LightGpu& row : table.rows) {
                    const glm::vec3 toLight = glm::vec3(row.positionRadius) - p;
                    const float d = glm::length(toLight);
                    if (row.positionRadius.w > 0.0f && d > row.positionRadius.w) continue;
                    const bool spot = static_cast<int>(row.attenuation.w + 0.5f) == 2;  // LIGHT_SPOT
                    if (spot && glm::dot(-toLight / std::max(d, 1e-6f), glm::vec3(row.directionCutoff)) < row.directionCutoff.w)
                        continue;
                    ++reaching;
                }
                // The G-buffer's reconstructed position and the CPU's may put a
                // surface on either side of a sphere's edge: one light at most.
                EXPECT_NEAR(o, reaching, 1.0) << strategy << " at " << x << "," << y;
                off += o != static_cast<float>(reaching);
            }
        std::printf("%s: mean lights shaded per pixel %.2f, listed %.2f per surface pixel (of 200 lights, spots "
                    "among them); %d of %d surface pixels differ from the CPU's count by one\n",
                    strategy, sum / (W * H), listed / surfaces, off, surfaces);
        EXPECT_GT(sum, 0.0);
        EXPECT_LT(off, surfaces / 100);
    }
}


// Against the shading equation in double precision (renderer/reference): the
// single rounding of tiled and clustered lands nearer than the blender's
// rounding after every light.
TEST(TiledLighting, GridStrategiesMatchTheCpuShadingEquation) {
    const int W = 160, H = 90;
    auto session = test::makeSession(W, H);
    Scene s = test::boxesScene(false);
    s.ambient = glm::vec3(0.0f);
    const std::vector<Light> lights = s.lights;
    session->setScene(std::move(s));
    double worstOf[3] = {0, 0, 0};
    const char* const strategies[] = {"fullscreen", "tiled", "clustered"};
    for (int k = 0; k < 3; ++k) {
        session->knobs().setFromString("lighting.strategy", strategies[k]);
        session->render({{"lbuffer", "gbuffer.view_position", "gbuffer.view_normal"}});
        const FloatImage L = session->readRaw("lbuffer");
        const test::GBufferImages g = test::readGBuffer(*session);
        const glm::dmat4 view = session->pipeline().lastCamera().worldToView();  // the matrix the frame used
        double worst = 0.0, bias = 0.0;
        int checked = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                if (!g.surface(x, y)) continue;
                const glm::dvec3 expected = test::referenceRadiance(lights, view, g.at(x, y), 1.0 / 255.0);
                for (int c = 0; c < 3; ++c) {
                    const double e = (L.at(x, y, c) - expected[c]) / (std::fabs(expected[c]) + 0.01);
                    worst = std::max(worst, std::fabs(e));
                    bias += e;
                }
                ++checked;
            }
        worstOf[k] = worst;
        std::printf("%s vs the CPU equation: worst relative error %.3g, mean signed %.3g over %d pixels\n", strategies[k],
                    worst, bias / (3.0 * checked), checked);
        EXPECT_GT(checked, 5000);
        // LightingTest holds the blended strategies to 1e-2; the grid's single rounding does better.
        EXPECT_LT(worst, k == 0 ? 1e-2 : 5e-3) << strategies[k];
    }
    EXPECT_LE(worstOf[1], worstOf[0]);
    EXPECT_LE(worstOf[2], worstOf[0]);
}

// lighting.strategy = auto: below lighting.auto_coverage it lights with
// stencil_volumes, from there with tiled, and from
// lighting.auto_cluster_coverage with clustered; the image is that strategy's
// image, and the statistics line says which it picked and why.
TEST(TiledLighting, AutoPicksByCoverageAndRendersThatStrategy) {
    auto session = test::makeSession(96, 54);
    session->setScene(test::straddleScene(0));
    const auto* lighting = session->pipeline().pass<LightingPass>();
    std::map<std::string, FloatImage> images;
    for (const char* s : {"stencil_volumes", "tiled", "clustered"}) images[s] = lbufferWith(*session, s);
    struct Case {
        const char* coverage;
        const char* clusterCoverage;
        const char* expected;
    };
    for (const Case c : {Case{"1000", "1000", "stencil_volumes"}, Case{"0.5", "1000", "tiled"},
                         Case{"0.5", "0.5", "clustered"}}) {
        session->knobs().setFromString("lighting.auto_coverage", c.coverage);
        session->knobs().setFromString("lighting.auto_cluster_coverage", c.clusterCoverage);
        const FloatImage image = lbufferWith(*session, "auto");
        EXPECT_EQ(lighting->lastStrategy(), c.expected) << c.coverage << " " << c.clusterCoverage;
        const std::string stats = lighting->stats();
        EXPECT_NE(stats.find(std::string("auto picked ") + c.expected), std::string::npos) << stats;
        EXPECT_EQ(test::maxAbsDifference(image, images.at(c.expected), 4), 0.0) << c.expected;
        std::printf("auto (tiled from coverage %s, clustered from %s): %s\n", c.coverage, c.clusterCoverage,
                    stats.c_str());
    }
}

// lighting.tile_ambient: the tiled compute pass writing each pixel's first
// radiance itself (ambient.glsl: the ambient term with SSAO and baked
// occlusion, emission, the sky) gives the image of the full-screen ambient
// pass before it, with directional lights (blended after the pass instead of
// before), shadowed lights shaded one at a time, directional lights shaded in
// the G-buffer pass, and with no bounded light at all (the pass still makes
// the first write). The sums are the same up to their order: within a few
// float roundings. Each frame runs over an L-buffer filled with NaN, so a
// pixel the first write misses shows, and the statistics say which pass made it.
TEST(TiledLighting, TileAmbientChangesNoPixel) {
    auto session = test::makeSession(160, 90);
    const auto* lighting = session->pipeline().pass<LightingPass>();
    auto worstRelative = [](const FloatImage& a, const FloatImage& b) {
        double worst = 0.0;
        for (int y = 0; y < a.height; ++y)
            for (int x = 0; x < a.width; ++x)
                for (int c = 0; c < 4; ++c) {
                    const double va = a.at(x, y, c), vb = b.at(x, y, c);
                    worst = std::max(worst, std::fabs(va - vb) / (std::max(std::fabs(va), std::fabs(vb)) + 1e-6));
                }
        return worst;
    };
    struct Case {
        const char* scene;
        const char* directionalInGBuffer;
        bool boundedLights;
    };
    for (const Case c : {Case{"default", "false", true}, Case{"default", "true", true}, Case{"street", "false", true},
                         Case{"street", "false", false}}) {
        const std::string what = std::string(c.scene) + ", directional_in_gbuffer " + c.directionalInGBuffer +
                                 (c.boundedLights ? "" : ", no bounded light");
        session->loadScene(c.scene);
        if (!c.boundedLights)
            for (Light& l : session->mutableScene().lights) l.enabled = l.type == LightType::Directional;
        session->knobs().setFromString("lighting.strategy", "tiled");
        session->knobs().setFromString("lighting.directional_in_gbuffer", c.directionalInGBuffer);
        std::map<std::string, FloatImage> lbuffer, overlap;
        for (const char* fused : {"false", "true"}) {
            session->knobs().setFromString("lighting.tile_ambient", fused);
            session->render({{"lbuffer", "lighting.overlap"}});
            // The L-buffer filled with NaN, then the frame again: a pixel
            // the first write misses keeps its NaN.
            const PublishedOutput* out = session->pipeline().outputs().find("lbuffer");
            ASSERT_TRUE(out && out->texture) << what;
            const float nan4[4] = {NAN, NAN, NAN, NAN};
            glClearTexImage(out->texture->id(), 0, GL_RGBA, GL_FLOAT, nan4);
            session->render({{"lbuffer", "lighting.overlap"}});
            lbuffer[fused] = session->readRaw("lbuffer");
            overlap[fused] = session->readRaw("lighting.overlap");
            // Which pass made the first write, as the statistics say.
            const std::string stats = lighting->stats();
            std::printf("%s, tile_ambient %s: %s\n", what.c_str(), fused, stats.c_str());
            EXPECT_EQ(stats.find("ambient, emission and sky in the tiled pass") != std::string::npos,
                      std::string(fused) == "true")
                << stats;
        }
        // Every pixel written (the sky or a lit surface), not all alike.
        const auto red = test::stats(lbuffer["true"], 0);
        for (int channel = 0; channel < 4; ++channel)
            for (const char* fused : {"false", "true"})
                EXPECT_EQ(test::stats(lbuffer[fused], channel).nonFinite, 0) << what << ", channel " << channel << ", " << fused;
        EXPECT_GT(red.min, 0.0) << what;
        EXPECT_GT(red.max, 2.0 * red.min) << what;
        const double worst = worstRelative(lbuffer["true"], lbuffer["false"]);
        std::printf("%s: tile_ambient on against off: worst relative difference %.3g\n", what.c_str(), worst);
        EXPECT_LE(worst, 1e-5) << what;
        EXPECT_EQ(test::maxAbsDifference(overlap["true"], overlap["false"], 1), 0.0) << what;
    }
}

// Mesa's CPU rasteriser ends all of an invocation's loops once it has run
// 65 535 iterations in all (renderer/gl/ShaderLoopLimit.h). 70 000 lights
// that each reach every pixel of a floor: the tiled pass walks more lists
// than one invocation's budget allows unless it takes fewer candidates per
// dispatch, the cluster assignment loops over every candidate, and every
// pixel's cluster and forward list hold all 70 000. Before they split their
// loops, tiled shaded 3832 of 3900 such lights and clustered lost every
// light past about 32 000 in view. Now every strategy counts all 70 000 at
// every pixel (lighting.overlap, for the grids) and its sum is the CPU's.
TEST(TiledLighting, ListsLongerThanTheCpuRasterisersLoopLimitLoseNoLight) {
    const int W = 16, H = 16, kLights = 70000;
    auto session = test::makeSession(W, H);
    Scene s = test::planeScene(40.0f);
    s.camera.position = {0.0f, 10.0f, 0.01f};
    s.camera.target = {0.0f, 0.0f, 0.0f};
    s.camera.fovYDegrees = 30.0f;
    s.materials[0].specularColor = glm::vec3(0.2f);
    s.materials[0].specularExponent = 8.0f;
    // 0.01 of intensity reaching 1/255 at 125 units: every light reaches the whole view.
    for (int i = 0; i < kLights; ++i) {
        const float u = std::fmod(i * 0.618034f, 1.0f), v = std::fmod(i * 0.414214f, 1.0f);
        test::addPointLight(s, {-4.0f + 8.0f * u, 1.0f + 2.0f * v, -4.0f + 8.0f * std::fmod(i * 0.7071f, 1.0f)},
                            glm::vec3(0.01f), {1.0f, 0.0f, 1e-4f});
    }
    const std::vector<Light> lights = s.lights;
    session->setScene(std::move(s));
    for (const char* strategy : {"tiled", "clustered", "forward"})
        for (const char* walk : {"mark", "branch"}) {
            if (std::string(strategy) != "tiled" && std::string(walk) == "branch") continue;
            const std::string what = std::string(strategy) + (std::string(strategy) == "tiled" ? std::string(", ") + walk : "");
            session->knobs().setFromString("lighting.strategy", strategy);
            session->knobs().setFromString("lighting.tile_walk", walk);
            session->render({{"lbuffer", "lighting.overlap", "gbuffer.view_position", "gbuffer.view_normal"}});
            const FloatImage L = session->readRaw("lbuffer"), overlap = session->readRaw("lighting.overlap");
            const test::GBufferImages g = test::readGBuffer(*session);
            const glm::dmat4 view = session->pipeline().lastCamera().worldToView();
            double worst = 0.0;
            int checked = 0;
            for (int y = 0; y < H; y += 5)
                for (int x = 0; x < W; x += 5) {
                    ASSERT_TRUE(g.surface(x, y)) << "the floor fills the view";
                    // forward counts its lists' lengths, over the parts a long one is drawn in.
                    EXPECT_EQ(overlap.at(x, y, 0), float(kLights)) << what << " at " << x << "," << y;
                    const glm::dvec3 expected = test::referenceRadiance(lights, view, g.at(x, y), 1.0 / 255.0);
                    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(L.at(x, y, c) - expected[c]) / expected[c]);
                    ++checked;
                }
            std::printf("%d lights reaching every pixel, %s: %s; worst relative difference to the CPU %.3g over %d "
                        "pixels\n",
                        kLights, what.c_str(), session->pipeline().pass<LightingPass>()->stats().c_str(), worst, checked);
            // Forward shades unquantised materials (ForwardLighting's bounds); a lost light is 1.4e-5 of the sum.
            EXPECT_LT(worst, std::string(strategy) == "forward" ? 2e-2 : 1e-3) << what;
        }

    // The tiled pass's budget at other tile sizes and thread counts, where
    // an invocation walks its list more often (fewer candidates a dispatch):
    // 5000 lights reaching every pixel of a 32 x 32 view, every one counted.
    const int W2 = 32, kFewer = 5000;
    session->resize(W2, W2);
    Scene& scene = session->mutableScene();
    scene.lights.resize(kFewer);
    session->setScene(Scene(scene));
    session->knobs().setFromString("lighting.strategy", "tiled");
    struct Setting {
        const char *tile, *threads;
    };
    for (const Setting t : {Setting{"32", "0"}, Setting{"16", "1"}, Setting{"16", "4"}, Setting{"8", "0"}})
        for (const char* walk : {"mark", "branch"}) {
            session->knobs().setFromString("lighting.tile_size", t.tile);
            session->knobs().setFromString("lighting.tile_threads", t.threads);
            session->knobs().setFromString("lighting.tile_walk", walk);
            session->render({{"lbuffer", "lighting.overlap"}});
            const FloatImage overlap = session->readRaw("lighting.overlap");
            const auto counted = test::stats(overlap, 0);
            EXPECT_EQ(counted.min, double(kFewer)) << "tile " << t.tile << ", threads " << t.threads << ", " << walk;
            EXPECT_EQ(counted.max, double(kFewer)) << "tile " << t.tile << ", threads " << t.threads << ", " << walk;
        }
}
