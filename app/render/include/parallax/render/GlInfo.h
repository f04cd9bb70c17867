#pragma once
// What the current OpenGL context is, and whether the renderer can use it.

#include "parallax/Result.h"

#include <string>

namespace px {

struct GlInfo {
    std::string vendor;
    std::string renderer;
    std::string version;
    std::string glsl;
    int major = 0;
    int minor = 0;
    bool core = false;

    // Mesa's llvmpipe/softpipe and other CPU rasterisers.
    bool software() const;
    // GL timer queries measure GPU time only on real GPUs: on llvmpipe they read about 1 ms for
    // 30-240 ms of work (docs/platform.md). Time with a steady clock around glFinish
    // there.
    bool timerQueriesMeaningful() const;
    // "OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits)".
    std::string summary() const;
};

// Queries the context current on this thread.
GlInfo currentGlInfo();

// The renderer needs OpenGL 4.3 core; the error names what was found.
Status requireGl43(const GlInfo& info);

// Fails with "WHAT: GL_INVALID_OPERATION" style sentences if glGetError reports anything.
Status checkGlError(const std::string& what);

} // namespace px
