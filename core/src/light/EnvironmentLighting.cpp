#include "parallax/light/EnvironmentLighting.h"

#include "parallax/light/Environment.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <tbb/parallel_for.h>

namespace px {

namespace {

// Hammersley point i of n (radical inverse in base 2).
glm::vec2 hammersley(unsigned i, unsigned n) {
    unsigned bits = i;
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return {static_cast<float>(i) / static_cast<float>(n),
            static_cast<float>(bits) * 2.3283064e-10f};
}

// A half vector drawn from GGX's distribution of normals around n (alpha = roughness^2).
glm::vec3 sampleGgx(glm::vec2 xi, glm::vec3 n, float alpha) {
    const float phi = 2.0f * std::numbers::pi_v<float> * xi.x;
    const float cosTheta = std::sqrt((1.0f - xi.y) / (1.0f + (alpha * alpha - 1.0f) * xi.y));
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const glm::vec3 up = std::abs(n.y) < 0.999f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 tx = glm::normalize(glm::cross(up, n)), ty = glm::cross(n, tx);
    return glm::normalize(tx * (sinTheta * std::cos(phi)) + ty * (sinTheta * std::sin(phi)) +
                          n * cosTheta);
}

// Real SH basis, bands 0-2.
std::array<float, 9> basis(glm::vec3 d) {
    return {0.282095f,
            0.488603f * d.y,
            0.488603f * d.z,
            0.488603f * d.x,
            1.092548f * d.x * d.y,
            1.092548f * d.y * d.z,
            0.315392f * (3.0f * d.z * d.z - 1.0f),
            1.092548f * d.x * d.z,
            0.546274f * (d.x * d.x - d.y * d.y)};
}

IrradianceSh projectIrradiance(const Image& map) {
    IrradianceSh sh{};
    for (int y = 0; y < map.height; ++y) {
        const float theta = (y + 0.5f) / map.height * std::numbers::pi_v<float>;
        const float solidAngle = (2.0f * std::numbers::pi_v<float> / map.width) *
                                 (std::numbers::pi_v<float> / map.height) * std::sin(theta);
        for (int x = 0; x < map.width; ++x) {
            const glm::vec3 d =
                equirectDirection({(x + 0.5f) / map.width, (y + 0.5f) / map.height});
            const glm::vec3 radiance(map.at(x, y, 0), map.at(x, y, 1), map.at(x, y, 2));
            const std::array<float, 9> b = basis(d);
            for (int i = 0; i < 9; ++i)
                sh[i] += radiance * (b[i] * solidAngle);
        }
    }
    // Band weights of the clamped cosine (pi, 2pi/3, pi/4), divided by pi: E / pi.
    const float band[9] = {1.0f,  2.0f / 3.0f, 2.0f / 3.0f, 2.0f / 3.0f, 0.25f,
                           0.25f, 0.25f,       0.25f,       0.25f};
    for (int i = 0; i < 9; ++i)
        sh[i] *= band[i];
    return sh;
}

// Samples a box-filtered pyramid (level 0 the finest) trilinearly.
glm::vec3 samplePyramid(const std::vector<Image>& pyramid, glm::vec3 d, float level) {
    level = std::clamp(level, 0.0f, static_cast<float>(pyramid.size() - 1));
    const int l0 = static_cast<int>(level);
    const int l1 = std::min(l0 + 1, static_cast<int>(pyramid.size()) - 1);
    const float f = level - static_cast<float>(l0);
    return (1.0f - f) * sampleEquirect(pyramid[l0], d) + f * sampleEquirect(pyramid[l1], d);
}

// GGX-convolved radiance around n (= v = r, Karis's simplification), filtered importance sampling
// (Colbert and Krivanek, GPU Gems 3, ch. 20): each sample reads the pyramid level whose texels
// cover its share of the lobe's solid angle, so few samples give no fireflies.
glm::vec3 prefiltered(const std::vector<Image>& pyramid, glm::vec3 n, float roughness,
                      unsigned samples) {
    const float alpha = roughness * roughness;
    const float texelSolidAngle =
        4.0f * std::numbers::pi_v<float> / static_cast<float>(pyramid[0].width * pyramid[0].height);
    glm::vec3 sum(0.0f);
    float weight = 0.0f;
    for (unsigned i = 0; i < samples; ++i) {
        const glm::vec3 h = sampleGgx(hammersley(i, samples), n, alpha);
        const glm::vec3 l = 2.0f * glm::dot(n, h) * h - n;
        const float NdotL = glm::dot(n, l);
        if (NdotL <= 0.0f)
            continue;
        const float NdotH = std::max(glm::dot(n, h), 0.0f);
        const float a2 = alpha * alpha, dd = NdotH * NdotH * (a2 - 1.0f) + 1.0f;
        const float pdf =
            a2 / (std::numbers::pi_v<float> * dd * dd) / 4.0f; // D NdotH / (4 VdotH), v = n
        const float sampleSolidAngle = 1.0f / (static_cast<float>(samples) * pdf + 1e-6f);
        const float level = 0.5f * std::log2(sampleSolidAngle / texelSolidAngle) + 1.0f;
        sum += samplePyramid(pyramid, l, level) * NdotL;
        weight += NdotL;
    }
    return weight > 0.0f ? sum / weight : glm::vec3(0.0f);
}

} // namespace

glm::vec3 irradianceAt(const IrradianceSh& sh, glm::vec3 n) {
    const std::array<float, 9> b = basis(glm::normalize(n));
    glm::vec3 e(0.0f);
    for (int i = 0; i < 9; ++i)
        e += sh[i] * b[i];
    return glm::max(e, glm::vec3(0.0f));
}

PrefilteredEnvironment prefilterEnvironment(const Image& map, int baseWidth, int levels) {
    PrefilteredEnvironment out;
    const Image source = map.width > 2 * baseWidth ? resampledEnvironment(map, 2 * baseWidth) : map;
    out.irradiance = projectIrradiance(resampledEnvironment(source, std::min(source.width, 128)));
    std::vector<Image> pyramid{source};
    while (pyramid.back().width > 2)
        pyramid.push_back(resampledEnvironment(pyramid.back(), pyramid.back().width / 2));
    out.specular.push_back(resampledEnvironment(source, std::min(source.width, baseWidth)));
    for (int level = 1; level < levels; ++level) {
        const float roughness = static_cast<float>(level) / static_cast<float>(levels - 1);
        Image img(std::max(2, out.specular[0].width >> level),
                  std::max(1, out.specular[0].width >> (level + 1)), 3);
        const ImageWriter put = img.writer();
        tbb::parallel_for(0, img.height, [&](int y) {
            for (int x = 0; x < img.width; ++x) {
                const glm::vec3 n =
                    equirectDirection({(x + 0.5f) / img.width, (y + 0.5f) / img.height});
                const glm::vec3 c = prefiltered(pyramid, n, roughness, 128);
                for (int k = 0; k < 3; ++k)
                    put.at(x, y, k) = c[k];
            }
        });
        out.specular.push_back(std::move(img));
    }
    return out;
}

Image makeSplitSumTable(int size, int samples) {
    Image table(size, size, 2);
    const ImageWriter put = table.writer();
    for (int j = 0; j < size; ++j) {
        const float roughness = (j + 0.5f) / size;
        const float alpha = roughness * roughness, k = alpha / 2.0f;
        for (int i = 0; i < size; ++i) {
            const float NdotV = (i + 0.5f) / size;
            const glm::vec3 v(std::sqrt(1.0f - NdotV * NdotV), 0.0f, NdotV), n(0, 0, 1);
            float a = 0.0f, b = 0.0f;
            for (int s = 0; s < samples; ++s) {
                const glm::vec3 h = sampleGgx(hammersley(s, samples), n, alpha);
                const glm::vec3 l = 2.0f * glm::dot(v, h) * h - v;
                const float NdotL = std::max(l.z, 0.0f), NdotH = std::max(h.z, 0.0f),
                            VdotH = std::max(glm::dot(v, h), 0.0f);
                if (NdotL <= 0.0f)
                    continue;
                const float g = NdotL / (NdotL * (1.0f - k) + k) * NdotV / (NdotV * (1.0f - k) + k);
                const float visibility = g * VdotH / (NdotH * NdotV);
                const float fresnel = std::pow(1.0f - VdotH, 5.0f);
                a += (1.0f - fresnel) * visibility;
                b += fresnel * visibility;
            }
            put.at(i, j, 0) = a / samples;
            put.at(i, j, 1) = b / samples;
        }
    }
    return table;
}

} // namespace px
