// Lives beside the trace kernel it wraps (core/src/trace/TraceKernel.h).
#include "parallax/heightfield/Sampler.h"

#include "TraceKernel.h"

namespace px {

struct Sampler::Kernel : kernel::TraceKernel {};

Sampler::Sampler(const HeightField& field, WrapMode wrap) : m_kernel(std::make_unique<Kernel>()) {
    m_kernel->pxMapSize = glm::ivec2(field.width, field.height);
    m_kernel->pxWrapRepeat = wrap == WrapMode::Repeat;
    m_kernel->heightField = &field;
}

Sampler::~Sampler() = default;

float Sampler::sample(float u, float v) {
    ++m_fetches;
    return m_kernel->pxHeight(glm::vec2(u, v));
}

void Sampler::cellCorners(int x, int y, float corners[4]) {
    ++m_fetches;
    const glm::vec4 c = m_kernel->pxCellCorners(glm::ivec2(x, y));
    corners[0] = c.x;
    corners[1] = c.y;
    corners[2] = c.z;
    corners[3] = c.w;
}

} // namespace px
