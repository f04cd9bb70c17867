#include "parallax/sample/ProceduralMaps.h"

#include "AdversarialMaps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>

namespace px {
namespace {

constexpr std::array<std::string_view, 18> kNames{
    "bricks", "stones", "rivets",     "noise", "random", "ramp", "checker",  "spikes",   "step",
    "cracks", "flat",   "spike-flat", "walls", "treads", "pits", "terraces", "outliers", "jpeg"};

// A hash of integer lattice points to [0, 1): deterministic noise without global state.
float hash01(int x, int y, unsigned seed) {
    std::uint32_t h = static_cast<std::uint32_t>(x) * 0x8da6b343u ^
                      static_cast<std::uint32_t>(y) * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return static_cast<float>(h & 0xffffffu) / static_cast<float>(0x1000000);
}

float smooth(float t) {
    return t * t * (3.0f - 2.0f * t);
}

// Periodic value noise with `cells` lattice cells across the tile, so samples tile seamlessly.
float valueNoise(float u, float v, int cells, unsigned seed) {
    const float x = u * cells, y = v * cells;
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float fx = smooth(x - x0), fy = smooth(y - y0);
    auto at = [&](int i, int j) {
        return hash01(((i % cells) + cells) % cells, ((j % cells) + cells) % cells, seed);
    };
    const float a = at(x0, y0), b = at(x0 + 1, y0), c = at(x0, y0 + 1), d = at(x0 + 1, y0 + 1);
    return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
}

float fractalNoise(float u, float v, unsigned seed) {
    float sum = 0.0f, amplitude = 0.5f, total = 0.0f;
    for (int octave = 0; octave < 5; ++octave) {
        sum += amplitude * valueNoise(u, v, 4 << octave, seed + octave);
        total += amplitude;
        amplitude *= 0.5f;
    }
    return sum / total;
}

float bricks(float u, float v, unsigned seed) {
    const int rows = 8, columns = 4;
    const float y = v * rows;
    const int row = static_cast<int>(std::floor(y));
    const float x = u * columns + (row % 2 ? 0.5f : 0.0f);
    const int column = static_cast<int>(std::floor(x));
    const float fx = x - column, fy = y - row;
    const float mortar = 0.06f, bevel = 0.08f;
    // Distance to the brick's border in brick-width units (rows are half as tall as wide).
    const float aspect = static_cast<float>(columns) / rows;
    const float edge = std::min({fx, 1 - fx, fy * aspect, (1 - fy) * aspect});
    float h = edge < mortar ? 0.15f : 0.15f + 0.85f * std::min(1.0f, (edge - mortar) / bevel);
    const float tone = 0.9f + 0.1f * hash01(column, row, seed);
    return std::clamp(h * tone - 0.05f * fractalNoise(u, v, seed + 7), 0.0f, 1.0f);
}

float stones(float u, float v, unsigned seed) {
    const int cells = 6;
    const float x = u * cells, y = v * cells;
    const int cx = static_cast<int>(std::floor(x)), cy = static_cast<int>(std::floor(y));
    float d1 = 1e9f, d2 = 1e9f;
    for (int j = -1; j <= 1; ++j) {
        for (int i = -1; i <= 1; ++i) {
            const int gx = cx + i, gy = cy + j;
            const int wx = ((gx % cells) + cells) % cells, wy = ((gy % cells) + cells) % cells;
            const float px = gx + 0.2f + 0.6f * hash01(wx, wy, seed);
            const float py = gy + 0.2f + 0.6f * hash01(wx, wy, seed + 1);
            const float d = std::hypot(x - px, y - py);
            if (d < d1) {
                d2 = d1;
                d1 = d;
            } else {
                d2 = std::min(d2, d);
            }
        }
    }
    const float border = std::clamp((d2 - d1) * 2.5f, 0.0f, 1.0f);
    return std::clamp(std::sqrt(border) * (0.85f + 0.15f * fractalNoise(u, v, seed + 3)), 0.0f,
                      1.0f);
}

float rivets(float u, float v) {
    const int count = 6;
    const float x = u * count - std::floor(u * count) - 0.5f;
    const float y = v * count - std::floor(v * count) - 0.5f;
    const float r = std::hypot(x, y) / 0.3f;
    const float dome = r < 1.0f ? std::sqrt(1.0f - r * r) : 0.0f;
    return 0.3f + 0.7f * dome;
}

} // namespace

std::span<const std::string_view> proceduralMapNames() {
    return kNames;
}

std::optional<ProceduralMap> parseProceduralMap(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i) {
        if (kNames[i] == name)
            return static_cast<ProceduralMap>(i);
    }
    return std::nullopt;
}

HeightField makeProceduralMap(ProceduralMap kind, int width, int height, unsigned seed,
                              float level) {
    if (isAdversarial(kind))
        return makeAdversarialMap(kind, width, height, seed);
    HeightField field(width, height);
    const PlaneWriter put = field.writer();
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float u = (x + 0.5f) / width, v = (y + 0.5f) / height;
            float h = 0.0f;
            switch (kind) {
            case ProceduralMap::Bricks:
                h = bricks(u, v, seed);
                break;
            case ProceduralMap::Stones:
                h = stones(u, v, seed);
                break;
            case ProceduralMap::Rivets:
                h = rivets(u, v);
                break;
            case ProceduralMap::Noise:
                h = fractalNoise(u, v, seed);
                break;
            case ProceduralMap::Random:
                h = uniform(random);
                break;
            case ProceduralMap::Ramp:
                h = width > 1 ? static_cast<float>(x) / (width - 1) : 0.5f;
                break;
            case ProceduralMap::Checker:
                h = static_cast<float>((x + y) % 2);
                break;
            case ProceduralMap::Spikes:
                h = hash01(x, y, seed) < 0.02f ? 1.0f : 0.0f;
                break;
            case ProceduralMap::Step:
                h = 2 * x >= width ? 1.0f : 0.0f;
                break;
            case ProceduralMap::Cracks:
                h = (x % 16 == 7 || hash01(x / 4, y, seed) < 0.01f) ? 0.0f : 1.0f;
                break;
            case ProceduralMap::Flat:
                h = level;
                break;
            default: // the adversarial maps, made above
                break;
            }
            put.at(x, y) = std::clamp(h, 0.0f, 1.0f);
        }
    }
    return field;
}

} // namespace px
