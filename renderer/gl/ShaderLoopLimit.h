#pragma once
// How many loop iterations one shader invocation may run before the driver
// ends its loops without a word. Mesa's CPU rasterisers (llvmpipe, softpipe)
// give each batch of SIMD lanes one budget of 65535 iterations, summed over
// every loop it enters, each loop's test that ends it counting as one more
// (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS, one counter per batch, against
// shaders that never end; a batch runs as many iterations as its slowest
// lane): two loops of 40 000 iterations run 40 000 and 25 534 times there.
// Shaders whose loops scale with the light count (the tiled, clustered and
// forward strategies) split their work so that no invocation can reach it.
// Needs a current context.
namespace dw::gl {

// The budget on the current context's driver; 0 where none is known (GPU drivers).
int shaderLoopIterationLimit();

// LP_MAX_TGSI_LOOP_ITERATIONS in Mesa 22.3 (src/gallium/auxiliary/gallivm/lp_bld_limits.h).
inline constexpr int kMesaCpuLoopIterationLimit = 65535;

}  // namespace dw::gl
