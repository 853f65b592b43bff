#include "tests/support/AnimatedGltf.h"

#include <cmath>

#include "tests/support/GltfBuilder.h"

namespace dw::test {

using nlohmann::json;

json animatedGltf(bool withAnimation) {
    GltfBuilder b;
    const int pos = b.vec3({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
    const int nrm = b.vec3({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
    const int idx = b.indices({0, 1, 2, 0, 2, 3});
    const int joints = b.accessor(std::vector<std::uint16_t>{0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0}, 5123, "VEC4", 4);
    const int weights = b.accessor(std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 0.5f, 0.5f, 0, 0}, 5126, "VEC4", 4);
    const int ibm = b.accessor(std::vector<float>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,  //
                                                  1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1},
                               5126, "MAT4", 2);
    const int dpos = b.vec3({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
    const int dnrm = b.vec3({1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0});
    const int times = b.accessor(std::vector<float>{0, 1}, 5126, "SCALAR", 2);
    const int stepTimes = b.accessor(std::vector<float>{0, 0.25f}, 5126, "SCALAR", 2);
    const int translations = b.vec3({0, 0, 0, 2, 0, 0});
    const float h = static_cast<float>(std::sqrt(0.5));
    const int rotations = b.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, h, h}, 5126, "VEC4", 2);
    const int morphWeights = b.accessor(std::vector<float>{0, 1}, 5126, "SCALAR", 2);
    json j = b.finish({{"POSITION", pos}}, idx);
    json skinned = {{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"JOINTS_0", joints}, {"WEIGHTS_0", weights}}},
                    {"indices", idx}};
    json morphed = {{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}}, {"indices", idx}};
    morphed["targets"] = json::array({{{"POSITION", dpos}, {"NORMAL", dnrm}}});
    json mesh0 = json::object(), mesh1 = json::object();
    mesh0["primitives"] = json::array({skinned});
    mesh1["primitives"] = json::array({morphed});
    mesh1["weights"] = json::array({0.25});
    j["meshes"] = json::array({mesh0, mesh1});
    j["nodes"] = json::array({{{"mesh", 0}, {"skin", 0}},
                              {{"children", {2}}},
                              {{"translation", {0, 1, 0}}},
                              {{"mesh", 1}, {"translation", {3, 0, 0}}}});
    j["skins"] = json::array({{{"joints", {1, 2}}, {"inverseBindMatrices", ibm}}});
    j["scenes"] = json::array({{{"nodes", {0, 1, 3}}}});
    if (withAnimation)
        j["animations"] = json::array({{{"name", "move"},
                                        {"samplers", {{{"input", times}, {"output", translations}},
                                                      {{"input", times}, {"output", rotations}, {"interpolation", "LINEAR"}},
                                                      {{"input", stepTimes}, {"output", morphWeights}, {"interpolation", "STEP"}}}},
                                        {"channels", {{{"sampler", 0}, {"target", {{"node", 1}, {"path", "translation"}}}},
                                                      {{"sampler", 1}, {"target", {{"node", 2}, {"path", "rotation"}}}},
                                                      {{"sampler", 2}, {"target", {{"node", 3}, {"path", "weights"}}}}}}}});
    return j;
}

}  // namespace dw::test
