#include "Baking.h"

namespace px::studio {

MapKind mapKindOf(BakeKind kind) {
    switch (kind) {
    case BakeKind::Normal:
        return MapKind::Normal;
    case BakeKind::Cone:
        return MapKind::Cone;
    case BakeKind::RelaxedCone:
        return MapKind::RelaxedCone;
    }
    return MapKind::Cone;
}

BakeRequest makeBakeRequest(const DocumentState& state, BakeKind kind, NormalFilter filter) {
    BakeRequest request;
    request.kind = kind;
    request.source = state.assets;
    request.wrap = state.material.wrap;
    request.normal.heightScale = state.material.heightScale;
    request.normal.filter = filter;
    request.normal.wrap = state.material.wrap;
    request.normal.green = state.material.normalGreen;
    return request;
}

Result<DocumentState> withBake(const DocumentState& state, const BakeOutcome& outcome) {
    const BakeRequest& request = outcome.request;
    const HeightField& now = state.assets->height;
    const HeightField& then = request.source->height;
    const bool sameSurface =
        now.width == then.width && now.height == then.height &&
        (state.assets->height.texels.data() == then.texels.data() || now.texels == then.texels);
    if (!sameSurface)
        return Error{"The height map changed while the " + bakeTitle(request.kind).toStdString() +
                     " was baking; bake it again."};
    if (request.wrap != state.material.wrap)
        return Error{"The wrap mode changed while the " + bakeTitle(request.kind).toStdString() +
                     " was baking; bake it again."};
    if (request.kind == BakeKind::Normal &&
        request.normal.heightScale != state.material.heightScale)
        return Error{"The height scale changed while the normal map was baking; bake it again."};

    DocumentState next = state;
    auto assets = std::make_shared<MaterialAssets>(*state.assets);
    const MapKind kind = mapKindOf(request.kind);
    switch (request.kind) {
    case BakeKind::Normal:
        assets->normal = outcome.normal;
        next.material.normalSource = NormalSource::Map;
        next.material.normalGreen = request.normal.green;
        break;
    case BakeKind::Cone:
        assets->cone = outcome.cone;
        break;
    case BakeKind::RelaxedCone:
        assets->relaxedCone = outcome.cone;
        break;
    }
    next.assets = std::move(assets);
    mapPath(next.material.maps, kind).clear();
    next.setUnsaved(kind, true);
    return next;
}

} // namespace px::studio
