#include "parallax/render/GlInfo.h"

#include <GL/gl.h>
#include <GL/glext.h>

namespace px {

namespace {

std::string glString(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

const char* errorName(GLenum e) {
    switch (e) {
    case GL_INVALID_ENUM:
        return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
        return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
        return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
        return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
        return "GL_OUT_OF_MEMORY (the image or the maps are too large for this GPU)";
    default:
        return "an unknown GL error";
    }
}

} // namespace

bool GlInfo::software() const {
    for (const char* name : {"llvmpipe", "softpipe", "SwiftShader", "Software Rasterizer"}) {
        if (renderer.find(name) != std::string::npos)
            return true;
    }
    return false;
}

bool GlInfo::timerQueriesMeaningful() const {
    return !software();
}

std::string GlInfo::summary() const {
    if (version.empty())
        return "no OpenGL context";
    return "OpenGL " + version + ", " + renderer;
}

GlInfo currentGlInfo() {
    GlInfo info;
    info.vendor = glString(GL_VENDOR);
    info.renderer = glString(GL_RENDERER);
    info.version = glString(GL_VERSION);
    glGetIntegerv(GL_MAJOR_VERSION, &info.major);
    glGetIntegerv(GL_MINOR_VERSION, &info.minor);
    if (glGetError() != GL_NO_ERROR) {
        // Before 3.0 there is no GL_MAJOR_VERSION: read "X.Y" from the string.
        info.major = info.version.size() > 0 ? info.version[0] - '0' : 0;
        info.minor = info.version.size() > 2 ? info.version[2] - '0' : 0;
    }
    if (info.major >= 2)
        info.glsl = glString(GL_SHADING_LANGUAGE_VERSION);
    if (info.major > 3 || (info.major == 3 && info.minor >= 2)) {
        GLint mask = 0;
        glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
        info.core = (mask & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
    }
    glGetError();
    return info;
}

Status requireGl43(const GlInfo& info) {
    if (info.major > 4 || (info.major == 4 && info.minor >= 3))
        return success();
    return Error{"the renderer needs OpenGL 4.3; found " + info.summary()};
}

Status checkGlError(const std::string& what) {
    const GLenum e = glGetError();
    if (e == GL_NO_ERROR)
        return success();
    while (glGetError() != GL_NO_ERROR) {
    }
    return Error{what + ": " + errorName(e)};
}

} // namespace px
