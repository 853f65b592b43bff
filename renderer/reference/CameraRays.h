#pragma once
// The camera as the GPU sets it up (Pipeline::cameraUniforms): a rotation
// about the eye, GL's perspective, and rays through points of the image with
// view depth as their parameter (the direction's view-space z is -1), so a
// ray's t between nearPlane and farPlane is the rasteriser's clipping.
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/Camera.h"

namespace dw::reference {

struct CameraRays {
    glm::dmat3 viewToWorld;  // rotation
    glm::dmat3 worldToView;
    double tanHalf, aspect, nearPlane, farPlane;
    int width, height;
    CameraRays(const Camera& c, int w, int h) : width(w), height(h) {
        const glm::dvec3 eye(c.position);
        const glm::dmat4 view = glm::lookAt(glm::dvec3(0.0), glm::dvec3(c.target) - eye, glm::dvec3(c.up));
        worldToView = glm::dmat3(view);
        viewToWorld = glm::transpose(worldToView);
        tanHalf = std::tan(static_cast<double>(c.fovYDegrees) * 3.14159265358979323846 / 360.0);
        aspect = static_cast<double>(w) / h;
        nearPlane = c.nearPlane;
        farPlane = c.farPlane;
    }
    // Through normalised device coordinates (x, y in [-1, 1], y up).
    glm::dvec3 directionAtNdc(double ndcX, double ndcY) const {
        return viewToWorld * glm::dvec3(ndcX * tanHalf * aspect, ndcY * tanHalf, -1.0);
    }
    // Through a pixel's centre; row 0 at the top of the image (GL's window y counts from the bottom).
    glm::dvec3 direction(int x, int row) const {
        return directionAtNdc((x + 0.5) / width * 2.0 - 1.0, ((height - 1 - row) + 0.5) / height * 2.0 - 1.0);
    }
    // Through an image point (px, py) in pixels from the image's top-left
    // corner (py downwards): direction(x, row) is directionAt(x + 0.5, row + 0.5).
    glm::dvec3 directionAt(double px, double py) const {
        return directionAtNdc(px / width * 2.0 - 1.0, (height - py) / height * 2.0 - 1.0);
    }
    // A view-space point's normalised device coordinates (x, y).
    glm::dvec2 ndcOf(const glm::dvec3& view) const {
        return {view.x / (-view.z * tanHalf * aspect), view.y / (-view.z * tanHalf)};
    }
};

}  // namespace dw::reference
