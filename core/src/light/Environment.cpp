#include "parallax/light/Environment.h"

#include "parallax/image/ImageFile.h"
#include "parallax/light/CubeMapSky.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <tbb/parallel_for.h>
#include <vector>

namespace px {

namespace {

constexpr int kMaxWidth = 2048;

} // namespace

glm::vec2 equirectUv(glm::vec3 d) {
    const glm::vec3 n = glm::normalize(d);
    return {std::atan2(n.x, n.z) / (2.0f * std::numbers::pi_v<float>)+0.5f,
            std::acos(std::clamp(n.y, -1.0f, 1.0f)) / std::numbers::pi_v<float>};
}

glm::vec3 equirectDirection(glm::vec2 uv) {
    const float phi = (uv.x - 0.5f) * 2.0f * std::numbers::pi_v<float>,
                theta = uv.y * std::numbers::pi_v<float>;
    return {std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
}

glm::vec3 sampleEquirect(const Image& map, glm::vec3 direction) {
    const glm::vec2 uv = equirectUv(direction);
    const float x = uv.x * map.width - 0.5f, y = uv.y * map.height - 0.5f;
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float fx = x - x0, fy = y - y0;
    auto texel = [&](int i, int j) {
        i = ((i % map.width) + map.width) % map.width;
        j = std::clamp(j, 0, map.height - 1);
        if (map.channels < 3)
            return glm::vec3(map.at(i, j, 0));
        return glm::vec3(map.at(i, j, 0), map.at(i, j, 1), map.at(i, j, 2));
    };
    return (1.0f - fy) * ((1.0f - fx) * texel(x0, y0) + fx * texel(x0 + 1, y0)) +
           fy * ((1.0f - fx) * texel(x0, y0 + 1) + fx * texel(x0 + 1, y0 + 1));
}

namespace {

// One axis of a tent resampling: for each of `to` output texels, the weights of the `from` source
// texels under a tent as wide as the ratio (one texel when enlarging), at the texels' centres,
// normalised over those inside the map (the edge texels are not weighted twice).
struct TentAxis {
    std::vector<int> first; // the first source texel of each output texel
    std::vector<std::vector<float>> weights;
};

TentAxis tentAxis(int from, int to) {
    TentAxis axis;
    const double ratio = static_cast<double>(from) / to;
    const double radius = std::max(ratio, 1.0);
    for (int i = 0; i < to; ++i) {
        const double centre = (i + 0.5) * ratio;
        const int lo = std::max(0, static_cast<int>(std::floor(centre - radius)));
        const int hi = std::min(from - 1, static_cast<int>(std::ceil(centre + radius)));
        std::vector<float> w;
        double sum = 0.0;
        for (int j = lo; j <= hi; ++j) {
            const double weight = std::max(0.0, 1.0 - std::abs(j + 0.5 - centre) / radius);
            w.push_back(static_cast<float>(weight));
            sum += weight;
        }
        for (float& v : w)
            v = static_cast<float>(v / sum);
        axis.first.push_back(lo);
        axis.weights.push_back(std::move(w));
    }
    return axis;
}

// One pass of the separable tent: along each row (`alongRows`) or each column of `in`, the
// output texels `axis` describes.
Image tentPass(const Image& in, const TentAxis& axis, bool alongRows) {
    const int to = static_cast<int>(axis.first.size());
    const int width = alongRows ? to : in.width, height = alongRows ? in.height : to;
    Image out(width, height, in.channels);
    const ImageWriter put = out.writer();
    tbb::parallel_for(0, height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            const int o = alongRows ? x : y;
            const std::vector<float>& weights = axis.weights[o];
            for (int k = 0; k < in.channels; ++k) {
                float sum = 0.0f;
                for (std::size_t j = 0; j < weights.size(); ++j) {
                    const int s = axis.first[o] + static_cast<int>(j);
                    sum += weights[j] * (alongRows ? in.at(s, y, k) : in.at(x, s, k));
                }
                put.at(x, y, k) = sum;
            }
        }
    });
    return out;
}

} // namespace

Image resampledEnvironment(const Image& map, int width) {
    const int height = std::max(1, width / 2);
    if (map.width == width && map.height == height)
        return map;
    // A tent filter as wide as the ratio: every source texel counts, whatever the ratio, and no
    // texel comes out negative (a windowed sinc rings below zero around the sun). Rows first,
    // then columns (the tent is separable).
    const Image rows = tentPass(map, tentAxis(map.width, width), true);
    return tentPass(rows, tentAxis(map.height, height), false);
}

Result<Image> loadEnvironment(const std::string& path) {
    // Radiance far beyond any sky (the sun's disc in an unclipped capture is about 1e5) makes the
    // lighting's single-precision sums infinite, and the whole light black.
    ImageReadOptions options;
    options.maxMagnitude = 1e20f;
    options.limitReason = "an environment's radiance may reach (the lighting's integrals would "
                          "overflow and render black)";
    Result<Image> read = readImage(path, options);
    if (!read)
        return read.error();
    const Image& in = *read;
    if (in.width != 2 * in.height) {
        // A square file named as a cube face: the sky box of six, made equirectangular.
        if (const std::optional<CubeFaceFiles> faces = cubeFaceFiles(path);
            faces && in.width == in.height)
            return loadCubeMapSky(*faces, kMaxWidth);
        return fileError(path, "is " + std::to_string(in.width) + " x " +
                                   std::to_string(in.height) +
                                   "; an equirectangular environment is twice as wide as high "
                                   "(a cube map's faces are named like sky_px.hdr ... sky_nz.hdr)");
    }
    // Grey (with or without alpha) is grey in every channel; alpha is no light.
    const int colours = in.channels >= 3 ? 3 : 1;
    Image rgb(in.width, in.height, 3);
    const ImageWriter put = rgb.writer();
    for (int y = 0; y < in.height; ++y) {
        for (int x = 0; x < in.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const float v = in.at(x, y, std::min(c, colours - 1));
                if (v < 0.0f)
                    return fileError(path, "has negative radiance at texel (" + std::to_string(x) +
                                               ", " + std::to_string(y) + ")");
                put.at(x, y, c) = v;
            }
        }
    }
    if (rgb.width > kMaxWidth)
        return resampledEnvironment(rgb, kMaxWidth);
    return rgb;
}

Image makeSkyEnvironment(glm::vec3 sunDirection, int width) {
    const glm::vec3 sun = glm::normalize(sunDirection);
    const glm::vec3 zenith(0.18f, 0.36f, 0.85f), horizon(0.95f, 0.98f, 1.05f);
    const glm::vec3 ground(0.32f, 0.28f, 0.24f), sunColor(1.0f, 0.92f, 0.8f);
    Image sky(width, width / 2, 3);
    const ImageWriter put = sky.writer();
    for (int y = 0; y < sky.height; ++y) {
        for (int x = 0; x < sky.width; ++x) {
            const glm::vec3 d =
                equirectDirection({(x + 0.5f) / sky.width, (y + 0.5f) / sky.height});
            // Rayleigh-like: the sky pales towards the horizon; the ground is lit grey, darker
            // straight down; a soft band joins them.
            const float up = std::max(d.y, 0.0f);
            glm::vec3 c = glm::mix(horizon, zenith, std::pow(up, 0.45f));
            const glm::vec3 below = ground * (0.55f + 0.45f * std::exp(8.0f * std::min(d.y, 0.0f)));
            c = glm::mix(below, c, glm::smoothstep(-0.03f, 0.01f, d.y));
            // The sun: a small bright disc and a wide glow around it.
            const float cosine = glm::dot(d, sun);
            c += sunColor *
                 (40.0f * std::exp((cosine - 1.0f) * 4000.0f) +
                  0.6f * std::exp((cosine - 1.0f) * 12.0f)) *
                 glm::smoothstep(-0.02f, 0.02f, d.y);
            for (int k = 0; k < 3; ++k)
                put.at(x, y, k) = c[k];
        }
    }
    return sky;
}

Image scaledEnvironment(Image map, float factor) {
    for (float& v : map.pixels)
        v *= factor;
    return map;
}

} // namespace px
