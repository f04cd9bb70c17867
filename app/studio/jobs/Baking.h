#pragma once
// What a bake reads from the document and how its result goes back in: as a new map made here
// (saved with the material), and only if the surface it was baked from is still the document's.

#include "jobs/BakeRunner.h"
#include "model/DocumentState.h"
#include "parallax/Result.h"

#include <limits>

namespace px::studio {

// `occlusionDistance`: the occlusion bakes' D, horizontal uv (+inf: unlimited).
BakeRequest makeBakeRequest(const DocumentState& state, BakeKind kind,
                            NormalFilter filter = NormalFilter::Sobel,
                            double occlusionDistance = std::numeric_limits<double>::infinity());

// The state with the baked map in it (a baked normal map also becomes the normal source; an
// occlusion bake, either kind, fills the occlusion map). Fails when the height map, wrap mode or
// (for normals and occlusion) height scale changed since the bake started: the result describes
// another surface.
Result<DocumentState> withBake(const DocumentState& state, const BakeOutcome& outcome);

MapKind mapKindOf(BakeKind kind);

// Why the normal map baked here no longer matches the material (another height scale, or another
// filter than the panel's), or empty when it does or was not baked here.
QString staleNormalBake(const DocumentState& state, NormalFilter filter);

// How the occlusion map was baked here ("baked here: distance 0.1 uv, 64 directions"), empty when
// it was not.
QString occlusionBakeSummary(const DocumentState& state);
// Why the occlusion map baked here no longer matches the material (another height scale or
// wrap), or empty.
QString staleOcclusionBake(const DocumentState& state);

} // namespace px::studio
