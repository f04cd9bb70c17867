#include "TextureSets.h"

#include "parallax/bake/NormalMapBaker.h"
#include "parallax/image/ImageFile.h"
#include "parallax/sample/ProceduralMaps.h"

#include <array>
#include <stdexcept>

namespace px::test {

namespace {

void write(const std::string& path, const Image& image, PixelFormat format) {
    ImageWriteOptions options;
    options.format = format;
    if (!writeImage(path, image, options))
        throw std::runtime_error("cannot write " + path);
}

} // namespace

WrittenSet writeTextureSet(const std::string& folder, const TextureSetSpec& spec) {
    constexpr std::array<ProceduralMap, 3> kShapes{ProceduralMap::Noise, ProceduralMap::Stones,
                                                   ProceduralMap::Bricks};
    WrittenSet set;
    set.height =
        makeProceduralMap(kShapes[spec.seed % kShapes.size()], spec.size, spec.size, spec.seed);
    HeightField file = set.height;
    if (spec.depth) {
        for (float& h : file.texels)
            h = 1.0f - h;
    }
    const bool units = spec.fileScale != 0.0f;
    if (units) {
        for (float& h : file.texels)
            h = spec.fileOffset + spec.fileScale * h;
    }
    set.file = file;
    const std::string base = folder + "/" + spec.stem;
    set.heightFile = base + (spec.heightSuffix.empty() ? "_disp" : spec.heightSuffix) +
                     (units ? ".exr" : ".png");
    write(set.heightFile, file.toImage(), units ? PixelFormat::Float : PixelFormat::UInt16);
    if (spec.normal) {
        NormalBakeOptions options;
        options.heightScale = 0.05f;
        options.green = spec.green;
        Result<Image> normals = bakeNormalMap(set.height, options);
        if (!normals)
            throw std::runtime_error(normals.error().message);
        set.normalFile = base + "_normal.png";
        write(set.normalFile, *normals, PixelFormat::UInt8);
    }
    Image albedo(spec.size, spec.size, 3);
    for (std::size_t i = 0; i < albedo.pixels.size(); ++i)
        albedo.pixels[i] = static_cast<float>((i * 37 + spec.seed) % 256) / 255.0f;
    set.albedoFile = base + (spec.albedoSuffix ? "_albedo.png" : ".png");
    write(set.albedoFile, albedo, PixelFormat::UInt8);
    return set;
}

} // namespace px::test
