#include "model/SampleMaterial.h"

#include "parallax/sample/ProceduralAlbedo.h"

#include <array>
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
    assets->albedo = makeProceduralAlbedo(kind, assets->height, 1, m.wrap);
    state.assets = std::move(assets);
    state.setUnsaved(MapKind::Height, true);
    state.setUnsaved(MapKind::Albedo, true);
    return state;
}

} // namespace px::studio
