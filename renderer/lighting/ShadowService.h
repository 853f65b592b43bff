#pragma once
// How a lighting strategy gets a light's shadow map at the moment it needs it.
// With map reuse (seed 002 section 3.3's flip-flop) one layer serves every
// light, so the map is rendered just before its light is shaded; otherwise
// every map was rendered up front and this only makes sure it is bound.
namespace dw {

struct FrameContext;
struct LightTableEntry;

class ShadowService {
public:
    virtual ~ShadowService() = default;
    // Makes the entry's map current; when that meant rendering it (reuse),
    // patches the light's row of the light table and returns true: GL state
    // and texture bindings are then the caller's to restore.
    virtual bool prepare(FrameContext& ctx, const LightTableEntry& entry) = 0;
    // Binds the maps with their comparison samplers (units 6, 7, 8).
    virtual void bind() const = 0;
    // Whether every shadowed light's map exists now, its lookup in the light
    // table (no reuse this frame): a pass after the lighting (oit) may then
    // look up any light's shadow. With a reused map only the last light's is left.
    virtual bool everyMapKept() const { return false; }
};

}  // namespace dw
