#include "tests/support/GltfBuilder.h"

#include <fstream>

#include "tests/support/TestSupport.h"

namespace dw::test {

using nlohmann::json;

std::string base64(const std::vector<unsigned char>& data) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < data.size(); i += 3) {
        unsigned v = static_cast<unsigned>(data[i]) << 16;
        if (i + 1 < data.size()) v |= static_cast<unsigned>(data[i + 1]) << 8;
        if (i + 2 < data.size()) v |= data[i + 2];
        out += t[v >> 18];
        out += t[(v >> 12) & 63];
        out += i + 1 < data.size() ? t[(v >> 6) & 63] : '=';
        out += i + 2 < data.size() ? t[v & 63] : '=';
    }
    return out;
}

json GltfBuilder::finish(const json& attributes, int indexAccessor, const std::vector<json>& nodes) const {
    json j = doc;
    j["buffers"] = json::array({{{"byteLength", buffer.size()},
                                 {"uri", "data:application/octet-stream;base64," + base64(buffer)}}});
    json prim = {{"attributes", attributes}};
    if (indexAccessor >= 0) prim["indices"] = indexAccessor;
    j["meshes"] = json::array({{{"primitives", json::array({prim})}}});
    j["nodes"] = json::array();
    j["scenes"] = json::array({{{"nodes", json::array()}}});
    for (json n : nodes) {
        n["mesh"] = 0;
        j["scenes"][0]["nodes"].push_back(j["nodes"].size());
        j["nodes"].push_back(n);
    }
    j["scene"] = 0;
    return j;
}

std::filesystem::path writeJson(const std::string& name, const nlohmann::json& j) {
    const std::filesystem::path p = tempDir() / name;
    std::ofstream(p) << j.dump(1);
    return p;
}

}  // namespace dw::test
