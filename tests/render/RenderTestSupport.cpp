#include "RenderTestSupport.h"

#include "parallax/sample/ProceduralAlbedo.h"
#include "parallax/sample/ProceduralMaps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace px::test {

bool isLlvmpipe(const std::string& glRenderer) {
    return glRenderer.find("llvmpipe") != std::string::npos;
}

HeadlessContext* glContext() {
    static std::unique_ptr<HeadlessContext> context;
    static std::string failure;
    if (!context && failure.empty()) {
        Result<std::unique_ptr<HeadlessContext>> made = HeadlessContext::create();
        if (made)
            context = std::move(*made);
        else
            failure = made.error().message;
        if (!failure.empty())
            std::fprintf(stderr, "%s\n", failure.c_str());
    }
    return context.get();
}

MaterialAssets bricksAssets(int size, bool withAlbedo) {
    MaterialAssets assets;
    assets.height = makeProceduralMap(ProceduralMap::Bricks, size, size);
    if (withAlbedo)
        assets.albedo = makeProceduralAlbedo(ProceduralMap::Bricks, assets.height);
    return assets;
}

Material sampleMaterial(Technique technique) {
    Material m;
    m.name = "bricks";
    m.technique = technique;
    m.params = info(technique).defaults;
    m.heightScale = 0.06f;
    m.normalSource = NormalSource::HeightCentral;
    m.lighting = LightingModel::BlinnPhong;
    return m;
}

Result<Tracer> makeTracerFor(const HeightField& field, Technique technique,
                             const Material& material) {
    TraceMaps maps;
    maps.height = &field;
    maps.wrap = material.wrap;
    return Tracer::create(maps, technique, material.params, material.heightScale);
}

ImageDifference compareImages(const Image& a, const Image& b, int tolerance) {
    ImageDifference d;
    d.sameSize = a.width == b.width && a.height == b.height && a.channels == b.channels;
    if (!d.sameSize)
        return d;
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            int worst = 0;
            for (int c = 0; c < a.channels; ++c) {
                const int va = static_cast<int>(std::lround(a.at(x, y, c) * 255.0f));
                const int vb = static_cast<int>(std::lround(b.at(x, y, c) * 255.0f));
                worst = std::max(worst, std::abs(va - vb));
                sum += std::abs(va - vb);
            }
            d.maxAbs = std::max(d.maxAbs, worst);
            d.pixelsOver += worst > tolerance;
        }
    }
    d.meanAbs = sum / (static_cast<double>(a.width) * a.height * a.channels);
    return d;
}

} // namespace px::test
