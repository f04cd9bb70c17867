#pragma once
// What the GL tests share: one headless context per test process, the sample material, and
// image comparison.

#include "parallax/image/Image.h"
#include "parallax/material/Material.h"
#include "parallax/material/MaterialAssets.h"
#include "parallax/render/HeadlessContext.h"
#include "parallax/trace/Tracer.h"

#include <memory>
#include <string>

namespace px::test {

// Creates the context on first use and keeps it current; null (with the reason printed) when
// none can be made.
HeadlessContext* glContext();

// Mesa's llvmpipe: it runs the verify kernels as the CPU does, to the bit, filters with exact
// weights and made the goldens. On other renderers the tests allow what rounding may move.
bool isLlvmpipe(const std::string& glRenderer);

// The built-in bricks at `size` texels with their procedural albedo: the sample every golden
// image shows.
MaterialAssets bricksAssets(int size, bool withAlbedo = true);
// The material the goldens start from: bricks, s = 0.06, height-derived normals, Blinn-Phong.
Material sampleMaterial(Technique technique);

// A CPU Tracer for `field` with the material's technique, parameters and height scale (repeat).
Result<Tracer> makeTracerFor(const HeightField& field, Technique technique,
                             const Material& material);

struct ImageDifference {
    double meanAbs = 0.0; // over every channel, in 8-bit steps
    int maxAbs = 0;       // in 8-bit steps
    int pixelsOver = 0;   // pixels with a channel more than `tolerance` steps apart
    bool sameSize = false;
};
ImageDifference compareImages(const Image& a, const Image& b, int tolerance);

} // namespace px::test
