#include "renderer/gl/CounterQuery.h"

#include <cstring>

#include "renderer/Error.h"

namespace dw::gl {

bool hasPipelineStatistics() {
    static const bool has = [] {
        GLint major = 0, minor = 0, count = 0;
        glGetIntegerv(GL_MAJOR_VERSION, &major);
        glGetIntegerv(GL_MINOR_VERSION, &minor);
        if (major > 4 || (major == 4 && minor >= 6)) return true;
        glGetIntegerv(GL_NUM_EXTENSIONS, &count);
        for (GLint i = 0; i < count; ++i) {
            const auto* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
            if (name && std::strcmp(name, "GL_ARB_pipeline_statistics_query") == 0) return true;
        }
        return false;
    }();
    return has;
}

const std::array<GLenum, CounterQueries::kCount>& CounterQueries::targets() {
    static const std::array<GLenum, kCount> t = {GL_FRAGMENT_SHADER_INVOCATIONS_ARB, GL_PRIMITIVES_SUBMITTED_ARB,
                                                 GL_VERTICES_SUBMITTED_ARB, GL_COMPUTE_SHADER_INVOCATIONS_ARB,
                                                 GL_SAMPLES_PASSED};
    return t;
}

CounterQueries CounterQueries::create(bool statistics) {
    CounterQueries q;
    for (int i = statistics ? 0 : kStatistics; i < kCount; ++i) {
        // glGenQueries: the object takes its target at its first glBeginQuery
        // (Mesa's glCreateQueries refuses the pipeline-statistics targets).
        GLuint id = 0;
        glGenQueries(1, &id);
        if (id == 0) throw Error("glGenQueries for a cost counter failed");
        q.names_[static_cast<size_t>(i)] = GlObject<QueryTraits>(id);
    }
    return q;
}

void CounterQueries::begin() const {
    for (size_t i = 0; i < kCount; ++i)
        if (names_[i]) glBeginQuery(targets()[i], names_[i].id());
}

void CounterQueries::end() const {
    for (size_t i = 0; i < kCount; ++i)
        if (names_[i]) glEndQuery(targets()[i]);
}

bool CounterQueries::available() const {
    for (const auto& n : names_) {
        if (!n) continue;
        GLuint ready = GL_FALSE;
        glGetQueryObjectuiv(n.id(), GL_QUERY_RESULT_AVAILABLE, &ready);
        if (ready != GL_TRUE) return false;
    }
    return true;
}

std::array<std::int64_t, CounterQueries::kCount> CounterQueries::results() const {
    std::array<std::int64_t, kCount> v;
    v.fill(-1);
    for (size_t i = 0; i < kCount; ++i) {
        if (!names_[i]) continue;
        GLuint64 n = 0;
        glGetQueryObjectui64v(names_[i].id(), GL_QUERY_RESULT, &n);
        v[i] = static_cast<std::int64_t>(n);
    }
    return v;
}

}  // namespace dw::gl
