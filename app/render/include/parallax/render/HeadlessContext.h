#pragma once
// An OpenGL 4.3 core context with no window and no display: EGL on a GPU device where there is one
// (NVIDIA's EGL device platform), else Mesa's surfaceless platform (llvmpipe), else any EGL
// device. The renderer draws into framebuffer objects, so no surface is needed.
// PX_EGL_PLATFORM=device|surfaceless picks one. The context is current on the creating thread.

#include "parallax/Result.h"
#include "parallax/render/GlInfo.h"

#include <memory>
#include <string>

namespace px {

class HeadlessContext {
public:
    // Fails with one sentence listing each platform tried and what it offered, e.g. "no usable
    // OpenGL 4.3 context: surfaceless Mesa: found OpenGL 3.3 (softpipe); EGL device 0: ...".
    static Result<std::unique_ptr<HeadlessContext>> create();
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    bool makeCurrent();
    const GlInfo& info() const { return m_info; }
    // "surfaceless Mesa", "EGL device 0 (NVIDIA ...)".
    const std::string& platform() const { return m_platform; }

private:
    HeadlessContext() = default;
    void* m_display = nullptr;
    void* m_context = nullptr;
    void* m_surface = nullptr; // a 1x1 pbuffer where surfaceless contexts are not supported
    GlInfo m_info;
    std::string m_platform;
};

} // namespace px
