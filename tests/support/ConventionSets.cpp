#include "ConventionSets.h"

#include "parallax/bake/NormalMapBaker.h"
#include "parallax/image/ImageFile.h"
#include "parallax/sample/ProceduralMaps.h"

#include <array>
#include <stdexcept>

namespace px::test {

namespace {

void write(const std::string& path, const Image& image, bool deep) {
    ImageWriteOptions options;
    options.format = deep && extensionSupports(path, PixelFormat::UInt16) ? PixelFormat::UInt16
                                                                          : PixelFormat::UInt8;
    if (path.ends_with(".exr"))
        options.format = PixelFormat::Float;
    if (!writeImage(path, image, options))
        throw std::runtime_error("cannot write " + path);
}

} // namespace

Image withAlpha(const Image& rgb, const HeightField& alpha) {
    Image out(rgb.width, rgb.height, 4);
    for (int y = 0; y < rgb.height; ++y) {
        for (int x = 0; x < rgb.width; ++x) {
            for (int c = 0; c < 3; ++c)
                out.at(x, y, c) = rgb.at(x, y, c);
            out.at(x, y, 3) = alpha.at(x, y);
        }
    }
    return out;
}

float packedValue(int channel, int x, int y) {
    constexpr std::array<float, 4> kBase{0.2f, 0.5f, 0.8f, 0.3f};
    return kBase[static_cast<std::size_t>(channel)] + 0.01f * static_cast<float>((x + 2 * y) % 5);
}

ConventionTruth writeConventionSet(const std::string& folder,
                                   const std::vector<ConventionFile>& files, unsigned seed,
                                   NormalGreen green, int size) {
    constexpr std::array<ProceduralMap, 3> kShapes{ProceduralMap::Noise, ProceduralMap::Stones,
                                                   ProceduralMap::Bricks};
    ConventionTruth truth;
    truth.green = green;
    truth.height = makeProceduralMap(kShapes[seed % kShapes.size()], size, size, seed);
    HeightField depth = truth.height;
    for (float& h : depth.texels)
        h = 1.0f - h;
    NormalBakeOptions bake;
    bake.heightScale = 0.05f;
    bake.green = green;
    Result<Image> normals = bakeNormalMap(truth.height, bake);
    if (!normals)
        throw std::runtime_error(normals.error().message);
    const HeightField unrelated = makeProceduralMap(ProceduralMap::Noise, size, size, seed + 101);
    for (const ConventionFile& f : files) {
        const std::string path = folder + "/" + f.name;
        switch (f.texels) {
        case Texels::Albedo: {
            Image albedo(size, size, 3);
            for (std::size_t i = 0; i < albedo.pixels.size(); ++i)
                albedo.pixels[i] = static_cast<float>((i * 37 + seed * 11) % 256) / 255.0f;
            write(path, albedo, false);
            break;
        }
        case Texels::Height:
            write(path, truth.height.toImage(), true);
            break;
        case Texels::Depth:
            write(path, depth.toImage(), true);
            break;
        case Texels::Normal:
            write(path, *normals, false);
            break;
        case Texels::NormalHeightAlpha:
            write(path, withAlpha(*normals, truth.height), false);
            break;
        case Texels::NormalDepthAlpha:
            write(path, withAlpha(*normals, depth), false);
            break;
        case Texels::NormalGlossAlpha:
            write(path, withAlpha(*normals, unrelated), false);
            break;
        case Texels::Grey:
            write(path, unrelated.toImage(), false);
            break;
        case Texels::Packed: {
            Image packed(size, size, path.ends_with(".jpg") ? 3 : 4);
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x)
                    for (int c = 0; c < packed.channels; ++c)
                        packed.at(x, y, c) = packedValue(c, x, y);
            write(path, packed, false);
            break;
        }
        }
    }
    return truth;
}

} // namespace px::test
