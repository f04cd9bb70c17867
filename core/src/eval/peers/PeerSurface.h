#pragma once
// What the peers' occlusion methods share: the surface of docs/conventions.md §7 read the same way
// the exact baker reads it, and a parallel loop over texels with progress and cancellation.

#include "parallax/eval/PeerOcclusion.h"

#include <functional>
#include <glm/vec3.hpp>

namespace px::peers {

class PeerSurface {
public:
    PeerSurface(const HeightField& field, const PeerSurfaceOptions& options);

    // z = s h at texel coordinates (x, y): texel centre (i, j) is (i, j), y grows down the image;
    // bilinear, wrapped or edge-extended as the material says.
    double z(double x, double y) const;
    double zAt(int i, int j) const { return m_scale * m_field.at(i, j); }
    // The central-filter unit normal at texel (i, j), in X = u, Y = -v, Z up.
    glm::dvec3 normal(int i, int j) const;
    // Texel offsets for a horizontal uv step `r` in azimuth phi (X = u, Y = -v).
    double dx(double r, double phi) const;
    double dy(double r, double phi) const;
    int width() const { return m_field.width; }
    int height() const { return m_field.height; }
    double highest() const { return m_highest; } // s x the largest texel

private:
    const HeightField& m_field;
    double m_scale;
    WrapMode m_wrap;
    double m_highest;
};

// The checks every method makes on the surface (an empty map, a bad height scale).
Status checkSurface(const HeightField& field, const PeerSurfaceOptions& options);

// Runs `texel(i, j)` -> AO for every texel on every core, rows in parallel, with progress and
// cancellation; returns the one-channel image.
Result<Image> everyTexel(const PeerSurface& surface, const BakeControl& control,
                         const std::function<float(int, int)>& texel);

} // namespace px::peers
