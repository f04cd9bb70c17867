#pragma once
// An offscreen framebuffer: colour (RGBA8 for images, RGBA32F for hit data) and depth. What the
// command line and the tests render into; the editor renders into QOpenGLWidget's framebuffer.

#include "parallax/Result.h"
#include "parallax/image/Image.h"
#include "parallax/render/GlObjects.h"

#include <glm/vec2.hpp>

namespace px {

enum class TargetFormat { Rgba8, Rgba32F };

class RenderTarget {
public:
    // Fails over the GL's largest renderbuffer or when the framebuffer is incomplete.
    static Result<RenderTarget> create(glm::ivec2 size, TargetFormat format);

    unsigned framebuffer() const { return m_framebuffer.id(); }
    glm::ivec2 size() const { return m_size; }
    TargetFormat format() const { return m_format; }
    void bind() const; // as the draw framebuffer, viewport covering it

    // The colour attachment as an image, row 0 at the top (GL's row 0 is the bottom); RGBA, 8-bit
    // values scaled to [0, 1] or floats verbatim.
    Image read() const;

private:
    gl::Object m_framebuffer, m_color, m_depth;
    glm::ivec2 m_size{0};
    TargetFormat m_format = TargetFormat::Rgba8;
};

// Reads the colour of the framebuffer bound for reading into an image (top row first).
Image readFramebuffer(glm::ivec2 size, TargetFormat format);

} // namespace px
