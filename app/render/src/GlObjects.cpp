#include "parallax/render/GlObjects.h"

#include <GL/gl.h>
#include <GL/glext.h>

namespace px::gl {

Object::Object(ObjectKind kind) : m_kind(kind) {
    GLuint id = 0;
    switch (kind) {
    case ObjectKind::Texture:
        glGenTextures(1, &id);
        break;
    case ObjectKind::Buffer:
        glGenBuffers(1, &id);
        break;
    case ObjectKind::VertexArray:
        glGenVertexArrays(1, &id);
        break;
    case ObjectKind::Framebuffer:
        glGenFramebuffers(1, &id);
        break;
    case ObjectKind::Renderbuffer:
        glGenRenderbuffers(1, &id);
        break;
    case ObjectKind::Program:
        id = glCreateProgram();
        break;
    case ObjectKind::Shader:
        id = 0; // shaders need a stage: construct with Object(kind, glCreateShader(stage))
        break;
    case ObjectKind::Query:
        glGenQueries(1, &id);
        break;
    }
    m_id = id;
}

void Object::reset() {
    if (m_id == 0)
        return;
    GLuint id = m_id;
    switch (m_kind) {
    case ObjectKind::Texture:
        glDeleteTextures(1, &id);
        break;
    case ObjectKind::Buffer:
        glDeleteBuffers(1, &id);
        break;
    case ObjectKind::VertexArray:
        glDeleteVertexArrays(1, &id);
        break;
    case ObjectKind::Framebuffer:
        glDeleteFramebuffers(1, &id);
        break;
    case ObjectKind::Renderbuffer:
        glDeleteRenderbuffers(1, &id);
        break;
    case ObjectKind::Program:
        glDeleteProgram(id);
        break;
    case ObjectKind::Shader:
        glDeleteShader(id);
        break;
    case ObjectKind::Query:
        glDeleteQueries(1, &id);
        break;
    }
    m_id = 0;
}

} // namespace px::gl
