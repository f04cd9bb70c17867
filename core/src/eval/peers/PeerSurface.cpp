#include "eval/peers/PeerSurface.h"

#include "bake/BakeProgress.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace px::peers {

PeerSurface::PeerSurface(const HeightField& field, const PeerSurfaceOptions& options)
    : m_field(field), m_scale(options.heightScale), m_wrap(options.wrap),
      m_highest(options.heightScale * static_cast<double>(field.maxHeight())) {}

double PeerSurface::z(double x, double y) const {
    const double fx = std::floor(x), fy = std::floor(y);
    const double tx = x - fx, ty = y - fy;
    const int W = m_field.width, H = m_field.height;
    const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy); // rays stop within 4 tiles
    const int xa = wrapIndex(x0, W, m_wrap), xb = wrapIndex(x0 + 1, W, m_wrap);
    const int ya = wrapIndex(y0, H, m_wrap), yb = wrapIndex(y0 + 1, H, m_wrap);
    const double top = m_field.at(xa, ya) * (1 - tx) + m_field.at(xb, ya) * tx;
    const double bottom = m_field.at(xa, yb) * (1 - tx) + m_field.at(xb, yb) * tx;
    return m_scale * (top * (1 - ty) + bottom * ty);
}

glm::dvec3 PeerSurface::normal(int i, int j) const {
    const int W = m_field.width, H = m_field.height;
    // As the normal bake's central filter: with clamp, an edge difference spans what it spans.
    const auto slope = [&](int size, int at, auto height) {
        const int lo = wrapIndex(at - 1, size, m_wrap), hi = wrapIndex(at + 1, size, m_wrap);
        const int span =
            m_wrap == WrapMode::Repeat ? 2 : std::min(at + 1, size - 1) - std::max(at - 1, 0);
        return span > 0 ? (height(hi) - height(lo)) * size / span : 0.0;
    };
    const double dhdu = slope(W, i, [&](int x) { return double(m_field.at(x, j)); });
    const double dhdv = slope(H, j, [&](int y) { return double(m_field.at(i, y)); });
    return glm::normalize(glm::dvec3(-m_scale * dhdu, m_scale * dhdv, 1.0));
}

double PeerSurface::dx(double r, double phi) const {
    return r * std::cos(phi) * m_field.width;
}

double PeerSurface::dy(double r, double phi) const {
    return -r * std::sin(phi) * m_field.height;
}

Status checkSurface(const HeightField& field, const PeerSurfaceOptions& options) {
    if (field.empty())
        return Error{"the height map is empty"};
    if (!std::isfinite(options.heightScale) || options.heightScale < 0.0f)
        return Error{"the height scale must be a finite number >= 0"};
    return success();
}

Result<Image> everyTexel(const PeerSurface& surface, const BakeControl& control,
                         const std::function<float(int, int)>& texel) {
    const int W = surface.width(), H = surface.height();
    Image out(W, H, 1);
    const ImageWriter put = out.writer();
    BakeProgress progress(control, H);
    tbb::parallel_for(tbb::blocked_range<int>(0, H), [&](const tbb::blocked_range<int>& rows) {
        for (int j = rows.begin(); j < rows.end(); ++j) {
            if (progress.stopRequested())
                return;
            for (int i = 0; i < W; ++i)
                put.at(i, j, 0) = std::clamp(texel(i, j), 0.0f, 1.0f);
            progress.advance(1);
        }
    });
    if (progress.stopRequested())
        return cancelledError();
    progress.finish();
    return out;
}

} // namespace px::peers
