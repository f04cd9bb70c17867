#pragma once
// Clamp only: beyond the map's edges the surface repeats its edge, flat outward but not along the
// edge, so relaxed cones must see those strips too (ConeCells.h, stripSegment()). A 1-D maximum
// pyramid of the edge segments per side finds the few that matter for an apex.

#include "bake/ConeCells.h"

#include <array>
#include <vector>

namespace px::cone {

class EdgeStrips {
public:
    explicit EdgeStrips(const CellGrid& g); // empty with repeat

    // Narrows the relaxed cone c of apex b with every strip that may.
    float narrow(const CellGrid& g, const Apex& b, float c) const;

private:
    std::array<std::vector<std::vector<float>>, 4> m_levels; // per side, level, segment
};

} // namespace px::cone
