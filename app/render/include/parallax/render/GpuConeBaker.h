#pragma once
// Cone maps baked on the GPU: the kernels of shaders/bake/ (the ones the CPU bakers compile as
// C++) as a GL 4.3 compute program, over the pyramids prepareConeBake() builds. On llvmpipe the
// maps equal the CPU's to the bit (render.GpuConeBake); on other GPUs the arithmetic may differ in
// the last bits (GLSL leaves division and square roots a few ulps of slack), which the 2^-20
// margin every cone keeps covers. The work goes in slices of about `sliceMilliseconds` each (a
// dispatch, then glFinish): progress and cancel as the CPU bakers have them, and a viewport
// sharing the GPU draws between slices.

#include "parallax/Result.h"
#include "parallax/bake/BakeControl.h"
#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/render/GlObjects.h"

#include <map>
#include <string>

namespace px {

struct GpuBakeInfo {
    std::string renderer;      // GL_RENDERER of the context that baked
    double milliseconds = 0.0; // upload, dispatches and read-back (not the CPU's pyramids)
    int dispatches = 0;
};

class GpuConeBaker {
public:
    // Needs an OpenGL 4.3 context current on the calling thread, for every call.
    GpuConeBaker() = default;
    GpuConeBaker(const GpuConeBaker&) = delete;
    GpuConeBaker& operator=(const GpuConeBaker&) = delete;

    // The raw cones (as bakeQuickConeMap() and bakeRelaxedConeMap(): not post-processed).
    // Errors: the CPU bakers', a map larger than the GPU's storage buffers, GL errors.
    Result<ConeMap> bakeRaw(const HeightField& field, WrapMode wrap, ConeKind kind,
                            const BakeControl& control = {}, GpuBakeInfo* info = nullptr);
    // What the techniques use: the raw bake, then the 3x3 minimum (as bakeConeMap()).
    Result<ConeMap> bake(const HeightField& field, WrapMode wrap, ConeKind kind,
                         const BakeControl& control = {}, GpuBakeInfo* info = nullptr);

    double sliceMilliseconds = 20.0;

private:
    Result<unsigned> program(ConeKind kind, WrapMode wrap);
    std::map<int, gl::Object> m_programs; // by kind * 2 + wrap
    int m_localSize = 0;                  // invocations a work group, chosen with the first program
};

// GpuConeBaker::bake on a headless context made for the call (HeadlessContext): for the command
// line.
Result<ConeMap> bakeConeMapHeadless(const HeightField& field, WrapMode wrap, ConeKind kind,
                                    const BakeControl& control = {}, GpuBakeInfo* info = nullptr);

} // namespace px
