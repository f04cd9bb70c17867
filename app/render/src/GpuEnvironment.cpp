#include "parallax/render/GpuEnvironment.h"

#include "parallax/render/GlInfo.h"
#include "parallax/render/TextureUpload.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <vector>

namespace px {

Result<std::unique_ptr<GpuEnvironment>> GpuEnvironment::create(const PrefilteredEnvironment& env) {
    if (env.specular.empty())
        return Error{"the environment has no prefiltered levels"};
    std::unique_ptr<GpuEnvironment> g(new GpuEnvironment);
    g->m_irradiance = env.irradiance;
    g->m_levels = static_cast<int>(env.specular.size());
    g->m_specular = gl::Object(gl::ObjectKind::Texture);
    glBindTexture(GL_TEXTURE_2D, g->m_specular.id());
    // Each level is the previous one's half (prefilterEnvironment), as GL's mip chain wants.
    for (int level = 0; level < g->m_levels; ++level) {
        const Image& img = env.specular[static_cast<std::size_t>(level)];
        std::vector<float> rgb(static_cast<std::size_t>(img.width) * img.height * 3);
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x)
                for (int c = 0; c < 3; ++c)
                    rgb[(static_cast<std::size_t>(y) * img.width + x) * 3 + c] = img.at(x, y, c);
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGB32F, img.width, img.height, 0, GL_RGB, GL_FLOAT,
                     rgb.data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, g->m_levels - 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    // Around the horizon it wraps; over the poles it must not.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);

    const Image table = makeSplitSumTable();
    Result<gl::Object> splitSum = gl::uploadRg32f(table.width, table.height, table.pixels.vector());
    if (!splitSum)
        return splitSum.error();
    g->m_splitSum = std::move(*splitSum);
    glBindTexture(GL_TEXTURE_2D, g->m_splitSum.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    if (Status s = checkGlError("uploading the environment"); !s)
        return s.error();
    return g;
}

void GpuEnvironment::bind(const ShaderProgram& program) const {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(TextureUnit::EnvSpecular));
    glBindTexture(GL_TEXTURE_2D, m_specular.id());
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(TextureUnit::SplitSum));
    glBindTexture(GL_TEXTURE_2D, m_splitSum.id());
    glActiveTexture(GL_TEXTURE0);
    const int location = program.location("pxIrradianceSh");
    if (location >= 0)
        glProgramUniform3fv(program.id(), location, 9, &m_irradiance[0].x);
    program.set("pxEnvMaxLevel", static_cast<float>(m_levels - 1));
}

} // namespace px
