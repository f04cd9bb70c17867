#include "parallax/render/ShaderProgram.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <algorithm>
#include <cstring>
#include <glm/gtc/type_ptr.hpp>

namespace px {

namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
}

Result<gl::Object> compile(GLenum stage, const GeneratedShader& source, const std::string& name) {
    return compileShaderStage(stage, source,
                              "the " +
                                  std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                                  " shader of " + name);
}

} // namespace

Result<gl::Object> compileShaderStage(unsigned stage, const GeneratedShader& source,
                                      const std::string& what) {
    gl::Object shader(gl::ObjectKind::Shader, glCreateShader(stage));
    const char* text = source.text.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok)
        return Error{what + " does not compile:\n" +
                     mapCompilerLog(shaderLog(shader.id()), source.sources)};
    return shader;
}

Result<ShaderProgram> ShaderProgram::build(const GeneratedProgram& generated) {
    const std::string name = generated.key.name();
    Result<gl::Object> vertex = compile(GL_VERTEX_SHADER, generated.vertex, name);
    if (!vertex)
        return vertex.error();
    Result<gl::Object> fragment = compile(GL_FRAGMENT_SHADER, generated.fragment, name);
    if (!fragment)
        return fragment.error();
    ShaderProgram p;
    p.m_key = generated.key;
    p.m_program = gl::Object(gl::ObjectKind::Program);
    glAttachShader(p.id(), vertex->id());
    glAttachShader(p.id(), fragment->id());
    glLinkProgram(p.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(p.id(), GL_LINK_STATUS, &ok);
    glDetachShader(p.id(), vertex->id());
    glDetachShader(p.id(), fragment->id());
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(p.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
        glGetProgramInfoLog(p.id(), length, nullptr, log.data());
        log.resize(std::strlen(log.c_str()));
        return Error{"the shader of " + name + " does not link: " + log};
    }
    GLint count = 0;
    glGetProgramiv(p.id(), GL_ACTIVE_UNIFORMS, &count);
    for (GLint i = 0; i < count; ++i) {
        char buffer[256];
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(p.id(), static_cast<GLuint>(i), sizeof buffer, nullptr, &size, &type,
                           buffer);
        std::string uniform = buffer;
        if (const std::size_t bracket = uniform.find('['); bracket != std::string::npos)
            uniform.resize(bracket);
        p.m_locations[uniform] = glGetUniformLocation(p.id(), buffer);
    }
    return p;
}

void ShaderProgram::use() const {
    glUseProgram(id());
}

int ShaderProgram::location(const std::string& name) const {
    const auto it = m_locations.find(name);
    return it == m_locations.end() ? -1 : it->second;
}

void ShaderProgram::set(const std::string& name, float v) const {
    if (const int l = location(name); l >= 0)
        glProgramUniform1f(id(), l, v);
}
void ShaderProgram::set(const std::string& name, int v) const {
    if (const int l = location(name); l >= 0)
        glProgramUniform1i(id(), l, v);
}
void ShaderProgram::set(const std::string& name, glm::vec2 v) const {
    if (const int l = location(name); l >= 0)
        glProgramUniform2f(id(), l, v.x, v.y);
}
void ShaderProgram::set(const std::string& name, glm::vec3 v) const {
    if (const int l = location(name); l >= 0)
        glProgramUniform3f(id(), l, v.x, v.y, v.z);
}
void ShaderProgram::set(const std::string& name, const glm::mat3& v) const {
    if (const int l = location(name); l >= 0)
        glProgramUniformMatrix3fv(id(), l, 1, GL_FALSE, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& name, const glm::mat4& v) const {
    if (const int l = location(name); l >= 0)
        glProgramUniformMatrix4fv(id(), l, 1, GL_FALSE, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& name, std::span<const int> v) const {
    if (const int l = location(name); l >= 0)
        glProgramUniform1iv(id(), l, static_cast<GLsizei>(v.size()), v.data());
}

std::vector<std::string> ShaderProgram::activeUniforms() const {
    std::vector<std::string> names;
    for (const auto& [name, location] : m_locations)
        names.push_back(name);
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace px
