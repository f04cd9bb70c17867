#pragma once
// The ray tracer's view of a tile: one Embree device, the mesh as one triangle geometry whose
// vertex and index buffers are the BakeMesh's own arrays (shared, not copied), and a top-level
// scene holding it as instances translated by whole tiles: one for clamp, 3 x 3 for repeat (the
// hit's instID says which copy). Both scenes are robust (watertight on shared edges: a grid mesh
// aligned with the texels puts rays exactly on its edges), the mesh's compact.

#include "parallax/Result.h"
#include "parallax/meshbake/BakeMesh.h"

#include <embree3/rtcore.h>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

namespace px::meshbake {

class EmbreeTile {
public:
    // `mesh` must outlive the tile (its arrays are shared). `offsets`: the copies' translations.
    static Result<EmbreeTile> make(const BakeMesh& mesh, const std::vector<glm::vec2>& offsets);
    EmbreeTile(EmbreeTile&& other) noexcept;
    EmbreeTile& operator=(EmbreeTile&&) = delete;
    EmbreeTile(const EmbreeTile&) = delete;
    EmbreeTile& operator=(const EmbreeTile&) = delete;
    ~EmbreeTile();

    RTCScene scene() const { return m_top; }
    const std::vector<glm::vec2>& offsets() const { return m_offsets; }

private:
    EmbreeTile() = default;
    RTCDevice m_device = nullptr;
    RTCScene m_mesh = nullptr;
    RTCScene m_top = nullptr;
    std::vector<glm::vec2> m_offsets;
    std::string m_error; // the device's last error message
};

} // namespace px::meshbake
