#pragma once
// Lights grouped into batches whose screen rectangles do not overlap, so one
// draw can stencil-mark (and then shade) every light of a batch at
// once: within a batch no pixel is reached by two volumes, so the per-light
// stencil count of the volume test (seed 001 section 2.2, seed 000 section
// 3.2.1) stays exact. This is what cuts the stencil strategy's per-light CPU
// cost (seed 003 table 4.3 counts draw calls per light): two draws per batch
// instead of two per light.
#include <glm/glm.hpp>
#include <vector>

namespace dw {

// Pixels [x0, x1) x [y0, y1) of a width x height image; empty when x0 >= x1 or y0 >= y1.
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x0 >= x1 || y0 >= y1; }
};

// The pixels a convex volume can rasterise to: the projection of the 8
// corners of its local box [boxMin, boxMax] under `localToClip`, widened by
// one pixel and clipped to the image. The whole image when any corner is not
// in front of the eye (w <= 0: the camera is in or behind the box), since
// depth clamping keeps such volumes from being clipped at the near plane.
PixelRect screenRect(const glm::dmat4& localToClip, const glm::vec3& boxMin, const glm::vec3& boxMax, int width,
                     int height);

// Assigns each rectangle a batch (the returned vector, one index per
// rectangle, batches numbered from 0 in order of first use) so that no two
// rectangles of one batch share a pixel. Greedy first fit over a grid of
// cells (at most 64 x 64): two rectangles in one batch never touch a common
// cell, which is stricter than pixel-disjoint, so a few more batches than
// needed may appear, never a wrong one. Empty rectangles go into batch 0.
std::vector<int> disjointBatches(const std::vector<PixelRect>& rects, int width, int height);

}  // namespace dw
