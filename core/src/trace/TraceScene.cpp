#include "parallax/trace/TraceScene.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <tbb/parallel_for.h>

namespace px {

glm::vec2 parallaxVector(float heightScale, double polarDeg, double azimuthDeg) {
    const double polar = polarDeg * std::numbers::pi / 180.0;
    const double azimuth = azimuthDeg * std::numbers::pi / 180.0;
    const double length = heightScale * std::tan(polar);
    return {static_cast<float>(length * std::cos(azimuth)),
            static_cast<float>(length * std::sin(azimuth))};
}

long long rayCellBound(glm::vec2 P, int width, int height) {
    // One cell per border crossed on each axis, the first cell, and one per axis for rounding
    // (pxCellAt may step past a border the float position has not reached yet).
    return static_cast<long long>(std::floor(std::abs(static_cast<double>(P.x)) * width)) +
           static_cast<long long>(std::floor(std::abs(static_cast<double>(P.y)) * height)) + 3;
}

glm::dvec2 rayOrigin(const TraceScene& scene, int i, int j) {
    return glm::dvec2((i + 0.5) / scene.rays, (j + 0.5) / scene.rays) + scene.uvOffset;
}

Status validate(const TraceScene& scene) {
    if (scene.rays < 1 || scene.rays > 4096)
        return Error{"rays must be 1 to 4096 per side, not " + std::to_string(scene.rays)};
    if (!(scene.polarDeg >= 0.0 && scene.polarDeg < 90.0))
        return Error{"the polar angle must be in [0, 90) degrees"};
    if (!std::isfinite(scene.azimuthDeg))
        return Error{"the azimuth must be a finite angle"};
    return success();
}

std::vector<TraceResult> traceScene(const Tracer& tracer, const TraceScene& scene) {
    const int R = scene.rays;
    const glm::vec2 P = parallaxVector(tracer.heightScale(), scene.polarDeg, scene.azimuthDeg);
    std::vector<TraceResult> results(static_cast<std::size_t>(R) * R);
    tbb::parallel_for(0, R, [&](int j) {
        for (int i = 0; i < R; ++i)
            results[static_cast<std::size_t>(j) * R + i] = tracer.trace(rayOrigin(scene, i, j), P);
    });
    return results;
}

double hitErrorTexels(const TraceResult& a, const TraceResult& b, int width, int height) {
    return std::hypot((a.u - b.u) * width, (a.v - b.v) * height);
}

std::string traceCsv(const TraceScene& scene, const std::vector<TraceResult>& results) {
    std::string csv = "i,j,u,v,t,fetches\n";
    csv.reserve(results.size() * 64);
    char line[160];
    const int R = scene.rays;
    for (int j = 0; j < R; ++j) {
        for (int i = 0; i < R; ++i) {
            const TraceResult& r = results[static_cast<std::size_t>(j) * R + i];
            // %.17g and %.9g round-trip double and float exactly.
            std::snprintf(line, sizeof line, "%d,%d,%.17g,%.17g,%.9g,%d\n", i, j, r.u, r.v,
                          static_cast<double>(r.t), r.fetches);
            csv += line;
        }
    }
    return csv;
}

} // namespace px
