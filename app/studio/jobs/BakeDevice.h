#pragma once
// Where a cone bake runs. The cone bakers are the same kernels on the CPU (TBB) and on the GPU
// (compute shaders, GpuConeBake.h); a software rasteriser runs the GPU's on the CPU's cores with
// none of their tuning, about 10 times slower than the CPU's bakers (llvmpipe, 1024² relaxed
// cones: 71.6 s against 7.2 s). So the CPU bakes when GL_RENDERER names a software rasteriser and
// the GPU otherwise, unless the artist chose one (Bake ▸ Device, kept in the settings).

#include <QString>

namespace px::studio {

enum class BakeDevicePreference { Automatic, Cpu, Gpu };

// llvmpipe, softpipe, swrast, SwiftShader, "Software Rasterizer" (Microsoft's, Apple's), any case.
bool isSoftwareRasteriser(const QString& glRenderer);

struct BakeDeviceChoice {
    bool gpu = false;
    QString why; // a phrase for the bake's line: "the GPU (llvmpipe) is a software rasteriser"
};

// `glRenderer`: the viewports' GL_RENDERER; `gpuShared`: whether a bake's context can share
// theirs (else only the CPU can bake).
BakeDeviceChoice chooseBakeDevice(BakeDevicePreference preference, const QString& glRenderer,
                                  bool gpuShared);

// The artist's choice, in the editor's settings ("bake/device": automatic, cpu, gpu).
BakeDevicePreference savedBakeDevicePreference();
void saveBakeDevicePreference(BakeDevicePreference preference);

} // namespace px::studio
