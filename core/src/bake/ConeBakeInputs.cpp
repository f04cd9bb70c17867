#include "parallax/bake/ConeBakeInputs.h"

#include "bake/BakeProgress.h"
#include "bake/CellPyramid.h"
#include "bake/EdgeStrips.h"
#include "bake/FallPyramid.h"

namespace px {

namespace {

constexpr int kLevels = 32; // the uniform arrays of shaders/bake/gpu/bindings.glsl

} // namespace

Result<ConeBakeInputs> prepareConeBake(const HeightField& field, WrapMode wrap, ConeKind kind,
                                       const BakeControl& control) {
    if (field.empty())
        return Error{"the height map is empty"};
    ConeBakeInputs in;
    if (kind == ConeKind::Conservative) {
        const bake::CellPyramid cells(field, wrap);
        if (cells.levels() > kLevels)
            return Error{"the height map has too many pyramid levels for the GPU bake"};
        in.cellLevels = cells.levels();
        for (const MaxLevel& level : cells.levelData()) {
            in.cellSizes.emplace_back(level.width, level.height);
            in.cellOffsets.push_back(static_cast<int>(in.levelValues.size()));
            in.levelValues.insert(in.levelValues.end(), level.values.begin(), level.values.end());
        }
        return in;
    }
    BakeProgress progress(control, std::int64_t(field.height) + 1);
    bake::FallPyramid fall(field, wrap, &progress);
    if (progress.stopRequested())
        return cancelledError();
    if (fall.top() >= kLevels)
        return Error{"the height map has too many pyramid levels for the GPU bake"};
    in.fallTop = fall.top();
    in.fallUnit = fall.unit();
    for (int l = 0; l <= fall.top(); ++l) {
        in.fallSizes.push_back(fall.size(l));
        in.fallOffsets.push_back(static_cast<int>(fall.offset(l)));
    }
    in.fallWords = fall.takeWords();
    const bake::EdgeStrips strips(field, wrap);
    for (int side = 0; side < 4; ++side) {
        in.stripLevels[side] = strips.levels(side);
        for (int l = 0; l < strips.levels(side) && l < kLevels; ++l) {
            in.stripCounts[side * kLevels + l] = strips.count(side, l);
            in.stripOffsets[side * kLevels + l] = static_cast<int>(in.levelValues.size());
            for (int i = 0; i < strips.count(side, l); ++i)
                in.levelValues.push_back(strips.max(side, l, i));
        }
    }
    return in;
}

} // namespace px
