#pragma once
// Exact horizons of the bilinear surface z = s h (docs/conventions.md §7) for the occlusion bake:
// from a texel centre p, sup over 0 < r <= D of (z(p + r d) - z(p)) / r along one azimuth d, the
// r -> 0+ limit (the first cell's own slope) included. The ray walks the cells it crosses, in each
// of which the height is quadratic in r, so the cell's best secant is closed-form; a maximum
// pyramid of the cells lets it skip, at any size, every node too low to raise the horizon found so
// far (the max-mip search of BAKES.md §1).
//
// Unlimited distance: the surface is bounded, so the horizon is never below 0 (the secant tends to
// 0 far away). With repeat a ray may never close, so the search stops where nothing farther could
// raise the horizon's tangent by more than kOpenSkySlack, or kOpenSkyReach tiles away.

#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

#include <vector>

namespace px::occlusion {

inline constexpr double kOpenSkySlack = 1.0 / 16384.0;
inline constexpr double kOpenSkyReach = 64.0;

class HorizonSearch {
public:
    // `distance`: D in uv (+inf: unlimited). The field must not be empty.
    HorizonSearch(const HeightField& field, WrapMode wrap, double heightScale, double distance);

    // The horizon's tangent from texel (x, y) along the uv-space direction (cos phi, sin phi) in
    // (X, Y) = (u, -v). `witness`, if given: in, a distance worth trying first (where a
    // neighbour's horizon was, 0: none), which only speeds the search up (the surface there is a
    // lower bound, so the skips prune more from the start); out, where this horizon was found.
    double horizon(int x, int y, double cosPhi, double sinPhi, double* witness = nullptr) const;

private:
    struct Level {
        int width = 0, height = 0;
        std::vector<float> max; // per node: the highest corner of its cells
    };

    float texel(int x, int y) const; // resolved by the wrap mode
    float nodeMax(int level, int nx, int ny) const;
    // max(best, the best secant over the cell at local coordinates (lx, ly) between ra and rb);
    // (ax, ay): p in the cell's own coordinates.
    // `at`: where the best is, updated with it.
    double cellSecant(int lx, int ly, double ax, double ay, double zp, double dx, double dy,
                      double ra, double rb, double best, double& at) const;
    double surface(double x, double y) const; // h at texel coordinates (x, y), wrapped or clamped
    // beyondX, beyondY: the cell the ray is in is beyond the map's cells along that axis.
    double clampedOutside(int px, int py, double zp, double dx, double dy, double r, double best,
                          double rMax, bool beyondX, bool beyondY) const;

    const HeightField& m_field;
    WrapMode m_wrap;
    double m_scale;
    double m_distance;
    double m_top;                // s * the highest texel
    int m_cellsX, m_cellsY;      // cells per period (repeat) or inside the map (clamp)
    std::vector<Level> m_levels; // level 1 (2 x 2 cells) upwards; level 0 is read from the texels
};

} // namespace px::occlusion
