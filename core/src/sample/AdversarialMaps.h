#pragma once
// Maps made to break the tracers (issue: "exact means every ray"): features a step cap, a cone
// or a bracket can miss. Random positions and heights come from the seed, so tests can vary it.

#include "parallax/sample/ProceduralMaps.h"

namespace px {

bool isAdversarial(ProceduralMap kind);

// `kind` is one of the adversarial ProceduralMap values (SpikeFlat and after); others give zeros.
HeightField makeAdversarialMap(ProceduralMap kind, int width, int height, unsigned seed);

} // namespace px
