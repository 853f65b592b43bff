#pragma once
// Small glTF files written by tests: one buffer (a base64 data URI), accessors
// appended one by one, one mesh instanced by one node per transform.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace dw::test {

// Writes `j` as test::tempDir()/name (a .gltf or scene file) and returns the path.
std::filesystem::path writeJson(const std::string& name, const nlohmann::json& j);

std::string base64(const std::vector<unsigned char>& data);

struct GltfBuilder {
    std::vector<unsigned char> buffer;
    nlohmann::json doc = {{"asset", {{"version", "2.0"}}},
                          {"bufferViews", nlohmann::json::array()},
                          {"accessors", nlohmann::json::array()}};

    // Appends `values` (4-byte aligned) with its own bufferView; returns the accessor index.
    template <typename T>
    int accessor(const std::vector<T>& values, int componentType, const char* type, size_t count) {
        buffer.resize((buffer.size() + 3) & ~size_t(3));
        const size_t at = buffer.size();
        buffer.resize(at + values.size() * sizeof(T));
        std::memcpy(buffer.data() + at, values.data(), values.size() * sizeof(T));
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", values.size() * sizeof(T)}});
        doc["accessors"].push_back({{"bufferView", doc["bufferViews"].size() - 1},
                                    {"componentType", componentType},
                                    {"count", count},
                                    {"type", type}});
        return static_cast<int>(doc["accessors"].size() - 1);
    }
    int vec3(const std::vector<float>& v) { return accessor(v, 5126, "VEC3", v.size() / 3); }
    int indices(const std::vector<std::uint16_t>& v) { return accessor(v, 5123, "SCALAR", v.size()); }

    // The document: one mesh of one primitive (`attributes`, `indexAccessor`
    // or -1), under one root node per entry of `nodes` (their "mesh" is set).
    nlohmann::json finish(const nlohmann::json& attributes, int indexAccessor,
                          const std::vector<nlohmann::json>& nodes = {nlohmann::json::object()}) const;
};

}  // namespace dw::test
