// Every binding point the shaders use, named once for GLSL and C++ (the way
// shaders/params/*.h share the parameter blocks). A shader includes it as
// "../common/bindings.glsl" in the file that declares a binding (so does
// shaders/params/prelude.h); C++ as "shaders/common/bindings.glsl"
// (renderer/scene/GpuScene.h and renderer/lighting/LightLists.h do, and the
// prelude's C++ half), where a name is dw::binding::NAME, an unsigned
// constexpr, and dw::binding::kAll the list as data. In GLSL a name is a
// `const int`, which layout(binding = NAME) takes (GLSL 4.40's constant
// expressions). docs/architecture.md, "Binding points".
//
// One line a binding point: BIND(kind, NAME, value), kind UBO (uniform
// block), SSBO (shader storage block), TEXTURE (texture unit of a sampler;
// an array takes value, value + 1, ...) or IMAGE (image unit). No shader
// here uses atomic counter buffers. Names say the family (pass or method)
// and the input; points are per family where a family's programs are alone
// in their pass (several families use texture unit 0, for example), and
// frame-wide where programs of several families meet (the lighting programs
// read the G-buffer, the shadow maps, the ambient inputs, the grid's
// candidates and, in transparency's, the material maps). tests/gl/
// BindingsTest.cpp compiles every program the pipeline builds and checks by
// reflection that every block, sampler and image sits at the name it
// declares, and that no two of one kind share a point in a program.
//
// Comments inside the list are /* */ (a // comment would swallow the line
// continuation).
#ifndef BINDINGS_GLSL
#define BINDINGS_GLSL

// clang-format off
#define DW_BINDINGS(BIND)                                                                       \
    /* Uniform blocks: the frame's camera, a pass's parameters, the oit pass's own. */         \
    BIND(UBO, CAMERA_UBO, 0)                                                                     \
    BIND(UBO, PASS_UBO, 3)                                                                       \
    BIND(UBO, OIT_UBO, 4)                 /* beside the lighting block at PASS_UBO */           \
    /* Storage blocks. GL 4.5 promises bindings 0 to 7 only. */                                 \
    BIND(SSBO, MATERIAL_SSBO, 1)                                                                 \
    BIND(SSBO, LIGHT_SSBO, 2)                                                                    \
    BIND(SSBO, CLUSTER_FILL_SSBO, 3)      /* clustered: free of every other pass's buffers */   \
    BIND(SSBO, LIGHT_CANDIDATES_SSBO, 4)  /* tiled and clustered: the candidates' rows */       \
    BIND(SSBO, FORWARD_LIGHTS_SSBO, 4)    /* forward: the lights a draw shades */               \
    BIND(SSBO, CLUSTER_GRID_SSBO, 5)                                                             \
    BIND(SSBO, CLUSTER_INDEX_SSBO, 6)                                                            \
    BIND(SSBO, TILE_COARSE_MASK_SSBO, 7)                                                         \
    BIND(SSBO, OIT_LIST_NODES_SSBO, 5)    /* linked list: the nodes */                          \
    BIND(SSBO, OIT_LIST_COUNTER_SSBO, 6)  /* linked list: the nodes used */                     \
    BIND(SSBO, OIT_LOST_TOTAL_SSBO, 7)    /* the frame's lost and arrived fragments */          \
    BIND(SSBO, LUMINANCE_REDUCE_IN_SSBO, 4)                                                      \
    BIND(SSBO, LUMINANCE_REDUCE_OUT_SSBO, 5)                                                     \
    BIND(SSBO, BUFFER_VIEW_RANGE_IN_SSBO, 4)   /* min/max reduction */                          \
    BIND(SSBO, BUFFER_VIEW_RANGE_OUT_SSBO, 5)                                                    \
    BIND(SSBO, BUFFER_VIEW_AUTO_RANGE_SSBO, 4) /* the reduction's result, read by view.frag */ \
    BIND(SSBO, BUFFER_VIEW_SOURCE_SSBO, 6)     /* a storage buffer shown as an image */         \
    /* The scene layer's skinning dispatch (shaders/scene/skin.comp, alone in it). */          \
    BIND(SSBO, SKIN_VERTICES_SSBO, 0)          /* the scene's vertex buffer, written */         \
    BIND(SSBO, SKIN_REST_SSBO, 1)                                                                \
    BIND(SSBO, SKIN_INFLUENCES_SSBO, 2)                                                          \
    BIND(SSBO, SKIN_MORPH_SSBO, 3)                                                               \
    BIND(SSBO, SKIN_JOINTS_SSBO, 4)                                                              \
    BIND(SSBO, SKIN_WEIGHTS_SSBO, 5)                                                             \
    /* Texture units the geometry, forward and transparency programs meet at: the */           \
    /* material maps (dw::GpuScene::bindMaterialTextures, units 0-3 as a run). */               \
    BIND(TEXTURE, MATERIAL_BASE_COLOR_TEXTURE, 0)                                                \
    BIND(TEXTURE, MATERIAL_NORMAL_TEXTURE, 1)                                                    \
    BIND(TEXTURE, MATERIAL_SPECULAR_TEXTURE, 2)                                                  \
    BIND(TEXTURE, MATERIAL_EMISSIVE_TEXTURE, 3)                                                  \
    BIND(TEXTURE, MATERIAL_OCCLUSION_TEXTURE, 10)                                                \
    /* The lighting programs' (shaders/lighting/gbuffer_read.glsl, units 0-5 as a run). */     \
    BIND(TEXTURE, GBUFFER_ALBEDO_TEXTURE, 0)                                                     \
    BIND(TEXTURE, GBUFFER_NORMAL_TEXTURE, 1)                                                     \
    BIND(TEXTURE, GBUFFER_SPECULAR_TEXTURE, 2)                                                   \
    BIND(TEXTURE, GBUFFER_EMISSIVE_TEXTURE, 3)                                                   \
    BIND(TEXTURE, GBUFFER_DEPTH_TEXTURE, 4)                                                      \
    BIND(TEXTURE, LIGHTING_OCCLUSION_TEXTURE, 5)    /* the ambient occlusion pass's result */   \
    BIND(TEXTURE, SHADOW_2D_TEXTURE, 6)             /* dw::ShadowMaps::bind */                  \
    BIND(TEXTURE, SHADOW_CUBE_TEXTURE, 7)                                                        \
    BIND(TEXTURE, SHADOW_PARABOLOID_TEXTURE, 8)                                                  \
    BIND(TEXTURE, AMBIENT_SKY_TEXTURE, 9)                                                        \
    BIND(TEXTURE, AMBIENT_BAKED_OCCLUSION_TEXTURE, 11)                                           \
    BIND(TEXTURE, AMBIENT_GBUFFER_DIRECTIONAL_TEXTURE, 12)                                       \
    BIND(TEXTURE, LIGHT_CANDIDATE_DATA_TEXTURE, 13) /* tiled and clustered */                   \
    BIND(TEXTURE, CLUSTER_RANGE_TEXTURE, 14)                                                     \
    /* Transparency's inputs beside the lighting ones (shaders/oit). */                        \
    BIND(TEXTURE, OIT_PREVIOUS_DEPTH_TEXTURE, 13)   /* depth and dual depth peeling */          \
    BIND(TEXTURE, OIT_LAYER_COLOR_TEXTURE, 13)      /* depth peeling's compose */               \
    BIND(TEXTURE, OIT_LAYER_DEPTH_TEXTURE, 14)                                                   \
    BIND(TEXTURE, OIT_FRONT_LAYER_TEXTURE, 13)      /* dual depth peeling's compose */          \
    BIND(TEXTURE, OIT_BACK_LAYER_TEXTURE, 14)                                                    \
    BIND(TEXTURE, OIT_SAMPLES_TEXTURE, 13)          /* resolve: the A-buffer */                 \
    BIND(TEXTURE, OIT_SAMPLE_DEPTH_TEXTURE, 14)                                                  \
    BIND(TEXTURE, OIT_ACCUM_TEXTURE, 13)            /* resolve: weighted */                     \
    BIND(TEXTURE, OIT_REVEALAGE_TEXTURE, 14)                                                     \
    BIND(TEXTURE, OIT_PEEL_ACCUM_TEXTURE, 13)       /* resolve: depth peeling */                \
    BIND(TEXTURE, OIT_FRONT_ACCUM_TEXTURE, 13)      /* resolve: dual depth peeling */           \
    BIND(TEXTURE, OIT_BACK_ACCUM_TEXTURE, 14)                                                    \
    /* Texture units of passes whose programs are alone in their pass. */                      \
    BIND(TEXTURE, SHADOW_SUMS_TEXTURE, 0)           /* lighting's shadow_resolve.frag */        \
    BIND(TEXTURE, SSAO_DEPTH_TEXTURE, 0)                                                         \
    BIND(TEXTURE, SSAO_NORMAL_TEXTURE, 1)                                                        \
    BIND(TEXTURE, SSAO_NOISE_TEXTURE, 2)                                                         \
    BIND(TEXTURE, AO_FILTER_SOURCE_TEXTURE, 0)      /* ssao's blur and upsample */              \
    BIND(TEXTURE, AO_FILTER_DEPTH_TEXTURE, 1)                                                    \
    BIND(TEXTURE, GTAO_DEPTH_TEXTURE, 0)                                                         \
    BIND(TEXTURE, GTAO_NORMAL_TEXTURE, 1)                                                        \
    BIND(TEXTURE, GTAO_NOISY_TEXTURE, 2)            /* the denoiser's input */                  \
    BIND(TEXTURE, AOV_GBUFFER_DEPTH_TEXTURE, 0)     /* aov_depth.frag */                        \
    BIND(TEXTURE, AOV_VOLUME_DEPTH_TEXTURE, 11)     /* aov_volume.frag */                       \
    BIND(TEXTURE, AOV_VOLUME_NORMAL_TEXTURE, 12)                                                 \
    BIND(TEXTURE, AOV_OCCLUSION_TEXTURE, 0)         /* aov_resolve.frag */                      \
    BIND(TEXTURE, SKY_DEPTH_TEXTURE, 0)                                                          \
    BIND(TEXTURE, SKY_EQUIRECT_TEXTURE, 1)                                                       \
    BIND(TEXTURE, SKY_CUBE_TEXTURE, 2)                                                           \
    BIND(TEXTURE, LUMINANCE_HDR_TEXTURE, 0)                                                      \
    BIND(TEXTURE, LUMINANCE_DEPTH_TEXTURE, 1)                                                    \
    BIND(TEXTURE, BLOOM_HDR_TEXTURE, 0)             /* bright.frag */                           \
    BIND(TEXTURE, BLOOM_STATS_TEXTURE, 1)                                                        \
    BIND(TEXTURE, BLOOM_SOURCE_TEXTURE, 0)          /* down.frag, scale.frag */                 \
    BIND(TEXTURE, BLOOM_BRIGHT_TEXTURE, 0)          /* mipsum.frag */                           \
    BIND(TEXTURE, BLOOM_LEVELS_TEXTURE, 1)          /* mipsum.frag: an array, units 1-6 */      \
    BIND(TEXTURE, BLOOM_COARSE_TEXTURE, 0)          /* up.frag */                               \
    BIND(TEXTURE, BLOOM_SAME_TEXTURE, 1)                                                         \
    BIND(TEXTURE, TONEMAP_HDR_TEXTURE, 0)                                                        \
    BIND(TEXTURE, TONEMAP_STATS_TEXTURE, 1)                                                      \
    BIND(TEXTURE, TONEMAP_BLOOM_TEXTURE, 2)                                                      \
    BIND(TEXTURE, DOF_IMAGE_TEXTURE, 0)                                                          \
    BIND(TEXTURE, DOF_DEPTH_TEXTURE, 1)                                                          \
    BIND(TEXTURE, FXAA_IMAGE_TEXTURE, 0)                                                         \
    BIND(TEXTURE, SSAA_SOURCE_TEXTURE, 0)           /* post/ssaa_resolve.frag */                \
    BIND(TEXTURE, TAA_CURRENT_TEXTURE, 0)           /* post/taa.frag */                         \
    BIND(TEXTURE, TAA_HISTORY_TEXTURE, 1)                                                        \
    BIND(TEXTURE, TAA_DEPTH_TEXTURE, 2)                                                          \
    BIND(TEXTURE, MSAA_ALBEDO_TEXTURE, 0)           /* MSAA: the multisampled G-buffer */        \
    BIND(TEXTURE, MSAA_NORMAL_TEXTURE, 1)                                                        \
    BIND(TEXTURE, MSAA_SPECULAR_TEXTURE, 2)                                                      \
    BIND(TEXTURE, MSAA_EMISSIVE_TEXTURE, 3)                                                      \
    BIND(TEXTURE, MSAA_OCCLUSION_TEXTURE, 4)                                                     \
    BIND(TEXTURE, MSAA_DEPTH_TEXTURE, 5)                                                         \
    BIND(TEXTURE, MSAA_DIRECTIONAL_TEXTURE, 6)                                                   \
    BIND(TEXTURE, MSAA_EDGES_TEXTURE, 7)            /* aa.edges */                               \
    BIND(TEXTURE, MSAA_LBUFFER_TEXTURE, 0)          /* lighting/msaa_accumulate.frag */          \
    BIND(TEXTURE, GBUFFER_DECODE_NORMAL_TEXTURE, 0)                                              \
    BIND(TEXTURE, GBUFFER_DECODE_DEPTH_TEXTURE, 1)                                               \
    BIND(TEXTURE, BUFFER_VIEW_SOURCE_TEXTURE, 0)                                                 \
    /* Image units. */                                                                         \
    BIND(IMAGE, TILED_LBUFFER_IMAGE, 0)                                                          \
    BIND(IMAGE, TILED_OVERLAP_IMAGE, 1)             /* lighting.overlap */                      \
    BIND(IMAGE, TILED_COUNTS_IMAGE, 2)              /* lighting.tile_counts */                  \
    BIND(IMAGE, CLUSTER_COUNTS_IMAGE, 2)            /* lighting.cluster_counts */               \
    BIND(IMAGE, OIT_FRAGMENT_COUNT_IMAGE, 0)        /* oit.sample_count */                      \
    BIND(IMAGE, OIT_LIST_HEADS_IMAGE, 1)                                                         \
    BIND(IMAGE, OIT_OVERFLOW_IMAGE, 2)              /* oit.overflow */                          \
    BIND(IMAGE, OIT_PEEL_LAYERS_IMAGE, 3)           /* oit.peel_layers */                       \
    BIND(IMAGE, OIT_DUAL_CLAIMS_IMAGE, 4)           /* oit.dual_claims */                       \
    BIND(IMAGE, AOV_OVERDRAW_IMAGE, 0)              /* aov.overdraw */                          \
    BIND(IMAGE, LUMINANCE_STATS_IMAGE, 0)           /* luminance.stats */
// clang-format on

#ifdef __cplusplus
namespace dw::binding {
enum class Kind { UBO, SSBO, TEXTURE, IMAGE };
#define DW_BINDING_CPP_CONSTANT(kind, name, value) inline constexpr unsigned name = value;
DW_BINDINGS(DW_BINDING_CPP_CONSTANT)
#undef DW_BINDING_CPP_CONSTANT
// The list as data, for the bindings test: {"CAMERA_UBO", Kind::UBO, 0}, ...
struct Named {
    const char* name;
    Kind kind;
    unsigned value;
};
#define DW_BINDING_CPP_ROW(kind, name, value) Named{#name, Kind::kind, value},
inline constexpr Named kAll[] = {DW_BINDINGS(DW_BINDING_CPP_ROW)};
#undef DW_BINDING_CPP_ROW
}  // namespace dw::binding
#else
#define DW_BINDING_GLSL_CONSTANT(kind, name, value) const int name = value;
DW_BINDINGS(DW_BINDING_GLSL_CONSTANT)
#endif
#endif
