#include "parallax/render/TextureUpload.h"

#include "parallax/render/GlInfo.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
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

// Creates a 2D texture from float texels converted by GL to `internalFormat`.
Result<Object> makeTexture(int width, int height, GLenum internalFormat, GLenum format, GLenum type,
                           const void* data, bool mipmaps, const char* what) {
    if (Status s = checkSize(width, height, what); !s)
        return s.error();
    Object texture(ObjectKind::Texture);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internalFormat), width, height, 0, format,
                 type, data);
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
        const float k = h * 65535.0f;
        if (!(h >= 0.0f && h <= 1.0f) || std::abs(k - std::nearbyint(k)) > 1e-3f)
            return false;
    }
    return true;
}

Result<Object> uploadHeight(const HeightField& field, HeightFormat format) {
    if (format == HeightFormat::R16) {
        std::vector<std::uint16_t> texels(field.texels.size());
        std::transform(field.texels.begin(), field.texels.end(), texels.begin(), [](float h) {
            return static_cast<std::uint16_t>(std::nearbyint(std::clamp(h, 0.0f, 1.0f) * 65535.0f));
        });
        return makeTexture(field.width, field.height, GL_R16, GL_RED, GL_UNSIGNED_SHORT,
                           texels.data(), true, "height map");
    }
    return makeTexture(field.width, field.height, GL_R32F, GL_RED, GL_FLOAT, field.texels.data(),
                       true, "height map");
}

Result<Object> uploadAlbedo(const Image& albedo) {
    std::vector<float> rgba(static_cast<std::size_t>(albedo.width) * albedo.height * 4, 1.0f);
    for (int y = 0; y < albedo.height; ++y) {
        for (int x = 0; x < albedo.width; ++x) {
            float* out = &rgba[(static_cast<std::size_t>(y) * albedo.width + x) * 4];
            const int c = albedo.channels;
            for (int k = 0; k < 3; ++k)
                out[k] = srgbToLinear(albedo.at(x, y, c >= 3 ? k : 0));
            if (c == 2 || c >= 4)
                out[3] = albedo.at(x, y, c == 2 ? 1 : 3);
        }
    }
    return makeTexture(albedo.width, albedo.height, GL_RGBA16F, GL_RGBA, GL_FLOAT, rgba.data(),
                       true, "albedo map");
}

Result<Object> uploadNormalMap(const Image& normal) {
    if (normal.channels < 3)
        return Error{"the normal map needs 3 channels, it has " + std::to_string(normal.channels)};
    std::vector<float> rgba(static_cast<std::size_t>(normal.width) * normal.height * 4, 1.0f);
    for (int y = 0; y < normal.height; ++y) {
        for (int x = 0; x < normal.width; ++x) {
            for (int k = 0; k < 3; ++k)
                rgba[(static_cast<std::size_t>(y) * normal.width + x) * 4 + k] = normal.at(x, y, k);
        }
    }
    return makeTexture(normal.width, normal.height, GL_RGBA16, GL_RGBA, GL_FLOAT, rgba.data(), true,
                       "normal map");
}

Result<Object> uploadOrm(const Image* ao, const Image* roughness, const Image* metallic) {
    const Image* maps[3] = {ao, roughness, metallic};
    int width = 0, height = 0;
    for (const Image* m : maps) {
        if (m && !m->empty() && m->width * m->height > width * height) {
            width = m->width;
            height = m->height;
        }
    }
    if (width == 0)
        return Error{"no occlusion, roughness or metallic map to pack"};
    std::vector<float> rgba(static_cast<std::size_t>(width) * height * 4, 1.0f);
    for (int k = 0; k < 3; ++k) {
        const Image* m = maps[k];
        if (!m || m->empty())
            continue;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const float v = m->width == width && m->height == height
                                    ? m->at(x, y, 0)
                                    : bilinear(*m, 0, (x + 0.5f) / width, (y + 0.5f) / height);
                rgba[(static_cast<std::size_t>(y) * width + x) * 4 + k] = v;
            }
        }
    }
    return makeTexture(width, height, GL_RGBA16, GL_RGBA, GL_FLOAT, rgba.data(), true,
                       "occlusion/roughness/metallic map");
}

Result<Object> uploadConeMap(const HeightField& field, const ConeMap& cones) {
    if (cones.width != field.width || cones.height != field.height)
        return Error{"the cone map's size differs from the height map's"};
    std::vector<float> rg(field.texels.size() * 2);
    for (std::size_t i = 0; i < field.texels.size(); ++i) {
        rg[2 * i] = field.texels[i];
        rg[2 * i + 1] = cones.sqrtRatio[i];
    }
    return uploadRg32f(field.width, field.height, rg);
}

Result<Object> uploadMaxMipAtlas(const MaxMipPyramid& pyramid, std::vector<int>& rows) {
    const Image atlas = pyramid.atlas();
    rows.clear();
    for (int level = 0; level < pyramid.levels(); ++level)
        rows.push_back(pyramid.atlasRow(level));
    return makeTexture(atlas.width, atlas.height, GL_R32F, GL_RED, GL_FLOAT, atlas.pixels.data(),
                       false, "max-mip pyramid");
}

Result<Object> uploadRg32f(int width, int height, const std::vector<float>& texels) {
    return makeTexture(width, height, GL_RG32F, GL_RG, GL_FLOAT, texels.data(), false, "cone map");
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
