#pragma once
// The approximation families `tradeoff --attribute` takes apart: each a set
// of knobs that choose how the GPU approximates the shading model, with the
// values at which that family is at its most accurate. Every knob here is
// one the CPU reference ignores (ReferenceModel: it models the shading, not
// the approximation), so setting a family exact leaves the reference the
// same; ErrorAttribution checks that per scene and settings (the light
// threshold is part of the windowed attenuation's model, so under
// lighting.attenuation=windowed it stays as it is, and the output says so).
// "Most accurate" is what this project measured (docs/reference.md,
// docs/tradeoffs.md, docs/ao.md), not an exact method: the all-exact row is
// what no setting removes. Needs no GL.
#include <string>
#include <vector>

namespace dw {

struct ApproximationFamily {
    std::string name;                // the row's name: "shadows", "ao", ...
    std::string what;                // one line: what the family approximates
    std::vector<std::string> exact;  // knob=value: the family at its most accurate setting
};

// In a fixed order (the table's rows): shadows, ao, light_cutoff, gbuffer,
// texture_filter, transparency, bloom, dof, aa (aa.method).
const std::vector<ApproximationFamily>& approximationFamilies();

}  // namespace dw
