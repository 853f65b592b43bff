#include "renderer/gl/DeviceLimits.h"

#include <algorithm>
#include <map>
#include <vector>

namespace dw::gl {

namespace {
int maxSamplesFor(GLenum format) {
    static std::map<GLenum, int> cache;
    if (auto it = cache.find(format); it != cache.end()) return it->second;
    GLint count = 0;
    glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, format, GL_NUM_SAMPLE_COUNTS, 1, &count);
    int best = 1;
    if (count > 0) {
        std::vector<GLint> samples(static_cast<size_t>(count), 0);
        glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, format, GL_SAMPLES, count, samples.data());
        for (GLint s : samples) best = std::max(best, static_cast<int>(s));
    }
    cache[format] = best;
    return best;
}
}  // namespace

int maxMultisampleSamples(std::initializer_list<GLenum> formats) {
    int cap = 1 << 30;
    for (GLenum f : formats) cap = std::min(cap, maxSamplesFor(f));
    return std::max(cap, 1);
}

}  // namespace dw::gl
