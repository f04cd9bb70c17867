#include "bake/FallPyramid.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace px::bake {

namespace {

constexpr int kLimit = 16383; // |stored| <= kLimit + 1: products with offsets fit in int

// A box of corner differences, in texel steps: (gx0, gx1, gy0, gy1).
struct Box {
    double gx0, gx1, gy0, gy1;
};

std::uint32_t pack(std::int32_t lo, std::int32_t hi) {
    return (static_cast<std::uint32_t>(lo) & 0xffffu) | (static_cast<std::uint32_t>(hi) << 16);
}
std::int32_t low(std::uint32_t w) {
    return static_cast<std::int16_t>(w & 0xffffu);
}
std::int32_t high(std::uint32_t w) {
    return static_cast<std::int16_t>(w >> 16);
}

// Writes a node: its highest corner rounded up to 16 bits of the map's maximum (0: none), the
// box scaled by 2^s (per node, so that small gradients keep their signs) and rounded outwards.
// The kernel decodes q as float(q) * unit in float: q is the least for which that is >= m.
void store(std::uint32_t* out, float m, const Box& b, float unit) {
    std::uint32_t q = 0;
    if (m > 0.0f && unit > 0.0f) {
        q = static_cast<std::uint32_t>(std::min(65535.0, std::ceil(double(m) / unit)));
        while (q > 1 && static_cast<float>(q - 1) * unit >= m)
            --q;
        while (q < 65535 && static_cast<float>(q) * unit < m)
            ++q;
    }
    const double most = std::max(std::max(-b.gx0, b.gx1), std::max(-b.gy0, b.gy1));
    int s = 0;
    if (most > 0.0) {
        int e = 0;
        std::frexp(kLimit / most, &e); // kLimit / most in [2^(e-1), 2^e)
        s = std::clamp(e - 1, -127, 127);
    }
    const double scale = std::ldexp(1.0, s);
    auto down = [scale](double d) {
        return static_cast<std::int32_t>(std::max<double>(-kLimit - 1, std::floor(d * scale) - 1));
    };
    auto up = [scale](double d) {
        return static_cast<std::int32_t>(std::min<double>(kLimit + 1, std::ceil(d * scale) + 1));
    };
    out[0] = q | static_cast<std::uint32_t>(s + 128) << 16;
    out[1] = pack(down(b.gx0), up(b.gx1));
    out[2] = pack(down(b.gy0), up(b.gy1));
}

// A stored node's box back in texel steps (it contains the box the node was made from).
Box load(const std::uint32_t* in) {
    const double scale = std::ldexp(1.0, -(static_cast<int>(in[0] >> 16) - 128));
    return {low(in[1]) * scale, high(in[1]) * scale, low(in[2]) * scale, high(in[2]) * scale};
}

} // namespace

FallPyramid::FallPyramid(const HeightField& f, WrapMode wrap, BakeProgress* progress) {
    const bool repeat = wrap == WrapMode::Repeat;
    const int W = f.width, H = f.height;
    const glm::ivec2 cells =
        repeat ? glm::ivec2(W, H) : glm::ivec2(std::max(W - 1, 1), std::max(H - 1, 1));
    const int sx = repeat || W > 1 ? 1 : 0, sy = repeat || H > 1 ? 1 : 0;
    m_size.push_back(cells);
    while (m_size.back().x > 1 || m_size.back().y > 1)
        m_size.emplace_back((m_size.back().x + 1) / 2, (m_size.back().y + 1) / 2);
    m_offset.assign(m_size.size(), 0);
    std::size_t words = 0;
    for (std::size_t l = 1; l < m_size.size(); ++l) {
        m_offset[l] = words;
        words += 3 * static_cast<std::size_t>(m_size[l].x) * static_cast<std::size_t>(m_size[l].y);
    }
    // 65535 units reach the map's maximum in float, as the kernel multiplies.
    const float top = f.maxHeight();
    m_unit = top > 0.0f ? top / 65535.0f : 0.0f;
    while (m_unit > 0.0f && 65535.0f * m_unit < top)
        m_unit = std::nextafter(m_unit, 1.0f);
    if (m_size.size() == 1)
        return;
    m_nodes.resize(words);
    const float unit = m_unit;
    auto texel = [&](int x, int y) {
        if (repeat)
            return f.at(x >= W ? x - W : x, y >= H ? y - H : y);
        return f.at(std::min(x, W - 1), std::min(y, H - 1));
    };
    auto stopped = [progress] { return progress && progress->stopRequested(); };
    // Level 1 from the cells.
    const glm::ivec2 one = m_size[1];
    std::uint32_t* level1 = &m_nodes[m_offset[1]];
    tbb::parallel_for(
        tbb::blocked_range<int>(0, one.y, 8), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y < rows.end(); ++y) {
                if (stopped())
                    return;
                for (int x = 0; x < one.x; ++x) {
                    float m = 0.0f;
                    Box box{0.0, 0.0, 0.0, 0.0};
                    bool any = false;
                    for (int j = 0; j < 2; ++j) {
                        for (int i = 0; i < 2; ++i) {
                            const int cx = 2 * x + i, cy = 2 * y + j;
                            if (cx >= cells.x || cy >= cells.y)
                                continue;
                            const float t00 = texel(cx, cy), t10 = texel(cx + sx, cy);
                            const float t01 = texel(cx, cy + sy), t11 = texel(cx + sx, cy + sy);
                            const double h00 = t00, h10 = t10, h01 = t01, h11 = t11;
                            if (h00 == h10 && h00 == h01 && h00 == h11)
                                continue; // flat: falls nowhere
                            m = std::max({m, t00, t10, t01, t11});
                            const Box c{
                                std::min(h10 - h00, h11 - h01), std::max(h10 - h00, h11 - h01),
                                std::min(h01 - h00, h11 - h10), std::max(h01 - h00, h11 - h10)};
                            box = any ? Box{std::min(box.gx0, c.gx0), std::max(box.gx1, c.gx1),
                                            std::min(box.gy0, c.gy0), std::max(box.gy1, c.gy1)}
                                      : c;
                            any = true;
                        }
                    }
                    store(level1 + 3 * (static_cast<std::size_t>(y) * one.x + x), any ? m : 0.0f,
                          box, unit);
                }
                if (progress)
                    progress->advance(2);
            }
        });
    for (std::size_t l = 2; l < m_size.size() && !stopped(); ++l) {
        const glm::ivec2 child = m_size[l - 1], parent = m_size[l];
        const std::uint32_t* in = &m_nodes[m_offset[l - 1]];
        std::uint32_t* outLevel = &m_nodes[m_offset[l]];
        tbb::parallel_for(
            tbb::blocked_range<int>(0, parent.y, 8), [&](const tbb::blocked_range<int>& rows) {
                for (int y = rows.begin(); y < rows.end(); ++y) {
                    for (int x = 0; x < parent.x; ++x) {
                        std::uint32_t m = 0;
                        Box box{0.0, 0.0, 0.0, 0.0};
                        bool any = false;
                        for (int j = 0; j < 2; ++j) {
                            for (int i = 0; i < 2; ++i) {
                                const int cx = 2 * x + i, cy = 2 * y + j;
                                if (cx >= child.x || cy >= child.y)
                                    continue;
                                const std::uint32_t* c =
                                    in + 3 * (static_cast<std::size_t>(cy) * child.x + cx);
                                if ((c[0] & 0xffffu) == 0)
                                    continue; // nothing that falls, or nothing above 0
                                m = std::max(m, c[0] & 0xffffu);
                                const Box b = load(c);
                                box = any ? Box{std::min(box.gx0, b.gx0), std::max(box.gx1, b.gx1),
                                                std::min(box.gy0, b.gy0), std::max(box.gy1, b.gy1)}
                                          : b;
                                any = true;
                            }
                        }
                        // The children's rounded maxima, kept as they are.
                        std::uint32_t* out =
                            outLevel + 3 * (static_cast<std::size_t>(y) * parent.x + x);
                        store(out, 0.0f, box, unit);
                        out[0] |= m;
                    }
                }
            });
    }
}

} // namespace px::bake
