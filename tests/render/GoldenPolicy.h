#pragma once
// Which golden image a render is compared with, and how closely, on the renderer that made it.
//
// The goldens in tests/render/golden/ were made on Mesa's llvmpipe, which renders bit-identically
// on any CPU and thread count: there a render must match to rounding noise. A GPU (the EGL device
// platform of an NVIDIA machine, say) filters, interpolates and rounds differently, so:
//   - with goldens of its own, tests/render/golden/<renderer key>/ (recorded on that machine with
//     PX_UPDATE_GOLDEN=1), it is held to the same rounding-noise rule;
//   - without, it is compared with llvmpipe's under a tolerance that lets through filtering and
//     rounding differences and catches what breaks a picture (a wrong technique of the marching
//     family, lost relief, a flipped normal, missing shadows): see kGpuTolerance.
// Renderers that are neither (softpipe, SwiftShader) are treated as GPUs.

#include "RenderTestSupport.h"

#include <string>

namespace px::test {

struct GoldenTolerance {
    int stepsPerPixel;   // a pixel "differs" when a channel is more than this many 8-bit steps off
    double maxMeanSteps; // mean over every channel, in 8-bit steps
    double maxDifferingShare; // of the pixels
};

// llvmpipe against its own goldens (and any renderer against goldens it recorded itself).
inline constexpr GoldenTolerance kSameRendererTolerance{2, 0.25, 16.0 / (128 * 128)};
// A GPU against llvmpipe's goldens.
inline constexpr GoldenTolerance kGpuTolerance{24, 1.5, 0.02};

struct GoldenRule {
    std::string path; // the golden to compare with, or to write with PX_UPDATE_GOLDEN
    GoldenTolerance tolerance;
    std::string why; // one line for the test log
};

// "llvmpipe" for Mesa's llvmpipe; otherwise GL_RENDERER in lower case with every run of other
// characters turned into one '-': "NVIDIA GeForce RTX 4090/PCIe/SSE2" ->
// "nvidia-geforce-rtx-4090-pcie-sse2".
std::string rendererKey(const std::string& glRenderer);

// The rule for case `name` under golden folder `dir` on `glRenderer`. `updating`: the path where
// PX_UPDATE_GOLDEN writes (a GPU writes its own folder, never llvmpipe's goldens).
GoldenRule goldenRule(const std::string& dir, const std::string& name,
                      const std::string& glRenderer, bool updating = false);

bool withinTolerance(const ImageDifference& d, const GoldenTolerance& t, int pixels);

} // namespace px::test
