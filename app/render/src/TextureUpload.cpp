#include "parallax/render/TextureUpload.h"

#include "parallax/render/GlInfo.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>

namespace px::gl {

namespace {

Status checkSize(int width, int height, const char* what) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (width <= 0 || height <= 0)
        return Error{std::string("the ") + what + " is empty"};
    if (width > maxSize || height > maxSize)
        return Error{std::string("the ") + what + " (" + std::to_string(width) + " x " +
                     std::to_string(height) + ") exceeds this GPU's largest texture, " +
                     std::to_string(maxSize) + " texels a side"};
    return success();
}

bool anisotropyAvailable() {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const char* e =
            reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
        if (e && (std::strcmp(e, "GL_EXT_texture_filter_anisotropic") == 0 ||
                  std::strcmp(e, "GL_ARB_texture_filter_anisotropic") == 0))
            return true;
    }
    return false;
}

// Level 0 goes up in bands of rows of about this many bytes: an 8192² map's conversion buffer
// would otherwise cost as much as the texture (and llvmpipe keeps both in the process).
constexpr std::size_t kBandBytes = std::size_t(4) << 20;

// Writes rows [y0, y0 + rows) as the texture's `format`/`type` texels into `scratch` (resized to
// fit) and returns them, or returns a pointer into the source when it needs no conversion.
using RowSource = std::function<const void*(int y0, int rows, std::vector<std::byte>& scratch)>;

// Creates a 2D texture of `internalFormat` from `source`, band by band.
Result<Object> makeTexture(int width, int height, GLenum internalFormat, GLenum format, GLenum type,
                           std::size_t texelBytes, const RowSource& source, bool mipmaps,
                           const char* what) {
    if (Status s = checkSize(width, height, what); !s)
        return s.error();
    Object texture(ObjectKind::Texture);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Storage for every level at once: glGenerateMipmap after glTexImage2D makes the driver
    // reallocate the texture with its levels and copy level 0 over (llvmpipe, 8192² height map:
    // a peak 256 MiB higher, measured).
    int levels = 1;
    while (mipmaps && std::max(width, height) >> levels > 0)
        ++levels;
    glTexStorage2D(GL_TEXTURE_2D, levels, internalFormat, width, height);
    const int band =
        static_cast<int>(std::max<std::size_t>(1, kBandBytes / (texelBytes * std::size_t(width))));
    std::vector<std::byte> scratch;
    for (int y0 = 0; y0 < height; y0 += band) {
        const int rows = std::min(band, height - y0);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, y0, width, rows, format, type,
                        source(y0, rows, scratch));
    }
    if (mipmaps) {
        glGenerateMipmap(GL_TEXTURE_2D);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    } else {
        // Bilinear: the production kernels filter cone maps in hardware (texelFetch, which the
        // verify kernels and the atlas use, ignores the filter).
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    if (Status s = checkGlError(std::string("uploading the ") + what); !s)
        return s.error();
    return texture;
}

// A source that reads rows straight out of contiguous texels of `texelBytes` each.
RowSource rowsOf(const void* texels, int width, std::size_t texelBytes) {
    return [=](int y0, int, std::vector<std::byte>&) -> const void* {
        return static_cast<const std::byte*>(texels) +
               static_cast<std::size_t>(y0) * width * texelBytes;
    };
}

// A source that converts each band to `T`, `perTexel` values a texel, with
// `convert(x, y, T* out)`.
template <class T, class Convert> RowSource converted(int width, int perTexel, Convert convert) {
    return [=](int y0, int rows, std::vector<std::byte>& scratch) -> const void* {
        const std::size_t values = static_cast<std::size_t>(width) * rows * perTexel;
        scratch.resize(values * sizeof(T));
        T* out = reinterpret_cast<T*>(scratch.data());
        for (int y = y0; y < y0 + rows; ++y)
            for (int x = 0; x < width; ++x, out += perTexel)
                convert(x, y, out);
        return scratch.data();
    };
}

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float bilinear(const Image& image, int channel, float u, float v) {
    const float x = std::clamp(u * image.width - 0.5f, 0.0f, image.width - 1.0f);
    const float y = std::clamp(v * image.height - 0.5f, 0.0f, image.height - 1.0f);
    const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
    const int x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
    const float fx = x - x0, fy = y - y0;
    const float top = image.at(x0, y0, channel) * (1 - fx) + image.at(x1, y0, channel) * fx;
    const float bottom = image.at(x0, y1, channel) * (1 - fx) + image.at(x1, y1, channel) * fx;
    return top * (1 - fy) + bottom * fy;
}

} // namespace

bool fitsR16(const HeightField& field) {
    for (float h : field.texels) {
        // In double: a float holds k / 65535 to 2^-24 of itself, which above k = 8192 is more
        // than 10^-3 of a step once multiplied out in float.
        const double k = static_cast<double>(h) * 65535.0;
        if (!(h >= 0.0f && h <= 1.0f) || std::abs(k - std::nearbyint(k)) > 1e-3 + k * 0x1p-22)
            return false;
    }
    return true;
}

bool fitsRG16(const ConeMap& cones) {
    // Exactly k / 65535, as the bakers' 16-bit rounding gives it: RG16 then stores k, and the GL
    // reads it back as k / 65535 or an ulp under (never wider, which would let rays through).
    for (float g : cones.sqrtRatio) {
        if (!(g >= 0.0f && g <= 1.0f) || std::nearbyint(g * 65535.0f) / 65535.0f != g)
            return false;
    }
    return true;
}

Result<Object> uploadHeight(const HeightField& field, HeightFormat format) {
    if (format == HeightFormat::R16) {
        const float* h = field.texels.data();
        const int w = field.width;
        return makeTexture(
            field.width, field.height, GL_R16, GL_RED, GL_UNSIGNED_SHORT, 2,
            converted<std::uint16_t>(w, 1,
                                     [h, w](int x, int y, std::uint16_t* out) {
                                         const float v = h[static_cast<std::size_t>(y) * w + x];
                                         *out = static_cast<std::uint16_t>(
                                             std::nearbyint(std::clamp(v, 0.0f, 1.0f) * 65535.0f));
                                     }),
            true, "height map");
    }
    return makeTexture(field.width, field.height, GL_R32F, GL_RED, GL_FLOAT, 4,
                       rowsOf(field.texels.data(), field.width, 4), true, "height map");
}

Result<Object> uploadAlbedo(const Image& albedo) {
    const Image* a = &albedo;
    return makeTexture(albedo.width, albedo.height, GL_RGBA16F, GL_RGBA, GL_FLOAT, 16,
                       converted<float>(albedo.width, 4,
                                        [a](int x, int y, float* out) {
                                            const int c = a->channels;
                                            for (int k = 0; k < 3; ++k)
                                                out[k] = srgbToLinear(a->at(x, y, c >= 3 ? k : 0));
                                            out[3] = c == 2 || c >= 4 ? a->at(x, y, c == 2 ? 1 : 3)
                                                                      : 1.0f;
                                        }),
                       true, "albedo map");
}

Result<Object> uploadNormalMap(const Image& normal) {
    if (normal.channels < 3)
        return Error{"the normal map needs 3 channels, it has " + std::to_string(normal.channels)};
    const Image* n = &normal;
    return makeTexture(normal.width, normal.height, GL_RGBA16, GL_RGBA, GL_FLOAT, 16,
                       converted<float>(normal.width, 4,
                                        [n](int x, int y, float* out) {
                                            for (int k = 0; k < 3; ++k)
                                                out[k] = n->at(x, y, k);
                                            out[3] = 1.0f;
                                        }),
                       true, "normal map");
}

Result<Object> uploadOrm(const Image* ao, const Image* roughness, const Image* metallic) {
    const std::array<const Image*, 3> maps = {ao, roughness, metallic};
    int width = 0, height = 0;
    for (const Image* m : maps) {
        if (m && !m->empty() && m->width * m->height > width * height) {
            width = m->width;
            height = m->height;
        }
    }
    if (width == 0)
        return Error{"no occlusion, roughness or metallic map to pack"};
    return makeTexture(width, height, GL_RGBA16, GL_RGBA, GL_FLOAT, 16,
                       converted<float>(width, 4,
                                        [maps, width, height](int x, int y, float* out) {
                                            for (int k = 0; k < 3; ++k) {
                                                const Image* m = maps[k];
                                                out[k] = !m || m->empty() ? 1.0f
                                                         : m->width == width && m->height == height
                                                             ? m->at(x, y, 0)
                                                             : bilinear(*m, 0, (x + 0.5f) / width,
                                                                        (y + 0.5f) / height);
                                            }
                                            out[3] = 1.0f;
                                        }),
                       true, "occlusion/roughness/metallic map");
}

Result<Object> uploadConeMap(const HeightField& field, const ConeMap& cones, ConeFormat format) {
    if (cones.width != field.width || cones.height != field.height)
        return Error{"the cone map's size differs from the height map's"};
    const float* h = field.texels.data();
    const float* g = cones.sqrtRatio.data();
    const int w = field.width;
    if (format == ConeFormat::RG16) {
        return makeTexture(field.width, field.height, GL_RG16, GL_RG, GL_UNSIGNED_SHORT, 4,
                           converted<std::uint16_t>(
                               w, 2,
                               [h, g, w](int x, int y, std::uint16_t* out) {
                                   const std::size_t i = static_cast<std::size_t>(y) * w + x;
                                   out[0] = static_cast<std::uint16_t>(
                                       std::nearbyint(std::clamp(h[i], 0.0f, 1.0f) * 65535.0f));
                                   out[1] =
                                       static_cast<std::uint16_t>(std::nearbyint(g[i] * 65535.0f));
                               }),
                           false, "cone map");
    }
    return makeTexture(field.width, field.height, GL_RG32F, GL_RG, GL_FLOAT, 8,
                       converted<float>(w, 2,
                                        [h, g, w](int x, int y, float* out) {
                                            const std::size_t i =
                                                static_cast<std::size_t>(y) * w + x;
                                            out[0] = h[i];
                                            out[1] = g[i];
                                        }),
                       false, "cone map");
}

Result<Object> uploadMaxMipAtlas(const MaxMipPyramid& pyramid, std::vector<int>& rows) {
    const Image atlas = pyramid.atlas();
    rows.clear();
    for (int level = 0; level < pyramid.levels(); ++level)
        rows.push_back(pyramid.atlasRow(level));
    return makeTexture(atlas.width, atlas.height, GL_R32F, GL_RED, GL_FLOAT, 4,
                       rowsOf(atlas.pixels.data(), atlas.width, 4), false, "max-mip pyramid");
}

Result<Object> uploadRg32f(int width, int height, const std::vector<float>& texels) {
    return makeTexture(width, height, GL_RG32F, GL_RG, GL_FLOAT, 8, rowsOf(texels.data(), width, 8),
                       false, "cone map");
}

void setWrap(const Object& texture, WrapMode wrap) {
    const GLint mode = wrap == WrapMode::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, mode);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, mode);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void setFilteredSampling(const Object& texture, WrapMode wrap) {
    // llvmpipe's anisotropic filter (Mesa 22) spends seconds per pixel on extreme footprints such
    // as a sphere's poles: minutes per frame. Software renderers filter trilinearly.
    static const bool anisotropy = anisotropyAvailable() && !currentGlInfo().software();
    setWrap(texture, wrap);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    if (anisotropy)
        glTexParameterf(GL_TEXTURE_2D, 0x84FE /* GL_TEXTURE_MAX_ANISOTROPY */, 8.0f);
    glBindTexture(GL_TEXTURE_2D, 0);
}

} // namespace px::gl
