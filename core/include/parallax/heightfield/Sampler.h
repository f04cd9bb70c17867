#pragma once
// Bilinear sampling of a height field between texel centres with the material's wrap mode
// (docs/conventions.md §1), counting its fetches. It runs the trace kernels' own sampling code
// (shaders/trace/common.glsl), so bakers, tools and techniques read the surface identically.

#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

#include <memory>

namespace px {

class Sampler {
public:
    Sampler(const HeightField& field, WrapMode wrap);
    ~Sampler();
    Sampler(const Sampler&) = delete;
    Sampler& operator=(const Sampler&) = delete;

    // Height at (u, v) in uv units; one fetch.
    float sample(float u, float v);
    // The four corner texels of the cell whose top-left texel is (x, y): h00, h10, h01, h11.
    void cellCorners(int x, int y, float corners[4]);

    long long fetches() const { return m_fetches; }
    void resetFetches() { m_fetches = 0; }

private:
    struct Kernel;
    std::unique_ptr<Kernel> m_kernel;
    long long m_fetches = 0;
};

} // namespace px
