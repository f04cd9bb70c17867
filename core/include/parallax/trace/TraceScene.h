#pragma once
// The canonical trace scene (docs/conventions.md §5): R x R rays entering at texel-centred uv0 with
// one direction, used by `trace`, `bench`, the tests and every accuracy figure.

#include "parallax/Result.h"
#include "parallax/trace/Tracer.h"

#include <glm/vec2.hpp>
#include <string>
#include <vector>

namespace px {

struct TraceScene {
    int rays = 64;                 // R
    double polarDeg = 45;          // from the normal, in [0, 90)
    double azimuthDeg = 0;         // from +u towards +v
    glm::dvec2 uvOffset{0.0, 0.0}; // added to every uv0 (tests of far-from-origin tiling)
};

// P = s tan(polar) (cos azimuth, sin azimuth).
glm::vec2 parallaxVector(float heightScale, double polarDeg, double azimuthDeg);

// At most how many cells of a W x H map a ray with (bounded) parallax P crosses: the length of
// the exact walks that finish `cone`, `relaxed-cone` and `pyramid` (fetchCap()).
long long rayCellBound(glm::vec2 P, int width, int height);

// Ray (i, j) enters at ((i + 0.5)/R, (j + 0.5)/R) + offset; i the column, j the row.
glm::dvec2 rayOrigin(const TraceScene& scene, int i, int j);

// Fails on R outside [1, 4096] or a polar angle outside [0, 90).
Status validate(const TraceScene& scene);

// All R*R rays, row-major (index j * R + i), traced in parallel.
std::vector<TraceResult> traceScene(const Tracer& tracer, const TraceScene& scene);

// Distance between two hit points in texels of a W x H map (docs/conventions.md §5).
double hitErrorTexels(const TraceResult& a, const TraceResult& b, int width, int height);

// The CSV `parallax-cli trace` writes: header "i,j,u,v,t,fetches", full float precision.
std::string traceCsv(const TraceScene& scene, const std::vector<TraceResult>& results);

} // namespace px
