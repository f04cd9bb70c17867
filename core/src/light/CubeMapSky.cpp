#include "parallax/light/CubeMapSky.h"

#include "parallax/image/ImageFile.h"
#include "parallax/light/Environment.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <tbb/parallel_for.h>

namespace px {

namespace {

// The families of face names, each in CubeFace order.
constexpr std::array<std::array<std::string_view, 6>, 4> kFamilies{{
    {"px", "nx", "py", "ny", "pz", "nz"},
    {"posx", "negx", "posy", "negy", "posz", "negz"},
    {"right", "left", "top", "bottom", "front", "back"},
    {"rt", "lf", "up", "dn", "ft", "bk"},
}};

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// `word` written in the case `like` is written in: all upper, capitalised, or lower.
std::string inCaseOf(std::string_view word, const std::string& like) {
    std::string out(word);
    const bool upper = std::all_of(like.begin(), like.end(), [](unsigned char c) {
        return !std::isalpha(c) || std::isupper(c);
    });
    const bool capital =
        !upper && !like.empty() && std::isupper(static_cast<unsigned char>(like[0]));
    for (std::size_t i = 0; i < out.size(); ++i)
        if (upper || (capital && i == 0))
            out[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(out[i])));
    return out;
}

bool isSeparator(char c) {
    return c == '_' || c == '-' || c == '.' || c == ' ';
}

struct FaceSample {
    int face;
    float s, t; // in [0, 1] across the face, t down the image
};

// The face and coordinates OpenGL's cube map selection gives direction d (the GL spec's table:
// major axis, then sc, tc over |ma|).
FaceSample faceOf(glm::vec3 d) {
    const float ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    float sc = 0.0f, tc = 0.0f, ma = 0.0f;
    int face = 0;
    if (ax >= ay && ax >= az) {
        face = d.x >= 0.0f ? 0 : 1;
        ma = ax;
        sc = d.x >= 0.0f ? -d.z : d.z;
        tc = -d.y;
    } else if (ay >= az) {
        face = d.y >= 0.0f ? 2 : 3;
        ma = ay;
        sc = d.x;
        tc = d.y >= 0.0f ? d.z : -d.z;
    } else {
        face = d.z >= 0.0f ? 4 : 5;
        ma = az;
        sc = d.z >= 0.0f ? d.x : -d.x;
        tc = -d.y;
    }
    return {face, 0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f)};
}

glm::vec3 sampleFace(const Image& face, float s, float t) {
    const float x = s * face.width - 0.5f, y = t * face.height - 0.5f;
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float fx = x - x0, fy = y - y0;
    auto texel = [&](int i, int j) {
        i = std::clamp(i, 0, face.width - 1);
        j = std::clamp(j, 0, face.height - 1);
        return glm::vec3(face.at(i, j, 0), face.at(i, j, 1), face.at(i, j, 2));
    };
    return (1.0f - fy) * ((1.0f - fx) * texel(x0, y0) + fx * texel(x0 + 1, y0)) +
           fy * ((1.0f - fx) * texel(x0, y0 + 1) + fx * texel(x0 + 1, y0 + 1));
}

} // namespace

std::optional<CubeFaceFiles> cubeFaceFiles(const std::string& path) {
    const std::filesystem::path file(path);
    const std::string stem = file.stem().string();
    const std::string lowered = lower(stem);
    for (const auto& family : kFamilies) {
        for (std::size_t f = 0; f < family.size(); ++f) {
            const std::string_view word = family[f];
            if (lowered.size() < word.size() ||
                lowered.compare(lowered.size() - word.size(), word.size(), word) != 0)
                continue;
            const std::size_t at = lowered.size() - word.size();
            if (at > 0 && !isSeparator(lowered[at - 1]))
                continue; // "fx" in "sfx", "up" in "backup"
            const std::string written = stem.substr(at);
            CubeFaceFiles files;
            files.face = static_cast<CubeFace>(f);
            for (std::size_t g = 0; g < family.size(); ++g) {
                const std::string name =
                    stem.substr(0, at) + inCaseOf(family[g], written) + file.extension().string();
                files.paths[g] = (file.parent_path() / name).string();
            }
            return files;
        }
    }
    return std::nullopt;
}

Image equirectFromCube(const std::array<Image, 6>& faces, int width) {
    const int height = std::max(1, width / 2);
    Image out(width, height, 3);
    const ImageWriter put = out.writer();
    tbb::parallel_for(0, height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            const glm::vec3 d = equirectDirection({(x + 0.5f) / width, (y + 0.5f) / height});
            const FaceSample f = faceOf(d);
            const glm::vec3 c = sampleFace(faces[static_cast<std::size_t>(f.face)], f.s, f.t);
            for (int k = 0; k < 3; ++k)
                put.at(x, y, k) = c[k];
        }
    });
    return out;
}

Result<Image> loadCubeMapSky(const CubeFaceFiles& files, int maxWidth) {
    std::array<Image, 6> faces;
    for (std::size_t i = 0; i < faces.size(); ++i) {
        const std::string& path = files.paths[i];
        if (!std::filesystem::exists(path))
            return fileError(
                path, "is missing: a cube map needs all six faces (" +
                          std::filesystem::path(path).filename().string() + " beside " +
                          std::filesystem::path(files.paths[static_cast<std::size_t>(files.face)])
                              .filename()
                              .string() +
                          ")");
        ImageReadOptions options;
        options.maxMagnitude = 1e20f;
        options.limitReason = "an environment's radiance may reach (the lighting's integrals "
                              "would overflow and render black)";
        Result<Image> read = readImage(path, options);
        if (!read)
            return read.error();
        const Image& in = *read;
        if (in.width != in.height)
            return fileError(path, "is " + std::to_string(in.width) + " x " +
                                       std::to_string(in.height) + "; a cube face is square");
        if (i > 0 && in.width != faces[0].width)
            return fileError(path, "is " + std::to_string(in.width) + " x " +
                                       std::to_string(in.height) + "; the other faces are " +
                                       std::to_string(faces[0].width) + " x " +
                                       std::to_string(faces[0].height));
        const int colours = in.channels >= 3 ? 3 : 1;
        Image rgb(in.width, in.height, 3);
        const ImageWriter put = rgb.writer();
        for (int y = 0; y < in.height; ++y)
            for (int x = 0; x < in.width; ++x)
                for (int c = 0; c < 3; ++c) {
                    const float v = in.at(x, y, std::min(c, colours - 1));
                    if (v < 0.0f)
                        return fileError(path, "has negative radiance at texel (" +
                                                   std::to_string(x) + ", " + std::to_string(y) +
                                                   ")");
                    put.at(x, y, c) = v;
                }
        faces[i] = std::move(rgb);
    }
    return equirectFromCube(faces, std::min(4 * faces[0].width, maxWidth));
}

} // namespace px
