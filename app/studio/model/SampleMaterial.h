#pragma once
// The built-in sample materials: height and colour made by the project (ProceduralMaps,
// ProceduralAlbedo), held in memory until the material is saved.

#include "model/DocumentState.h"
#include "parallax/sample/ProceduralMaps.h"

#include <span>

namespace px::studio {

// The samples offered in File > New Sample, the first one opened when no file is given.
std::span<const ProceduralMap> sampleKinds();

DocumentState makeSampleState(ProceduralMap kind = ProceduralMap::Bricks, int size = 512);

} // namespace px::studio
