#include "renderer/gl/TimestampQuery.h"

#include "renderer/Error.h"

namespace dw::gl {

TimestampQuery TimestampQuery::create() {
    GLuint id = 0;
    glCreateQueries(GL_TIMESTAMP, 1, &id);
    if (id == 0) throw Error("glCreateQueries(GL_TIMESTAMP) failed");
    TimestampQuery q;
    q.name_ = GlObject<QueryTraits>(id);
    return q;
}

void TimestampQuery::record() const { glQueryCounter(id(), GL_TIMESTAMP); }

bool TimestampQuery::available() const {
    GLuint ready = GL_FALSE;
    glGetQueryObjectuiv(id(), GL_QUERY_RESULT_AVAILABLE, &ready);
    return ready == GL_TRUE;
}

std::uint64_t TimestampQuery::result() const {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(id(), GL_QUERY_RESULT, &ns);
    return ns;
}

}  // namespace dw::gl
