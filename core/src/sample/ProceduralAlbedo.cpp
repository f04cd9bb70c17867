#include "parallax/sample/ProceduralAlbedo.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace px {
namespace {

using Rgb = std::array<float, 3>;

std::uint32_t mix32(std::uint32_t h) {
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

float hash01(int x, int y, unsigned seed) {
    const std::uint32_t h = mix32(static_cast<std::uint32_t>(x) * 0x9e3779b1u ^
                                  mix32(static_cast<std::uint32_t>(y) + seed * 0x85ebca6bu));
    return static_cast<float>(h & 0xffffffu) / static_cast<float>(0x1000000);
}

// Periodic value noise, `cells` lattice cells across the tile in u and v: tiles seamlessly.
float valueNoise(float u, float v, int cellsU, int cellsV, unsigned seed) {
    const float x = u * cellsU, y = v * cellsV;
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    auto smooth = [](float t) { return t * t * (3.0f - 2.0f * t); };
    const float fx = smooth(x - x0), fy = smooth(y - y0);
    auto at = [&](int i, int j) {
        return hash01(((i % cellsU) + cellsU) % cellsU, ((j % cellsV) + cellsV) % cellsV, seed);
    };
    const float a = at(x0, y0), b = at(x0 + 1, y0), c = at(x0, y0 + 1), d = at(x0 + 1, y0 + 1);
    return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
}

float smoothstep(float lo, float hi, float x) {
    const float t = std::clamp((x - lo) / (hi - lo), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

Rgb lerp(const Rgb& a, const Rgb& b, float t) {
    return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}

Rgb scaled(const Rgb& c, float k) {
    return {c[0] * k, c[1] * k, c[2] * k};
}

// How one kind of sample looks: the raised regions' palette, the low ground's colour, where the
// one turns into the other, and how much grain each has.
struct Look {
    float threshold;            // raised regions start above this height
    float blendLo, blendHi;     // ground -> region colour over these heights
    std::array<Rgb, 5> palette; // one picked per raised region
    Rgb ground;                 // mortar, earth, plate
    float regionGrain, groundGrain;
    bool brushed; // grain stretched along u (brushed metal)
};

Look lookFor(ProceduralMap kind) {
    switch (kind) {
    case ProceduralMap::Bricks:
        return {0.16f,
                0.12f,
                0.22f,
                {{{0.56f, 0.25f, 0.18f},
                  {0.63f, 0.31f, 0.21f},
                  {0.47f, 0.22f, 0.17f},
                  {0.67f, 0.39f, 0.27f},
                  {0.43f, 0.20f, 0.16f}}},
                {0.68f, 0.65f, 0.58f},
                0.10f,
                0.14f,
                false};
    case ProceduralMap::Stones:
        return {0.25f,
                0.08f,
                0.35f,
                {{{0.56f, 0.54f, 0.50f},
                  {0.51f, 0.47f, 0.42f},
                  {0.61f, 0.59f, 0.55f},
                  {0.46f, 0.45f, 0.44f},
                  {0.59f, 0.52f, 0.45f}}},
                {0.26f, 0.21f, 0.16f},
                0.12f,
                0.20f,
                false};
    case ProceduralMap::Rivets:
        return {0.32f,
                0.30f,
                0.36f,
                {{{0.72f, 0.72f, 0.73f},
                  {0.68f, 0.69f, 0.71f},
                  {0.75f, 0.74f, 0.72f},
                  {0.70f, 0.70f, 0.70f},
                  {0.66f, 0.67f, 0.69f}}},
                {0.50f, 0.52f, 0.55f},
                0.05f,
                0.12f,
                true};
    default: // test shapes: a neutral sandstone ramp, dark low, light high
        return {2.0f,
                0.0f,
                1.0f,
                {{{0.80f, 0.76f, 0.70f},
                  {0.80f, 0.76f, 0.70f},
                  {0.80f, 0.76f, 0.70f},
                  {0.80f, 0.76f, 0.70f},
                  {0.80f, 0.76f, 0.70f}}},
                {0.30f, 0.28f, 0.26f},
                0.0f,
                0.06f,
                false};
    }
}

int find(std::vector<int>& parent, int i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

} // namespace

std::vector<int> labelRaisedRegions(const HeightField& field, float threshold, WrapMode wrap) {
    const int w = field.width, h = field.height;
    std::vector<int> labels(static_cast<std::size_t>(w) * h, 0);
    if (field.empty())
        return labels;
    std::vector<int> parent(labels.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto raised = [&](int x, int y) { return field.at(x, y) > threshold; };
    auto join = [&](int a, int b) {
        const int ra = find(parent, a), rb = find(parent, b);
        if (ra != rb)
            parent[std::max(ra, rb)] = std::min(ra, rb);
    };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!raised(x, y))
                continue;
            const int i = y * w + x;
            // Right and down neighbours; with repeat the last column joins the first, and so on.
            const bool wrapX = x + 1 < w || wrap == WrapMode::Repeat;
            const bool wrapY = y + 1 < h || wrap == WrapMode::Repeat;
            const int xr = (x + 1) % w, yd = (y + 1) % h;
            if (wrapX && raised(xr, y))
                join(i, y * w + xr);
            if (wrapY && raised(x, yd))
                join(i, yd * w + x);
        }
    }
    std::vector<int> number(labels.size(), 0);
    int next = 0;
    for (std::size_t i = 0; i < labels.size(); ++i) {
        if (field.texels[i] <= threshold)
            continue;
        const int root = find(parent, static_cast<int>(i));
        if (number[root] == 0)
            number[root] = ++next;
        labels[i] = number[root];
    }
    return labels;
}

Image makeProceduralAlbedo(ProceduralMap kind, const HeightField& field, unsigned seed,
                           WrapMode wrap) {
    Image image(field.width, field.height, 3);
    const ImageWriter put = image.writer();
    if (field.empty())
        return image;
    const Look look = lookFor(kind);
    const std::vector<int> labels = labelRaisedRegions(field, look.threshold, wrap);
    for (int y = 0; y < field.height; ++y) {
        for (int x = 0; x < field.width; ++x) {
            const float u = (x + 0.5f) / field.width, v = (y + 0.5f) / field.height;
            const float hgt = field.at(x, y);
            const int label = labels[static_cast<std::size_t>(y) * field.width + x];

            // Fine grain per texel plus a soft blotch, both periodic over the tile.
            const float grain = hash01(x, y, seed) - 0.5f;
            const float blotch = look.brushed ? valueNoise(u, v, 4, 96, seed + 5) - 0.5f
                                              : valueNoise(u, v, 16, 16, seed + 3) - 0.5f;

            const std::size_t pick =
                label > 0 ? static_cast<std::size_t>(hash01(label, 17, seed) * 5.0f) % 5 : 0;
            Rgb region = look.palette[pick];
            region = scaled(region, 1.0f + look.regionGrain * (grain + blotch));
            Rgb ground = scaled(look.ground, 1.0f + look.groundGrain * (grain + 1.5f * blotch));

            const float t = smoothstep(look.blendLo, look.blendHi, hgt);
            Rgb colour = lerp(ground, region, t);
            // Cavities read darker: a cheap ambient-occlusion look from the height itself.
            colour = scaled(colour, 0.8f + 0.2f * std::clamp(hgt * 1.5f, 0.0f, 1.0f));
            for (int c = 0; c < 3; ++c)
                put.at(x, y, c) = std::clamp(colour[c], 0.0f, 1.0f);
        }
    }
    return image;
}

} // namespace px
