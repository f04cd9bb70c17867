#include "model/SampleMaterial.h"

#include "parallax/sample/ProceduralAlbedo.h"

#include <array>
#include <cmath>
#include <string>

namespace px::studio {

std::span<const ProceduralMap> sampleKinds() {
    static constexpr std::array<ProceduralMap, 3> kKinds{
        ProceduralMap::Bricks, ProceduralMap::Stones, ProceduralMap::Rivets};
    return kKinds;
}

DocumentState makeSampleState(ProceduralMap kind, int size) {
    DocumentState state;
    Material& m = state.material;
    const std::string_view name = proceduralMapNames()[static_cast<std::size_t>(kind)];
    m.name = std::string(name);
    m.heightScale = kind == ProceduralMap::Rivets ? 0.04f : 0.06f;
    m.technique = Technique::Pom;
    m.params = info(Technique::Pom).defaults;
    m.normalSource = NormalSource::HeightSobel;
    m.tiling = 2.0f;
    m.selfShadow = true; // what parallax is for: bumps that cast shadows
    if (kind == ProceduralMap::Rivets) {
        m.specular = 0.6f;
        m.shininess = 64.0f;
    }

    auto assets = std::make_shared<MaterialAssets>();
    assets->height = makeProceduralMap(kind, size, size);
    // On the 16-bit grid, as most artists' maps are: the preview's textures then keep their
    // format when one is loaded, and llvmpipe, which compiles a shader variant per texture format
    // at its first draw, has none to compile (about 0.1 s a program, measured).
    for (float& h : assets->height.texels)
        h = std::nearbyint(h * 65535.0f) / 65535.0f;
    assets->albedo = makeProceduralAlbedo(kind, assets->height, 1, m.wrap);
    state.assets = std::move(assets);
    state.setUnsaved(MapKind::Height, true);
    state.setUnsaved(MapKind::Albedo, true);
    return state;
}

} // namespace px::studio
