#include "DoubleWalk.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace px::test {
namespace {

// Smallest s in [0, sMax] with A s^2 + B s + C >= 0 given C < 0, or -1 (cancellation-free roots).
double firstRoot(double A, double B, double C, double sMax) {
    double best = -1.0;
    if (A == 0.0) {
        if (B > 0.0)
            best = -C / B;
    } else {
        const double D = B * B - 4.0 * A * C;
        if (D >= 0.0) {
            const double q = -0.5 * (B + std::copysign(std::sqrt(D), B));
            const double r1 = q / A, r2 = q != 0.0 ? C / q : -1.0;
            const double lo = std::min(r1, r2), hi = std::max(r1, r2);
            best = lo >= 0.0 ? lo : hi;
        }
    }
    return best >= 0.0 && best <= sMax ? best : -1.0;
}

double borderT(long long cell, double X0, double dX) {
    if (dX > 0.0)
        return (static_cast<double>(cell + 1) - X0) / dX;
    if (dX < 0.0)
        return (static_cast<double>(cell) - X0) / dX;
    return std::numeric_limits<double>::infinity();
}

} // namespace

double doubleWalkT(const HeightField& field, WrapMode wrap, glm::dvec2 uv0, glm::dvec2 P) {
    const double X0 = uv0.x * field.width - 0.5, Y0 = uv0.y * field.height - 0.5;
    const double dX = P.x * field.width, dY = P.y * field.height;
    double t = std::clamp(1.0 - static_cast<double>(field.maxHeight()), 0.0, 1.0);
    auto cellAt = [](double X, double d) {
        return static_cast<long long>(d >= 0.0 ? std::floor(X) : std::ceil(X) - 1.0);
    };
    long long cx = cellAt(X0 + dX * t, dX), cy = cellAt(Y0 + dY * t, dY);
    // The wrapped columns and rows of the cell's corners, found once per cell (a 64-bit modulo per
    // texel read was a third of a long ray's walk).
    auto corners = [&](long long i, int size) {
        if (wrap == WrapMode::Clamp)
            return std::pair{static_cast<int>(std::clamp<long long>(i, 0, size - 1)),
                             static_cast<int>(std::clamp<long long>(i + 1, 0, size - 1))};
        const int lo = static_cast<int>(((i % size) + size) % size);
        return std::pair{lo, lo + 1 == size ? 0 : lo + 1};
    };
    while (t < 1.0) {
        const double tEnd = std::min({borderT(cx, X0, dX), borderT(cy, Y0, dY), 1.0});
        const auto [x0, x1] = corners(cx, field.width);
        const auto [y0, y1] = corners(cy, field.height);
        const double h00 = field.at(x0, y0), h10 = field.at(x1, y0), h01 = field.at(x0, y1),
                     h11 = field.at(x1, y1);
        const double ax = X0 + dX * t - static_cast<double>(cx);
        const double ay = Y0 + dY * t - static_cast<double>(cy);
        const double k = (h11 - h01) - (h10 - h00), hx = h10 - h00, hy = h01 - h00;
        const double C = h00 + hx * ax + hy * ay + k * ax * ay - (1.0 - t);
        if (C >= 0.0)
            return t;
        const double s = firstRoot(k * dX * dY, hx * dX + hy * dY + k * (ax * dY + ay * dX) + 1.0,
                                   C, std::max(0.0, tEnd - t));
        if (s >= 0.0)
            return t + s;
        if (tEnd >= 1.0)
            break;
        // Step over the border (or borders) reached at tEnd.
        if (borderT(cx, X0, dX) <= tEnd)
            cx += dX > 0.0 ? 1 : -1;
        if (borderT(cy, Y0, dY) <= tEnd)
            cy += dY > 0.0 ? 1 : -1;
        t = std::max(t, tEnd);
    }
    return 1.0;
}

} // namespace px::test
