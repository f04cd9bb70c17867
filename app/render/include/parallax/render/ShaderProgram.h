#pragma once
// One compiled and linked variant. Uniforms are set by name with glProgramUniform* (no binding
// needed); a name the variant does not use is ignored, so callers set every parameter they have
// and each variant takes what it reads. Changing a value never recompiles.

#include "parallax/Result.h"
#include "parallax/render/GlObjects.h"
#include "parallax/shader/ShaderGenerator.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace px {

// One stage (GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER) compiled; `what` names it
// in the error ("the compute shader of the relaxed cone bake"), which carries the compiler log
// with positions as "shaders/FILE:LINE".
Result<gl::Object> compileShaderStage(unsigned stage, const GeneratedShader& source,
                                      const std::string& what);

class ShaderProgram {
public:
    // Compiles and links; errors carry the compiler log with positions as "shaders/FILE:LINE".
    static Result<ShaderProgram> build(const GeneratedProgram& program);

    unsigned id() const { return m_program.id(); }
    const VariantKey& key() const { return m_key; }
    void use() const;

    // -1 when the variant does not read it.
    int location(const std::string& name) const;
    void set(const std::string& name, float v) const;
    void set(const std::string& name, int v) const;
    void set(const std::string& name, glm::vec2 v) const;
    void set(const std::string& name, glm::vec3 v) const;
    void set(const std::string& name, const glm::mat3& v) const;
    void set(const std::string& name, const glm::mat4& v) const;
    void set(const std::string& name, std::span<const int> v) const;

    // The uniforms GL reports active, array names without "[0]", sorted: what the tests compare
    // with the generator's declarations.
    std::vector<std::string> activeUniforms() const;

private:
    gl::Object m_program;
    VariantKey m_key;
    std::unordered_map<std::string, int> m_locations;
};

} // namespace px
