#pragma once
// The closed-form inner integrals of ambient occlusion and the bent normal over elevation
// (docs/conventions.md §7, BAKES.md §1; the GTAO inner integral). For one azimuth with unit normal
// n, a = n_x cos phi + n_y sin phi, and w the direction at elevation e:
//   occlusion  integral of (n . w) cos e        = a (e/2 + sin 2e / 4) + n_z sin^2 e / 2
//   horizontal integral of (n . w) cos e cos e  = a (sin e - sin^3 e / 3) - n_z cos^3 e / 3
//   vertical   integral of (n . w) cos e sin e  = -a cos^3 e / 3 + n_z sin^3 e / 3
// (antiderivatives). The bake subtracts what lies between the normal's own horizon (n . w = 0) and
// the surface's horizon from the unoccluded hemisphere (pi for AO, 2 pi / 3 n for the bent
// normal), so a surface that hides nothing above n's plane gives exactly 1 and n.

#include <cmath>

namespace px::occlusion {

struct Elevation {
    double e, sine, cosine;
};

// The elevation whose tangent is t.
inline Elevation elevationOf(double t) {
    const double c = 1.0 / std::sqrt(1.0 + t * t);
    return {std::atan(t), t * c, c};
}

struct Occluded {
    double occlusion = 0.0;  // of the cosine-weighted solid angle
    double horizontal = 0.0; // the bent normal's part along the azimuth
    double vertical = 0.0;   // and along Z
};

// What lies between elevations lo and hi (lo < hi) in one azimuth.
inline Occluded occludedBetween(double a, double nz, const Elevation& lo, const Elevation& hi) {
    const auto occ = [&](const Elevation& x) {
        return a * (x.e / 2.0 + x.sine * x.cosine / 2.0) + nz * x.sine * x.sine / 2.0;
    };
    const auto hor = [&](const Elevation& x) {
        return a * (x.sine - x.sine * x.sine * x.sine / 3.0) -
               nz * x.cosine * x.cosine * x.cosine / 3.0;
    };
    const auto ver = [&](const Elevation& x) {
        return -a * x.cosine * x.cosine * x.cosine / 3.0 + nz * x.sine * x.sine * x.sine / 3.0;
    };
    return {occ(hi) - occ(lo), hor(hi) - hor(lo), ver(hi) - ver(lo)};
}

} // namespace px::occlusion
