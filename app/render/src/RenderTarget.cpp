#include "parallax/render/RenderTarget.h"

#include "parallax/render/GlInfo.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <algorithm>
#include <string>

namespace px {

Result<RenderTarget> RenderTarget::create(glm::ivec2 size, TargetFormat format) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
    if (size.x <= 0 || size.y <= 0 || size.x > maxSize || size.y > maxSize)
        return Error{"a " + std::to_string(size.x) + " x " + std::to_string(size.y) +
                     " image is outside what this GPU renders (1 to " + std::to_string(maxSize) +
                     " a side)"};
    RenderTarget t;
    t.m_size = size;
    t.m_format = format;
    t.m_framebuffer = gl::Object(gl::ObjectKind::Framebuffer);
    t.m_color = gl::Object(gl::ObjectKind::Renderbuffer);
    t.m_depth = gl::Object(gl::ObjectKind::Renderbuffer);
    glBindRenderbuffer(GL_RENDERBUFFER, t.m_color.id());
    glRenderbufferStorage(GL_RENDERBUFFER, format == TargetFormat::Rgba8 ? GL_RGBA8 : GL_RGBA32F,
                          size.x, size.y);
    glBindRenderbuffer(GL_RENDERBUFFER, t.m_depth.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size.x, size.y);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, t.m_framebuffer.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              t.m_color.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.m_depth.id());
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (Status s = checkGlError("creating a render target"); !s)
        return s.error();
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return Error{"the GL cannot render into a " + std::to_string(size.x) + " x " +
                     std::to_string(size.y) +
                     (format == TargetFormat::Rgba8 ? " RGBA8" : " RGBA32F") + " framebuffer"};
    return t;
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    glViewport(0, 0, m_size.x, m_size.y);
}

Image RenderTarget::read() const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_framebuffer.id());
    Image image = readFramebuffer(m_size, m_format);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return image;
}

Image readFramebuffer(glm::ivec2 size, TargetFormat format) {
    Image image(size.x, size.y, 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    if (format == TargetFormat::Rgba8) {
        std::vector<unsigned char> bytes(image.pixels.size());
        glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
        for (int y = 0; y < size.y; ++y) {
            const unsigned char* row =
                &bytes[static_cast<std::size_t>(size.y - 1 - y) * size.x * 4];
            for (int k = 0; k < size.x * 4; ++k)
                image.pixels[static_cast<std::size_t>(y) * size.x * 4 + k] = row[k] / 255.0f;
        }
    } else {
        std::vector<float> floats(image.pixels.size());
        glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_FLOAT, floats.data());
        for (int y = 0; y < size.y; ++y) {
            std::copy_n(&floats[static_cast<std::size_t>(size.y - 1 - y) * size.x * 4], size.x * 4,
                        &image.pixels[static_cast<std::size_t>(y) * size.x * 4]);
        }
    }
    return image;
}

} // namespace px
