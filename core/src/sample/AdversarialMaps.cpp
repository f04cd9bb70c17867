#include "AdversarialMaps.h"

#include "image/ImageModule.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace px {
namespace {

// Stairs climbing along u: treads of 8 to 32 texels, the last one dropping back to the first.
void treads(HeightField& f, std::mt19937& random) {
    std::uniform_int_distribution<int> length(8, 32);
    std::vector<int> tread(static_cast<std::size_t>(f.width));
    int steps = 0;
    for (int x = 0; x < f.width;) {
        const int end = std::min(f.width, x + length(random));
        std::fill(tread.begin() + x, tread.begin() + end, steps++);
        x = end;
    }
    for (int y = 0; y < f.height; ++y) {
        for (int x = 0; x < f.width; ++x)
            f.at(x, y) = steps > 1 ? static_cast<float>(tread[x]) / (steps - 1) : 0.5f;
    }
}

// Smooth value noise from a coarse random lattice (bilinear, 8 lattice cells across).
float latticeNoise(const std::vector<float>& lattice, int cells, float u, float v) {
    const float x = u * cells, y = v * cells;
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float fx = x - x0, fy = y - y0;
    auto at = [&](int i, int j) {
        return lattice[static_cast<std::size_t>(j % cells) * static_cast<std::size_t>(cells) +
                       static_cast<std::size_t>(i % cells)];
    };
    return (at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx) * (1 - fy) +
           (at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx) * fy;
}

// Hills from a coarse random lattice (drawn first), then each texel, row by row, as `shape` makes
// it from the hills' value there.
template <class Shape> void hills(HeightField& f, std::mt19937& random, Shape shape) {
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    const int cells = 8;
    std::vector<float> lattice(cells * cells);
    for (float& v : lattice)
        v = uniform(random);
    for (int y = 0; y < f.height; ++y) {
        for (int x = 0; x < f.width; ++x)
            f.at(x, y) =
                shape(latticeNoise(lattice, cells, (x + 0.5f) / f.width, (y + 0.5f) / f.height));
    }
}

// An 8-bit map as a real JPEG depth map would be: encoded at quality 75 in memory, decoded back
// (blocks, ringing next to steep edges, values clamped to 8 bits).
void throughJpeg(HeightField& f) {
    std::vector<unsigned char> pixels(f.texels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i)
        pixels[i] =
            static_cast<unsigned char>(std::lround(std::clamp(f.texels[i], 0.0f, 1.0f) * 255));
    Result<const ImageModule*> module = imageModule();
    if (!module)
        throw std::runtime_error("the JPEG map class: " + module.error().message);
    Result<std::vector<unsigned char>> decoded =
        (*module)->throughJpeg(pixels, f.width, f.height, 75);
    if (!decoded)
        throw std::runtime_error("the JPEG map class: " + decoded.error().message);
    pixels = std::move(*decoded);
    for (std::size_t i = 0; i < pixels.size(); ++i)
        f.texels[i] = pixels[i] / 255.0f;
}

} // namespace

bool isAdversarial(ProceduralMap kind) {
    return kind >= ProceduralMap::SpikeFlat;
}

HeightField makeAdversarialMap(ProceduralMap kind, int width, int height, unsigned seed) {
    HeightField f(width, height, 0.0f);
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    auto texel = [&](int w) { return std::uniform_int_distribution<int>(0, w - 1)(random); };
    const int area = width * height;
    switch (kind) {
    case ProceduralMap::SpikeFlat: {
        // A low flat along each row, and somewhere on it one texel at the top.
        const float floor = 0.1f * uniform(random);
        std::fill(f.texels.begin(), f.texels.end(), floor);
        for (int y = 0; y < height; ++y)
            f.at(texel(width), y) = 1.0f;
        break;
    }
    case ProceduralMap::Walls:
        // One-texel walls every second column (the Nyquist rate), each its own height.
        for (int x = 0; x < width; x += 2) {
            const float wall = 0.6f + 0.4f * uniform(random);
            for (int y = 0; y < height; ++y)
                f.at(x, y) = wall;
        }
        break;
    case ProceduralMap::Treads:
        treads(f, random);
        break;
    case ProceduralMap::Pits:
        // The top, pierced by a few isolated one-texel pits to the bottom.
        std::fill(f.texels.begin(), f.texels.end(), 1.0f);
        for (int k = 0; k < std::max(1, area / 200); ++k)
            f.at(texel(width), texel(height)) = 0.0f;
        break;
    case ProceduralMap::Terraces: {
        // Smooth hills cut into six flat terraces, stored as 8 bits would store them.
        hills(f, random, [](float n) {
            const float terrace = std::min(5.0f, std::floor(n * 6.0f)) / 5.0f;
            return std::round(terrace * 255.0f) / 255.0f;
        });
        break;
    }
    case ProceduralMap::Outliers:
        // Gentle low texels, and a handful at the top: the map's maximum is a few texels.
        for (float& h : f.texels)
            h = 0.15f * uniform(random);
        for (int k = 0; k < 6; ++k)
            f.at(texel(width), texel(height)) = 1.0f;
        break;
    case ProceduralMap::Jpeg: {
        // Terrain: hills from a coarse lattice, sharp ridges where they fold, a little grain.
        hills(f, random, [&](float n) {
            const float ridge = 1.0f - std::abs(2.0f * n - 1.0f);
            return std::clamp(0.7f * ridge + 0.15f * n + 0.1f * uniform(random), 0.0f, 1.0f);
        });
        throughJpeg(f);
        break;
    }
    default:
        break;
    }
    return f;
}

} // namespace px
