#include "jobs/Baking.h"

#include <QObject>
#include <QStringList>
#include <cmath>

namespace px::studio {

MapKind mapKindOf(BakeKind kind) {
    switch (kind) {
    case BakeKind::Normal:
        return MapKind::Normal;
    case BakeKind::Cone:
        return MapKind::Cone;
    case BakeKind::RelaxedCone:
        return MapKind::RelaxedCone;
    case BakeKind::Occlusion:
    case BakeKind::BentNormal:
        return MapKind::Ao;
    }
    return MapKind::Cone;
}

BakeRequest makeBakeRequest(const DocumentState& state, BakeKind kind, NormalFilter filter,
                            double occlusionDistance) {
    BakeRequest request;
    request.kind = kind;
    request.source = state.assets;
    request.wrap = state.material.wrap;
    request.normal.heightScale = state.material.heightScale;
    request.normal.filter = filter;
    request.normal.wrap = state.material.wrap;
    request.normal.green = state.material.normalGreen;
    request.occlusion.heightScale = state.material.heightScale;
    request.occlusion.wrap = state.material.wrap;
    request.occlusion.distance = occlusionDistance;
    request.occlusion.green = state.material.normalGreen;
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
    const bool occlusion =
        request.kind == BakeKind::Occlusion || request.kind == BakeKind::BentNormal;
    if (occlusion && request.occlusion.heightScale != state.material.heightScale)
        return Error{"The height scale changed while the " + bakeTitle(request.kind).toStdString() +
                     " was baking; bake it again."};

    DocumentState next = state;
    auto assets = std::make_shared<MaterialAssets>(*state.assets);
    const MapKind kind = mapKindOf(request.kind);
    switch (request.kind) {
    case BakeKind::Normal:
        assets->normal = outcome.normal;
        next.material.normalSource = NormalSource::Map;
        next.material.normalGreen = request.normal.green;
        next.normalBake = NormalBake{request.normal.heightScale, request.normal.filter};
        break;
    case BakeKind::Cone:
        assets->cone = outcome.cone;
        break;
    case BakeKind::RelaxedCone:
        assets->relaxedCone = outcome.cone;
        break;
    case BakeKind::Occlusion:
    case BakeKind::BentNormal:
        assets->ao = outcome.occlusion;
        next.material.surface.ao = HeightChannel::Red; // one grey channel, saved as such
        next.occlusionBake =
            OcclusionBake{request.occlusion.heightScale, request.occlusion.wrap,
                          request.occlusion.distance, occlusionDirections(request.occlusion)};
        break;
    }
    next.assets = std::move(assets);
    mapPath(next.material.maps, kind).clear();
    next.setUnsaved(kind, true);
    return next;
}

QString occlusionBakeSummary(const DocumentState& state) {
    if (!state.occlusionBake || !state.hasMap(MapKind::Ao))
        return {};
    const OcclusionBake& bake = *state.occlusionBake;
    const QString distance = std::isfinite(bake.distance)
                                 ? QObject::tr("distance %1 uv").arg(bake.distance, 0, 'g', 4)
                                 : QObject::tr("distance unlimited");
    return QObject::tr("baked here: %1, %2 directions").arg(distance).arg(bake.directions);
}

QString staleOcclusionBake(const DocumentState& state) {
    if (!state.occlusionBake || !state.hasMap(MapKind::Ao))
        return {};
    const OcclusionBake& bake = *state.occlusionBake;
    QStringList reasons;
    if (bake.heightScale != state.material.heightScale)
        reasons << QObject::tr("baked at height scale %1, now %2")
                       .arg(bake.heightScale, 0, 'g', 4)
                       .arg(state.material.heightScale, 0, 'g', 4);
    if (bake.wrap != state.material.wrap)
        reasons << QObject::tr("baked with wrap %1, now %2")
                       .arg(QString::fromUtf8(toString(bake.wrap).data()),
                            QString::fromUtf8(toString(state.material.wrap).data()));
    if (reasons.isEmpty())
        return {};
    return QObject::tr("Out of date: %1. Bake it again.").arg(reasons.join(QStringLiteral("; ")));
}

QString staleNormalBake(const DocumentState& state, NormalFilter filter) {
    if (!state.normalBake || !state.hasMap(MapKind::Normal))
        return {};
    const NormalBake& bake = *state.normalBake;
    QStringList reasons;
    if (bake.heightScale != state.material.heightScale)
        reasons << QObject::tr("baked at height scale %1, now %2")
                       .arg(bake.heightScale, 0, 'g', 4)
                       .arg(state.material.heightScale, 0, 'g', 4);
    if (bake.filter != filter)
        reasons << QObject::tr("baked with the %1 filter, now %2")
                       .arg(QString::fromUtf8(toString(bake.filter).data()),
                            QString::fromUtf8(toString(filter).data()));
    if (reasons.isEmpty())
        return {};
    return QObject::tr("Out of date: %1. Bake it again.").arg(reasons.join(QStringLiteral("; ")));
}

} // namespace px::studio
