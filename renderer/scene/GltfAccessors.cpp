#include "renderer/scene/GltfAccessors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "renderer/Error.h"
#include "renderer/scene/GltfModelCheck.h"

namespace dw {

namespace {

// Anything larger is treated as a corrupt count rather than allocated.
constexpr size_t kMaxElements = size_t(1) << 27;

}  // namespace

void GltfAccessorReader::fail(const std::string& what) const { throw FileError(path_, what); }

void GltfAccessorReader::check(int index) const {
    const auto& a = model_.accessors[index];
    const std::string what = "accessor[" + std::to_string(index) + "]";
    const int compSize = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
    const int comps = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
    if (compSize <= 0) fail(what + " has an invalid componentType " + std::to_string(a.componentType));
    if (comps <= 0) fail(what + " has an invalid type " + std::to_string(a.type));
    if (a.count > kMaxElements) fail(what + ".count " + std::to_string(a.count) + " is implausibly large");
    const size_t elem = static_cast<size_t>(compSize) * comps;
    if (a.bufferView >= 0) {
        checkGltfIndex(a.bufferView, model_.bufferViews, path_, what + ".bufferView", false);
        const auto& bv = model_.bufferViews[a.bufferView];
        const int stride = a.ByteStride(bv);
        if (stride <= 0) fail(what + " has an invalid byteStride in bufferView[" + std::to_string(a.bufferView) + "]");
        if (a.count > 0) {
            const size_t need = a.byteOffset + static_cast<size_t>(stride) * (a.count - 1) + elem;
            if (need > bv.byteLength)
                fail(what + " reads " + std::to_string(need) + " bytes but bufferView[" +
                     std::to_string(a.bufferView) + "] has only " + std::to_string(bv.byteLength));
        }
    }
    if (a.sparse.isSparse) {
        const std::string sw = what + ".sparse";
        if (a.sparse.count < 0 || static_cast<size_t>(a.sparse.count) > a.count)
            fail(sw + ".count is out of range");
        checkGltfIndex(a.sparse.indices.bufferView, model_.bufferViews, path_, sw + ".indices.bufferView", false);
        checkGltfIndex(a.sparse.values.bufferView, model_.bufferViews, path_, sw + ".values.bufferView", false);
        const int isz = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.sparse.indices.componentType));
        if (isz <= 0) fail(sw + ".indices has an invalid componentType");
        const auto& ibv = model_.bufferViews[a.sparse.indices.bufferView];
        const auto& vbv = model_.bufferViews[a.sparse.values.bufferView];
        if (a.sparse.indices.byteOffset < 0 ||
            static_cast<size_t>(a.sparse.indices.byteOffset) + static_cast<size_t>(isz) * a.sparse.count > ibv.byteLength)
            fail(sw + ".indices run past their bufferView");
        if (a.sparse.values.byteOffset < 0 ||
            static_cast<size_t>(a.sparse.values.byteOffset) + elem * a.sparse.count > vbv.byteLength)
            fail(sw + ".values run past their bufferView");
    }
}

std::vector<double> GltfAccessorReader::read(int index, int wantComponents, const std::string& what,
                                             bool allowNonFinite) const {
    const auto& a = model_.accessors[index];
    const int comps = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
    if (comps != wantComponents)
        fail(what + " (accessor[" + std::to_string(index) + "]) has " + std::to_string(comps) +
             " components, expected " + std::to_string(wantComponents));
    std::vector<double> out(a.count * comps, 0.0);
    auto readElement = [&](const unsigned char* p, double* dst) {
        for (int c = 0; c < comps; ++c) dst[c] = readComponent(p, c, a.componentType, a.normalized);
    };
    if (a.bufferView >= 0) {
        const auto& bv = model_.bufferViews[a.bufferView];
        const unsigned char* base = model_.buffers[bv.buffer].data.data() + bv.byteOffset + a.byteOffset;
        const int stride = a.ByteStride(bv);
        for (size_t i = 0; i < a.count; ++i) readElement(base + i * stride, &out[i * comps]);
    }
    if (a.sparse.isSparse) {
        const auto& ibv = model_.bufferViews[a.sparse.indices.bufferView];
        const auto& vbv = model_.bufferViews[a.sparse.values.bufferView];
        const unsigned char* ip = model_.buffers[ibv.buffer].data.data() + ibv.byteOffset + a.sparse.indices.byteOffset;
        const unsigned char* vp = model_.buffers[vbv.buffer].data.data() + vbv.byteOffset + a.sparse.values.byteOffset;
        const int isz = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.sparse.indices.componentType));
        const int esz = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType)) * comps;
        for (int s = 0; s < a.sparse.count; ++s) {
            const auto target = static_cast<size_t>(readComponent(ip + s * isz, 0, a.sparse.indices.componentType, false));
            if (target >= a.count) fail(what + ": sparse index " + std::to_string(target) + " out of range");
            readElement(vp + static_cast<size_t>(s) * esz, &out[target * comps]);
        }
    }
    if (!allowNonFinite)
        for (double d : out)
            if (!std::isfinite(d))
                fail(what + " (accessor[" + std::to_string(index) + "]) contains non-finite values");
    return out;
}

double GltfAccessorReader::readComponent(const unsigned char* p, int c, int type, bool normalized) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: { float v; std::memcpy(&v, p + 4 * c, 4); return v; }
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: { double v; std::memcpy(&v, p + 8 * c, 8); return v; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: { const double v = p[c]; return normalized ? v / 255.0 : v; }
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const double v = static_cast<int8_t>(p[c]);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v; std::memcpy(&v, p + 2 * c, 2);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t v; std::memcpy(&v, p + 2 * c, 2);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, p + 4 * c, 4); return v; }
        case TINYGLTF_COMPONENT_TYPE_INT: { int32_t v; std::memcpy(&v, p + 4 * c, 4); return v; }
        default: return 0.0;
    }
}

}  // namespace dw
