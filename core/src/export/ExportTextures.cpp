#include "ExportTextures.h"

#include <algorithm>
#include <cmath>

namespace px::exporter {

Image heightImage(const HeightField& field, bool asDepth) {
    Image image(field.width, field.height, 1);
    for (std::size_t i = 0; i < field.texels.size(); ++i)
        image.pixels[i] = asDepth ? 1.0f - field.texels[i] : field.texels[i];
    return image;
}

Image coneImage(const HeightField& field, const ConeMap& cone, int bits) {
    const float steps = bits == 8 ? 255.0f : bits == 16 ? 65535.0f : 0.0f;
    Image image(field.width, field.height, 2);
    const ImageWriter put = image.writer();
    for (int y = 0; y < field.height; ++y) {
        for (int x = 0; x < field.width; ++x) {
            const float g = std::clamp(cone.g(x, y), 0.0f, 1.0f);
            put.at(x, y, 0) = field.at(x, y);
            put.at(x, y, 1) = steps > 0.0f ? std::floor(g * steps) / steps : g;
        }
    }
    return image;
}

Image specularLevel(const Image& specular) {
    Image out(specular.width, specular.height, 1);
    const ImageWriter put = out.writer();
    const int colours = specular.channels >= 3 ? 3 : 1; // grey + alpha: the grey
    for (int y = 0; y < specular.height; ++y) {
        for (int x = 0; x < specular.width; ++x) {
            float level = specular.at(x, y, 0);
            for (int c = 1; c < colours; ++c)
                level = std::max(level, specular.at(x, y, c));
            put.at(x, y, 0) = level;
        }
    }
    return out;
}

Image resample(const Image& image, int width, int height, WrapMode wrap) {
    if (image.width == width && image.height == height)
        return image;
    Image out(width, height, image.channels);
    const ImageWriter put = out.writer();
    for (int y = 0; y < height; ++y) {
        const double sy = (y + 0.5) * image.height / height - 0.5;
        const int y0 = static_cast<int>(std::floor(sy));
        const float fy = static_cast<float>(sy - y0);
        const int ya = wrapIndex(y0, image.height, wrap),
                  yb = wrapIndex(y0 + 1, image.height, wrap);
        for (int x = 0; x < width; ++x) {
            const double sx = (x + 0.5) * image.width / width - 0.5;
            const int x0 = static_cast<int>(std::floor(sx));
            const float fx = static_cast<float>(sx - x0);
            const int xa = wrapIndex(x0, image.width, wrap);
            const int xb = wrapIndex(x0 + 1, image.width, wrap);
            for (int c = 0; c < image.channels; ++c) {
                const float top = image.at(xa, ya, c) * (1 - fx) + image.at(xb, ya, c) * fx;
                const float bottom = image.at(xa, yb, c) * (1 - fx) + image.at(xb, yb, c) * fx;
                put.at(x, y, c) = top * (1 - fy) + bottom * fy;
            }
        }
    }
    return out;
}

std::optional<Image> packChannels(const ChannelSource* sources, int channels, WrapMode wrap) {
    int width = 0, height = 0;
    for (int c = 0; c < channels; ++c) {
        const Image* image = sources[c].image;
        if (image && !image->empty()) {
            width = std::max(width, image->width);
            height = std::max(height, image->height);
        }
    }
    if (width == 0)
        return std::nullopt;
    Image out(width, height, channels);
    const ImageWriter put = out.writer();
    for (int c = 0; c < channels; ++c) {
        const ChannelSource& s = sources[c];
        if (!s.image || s.image->empty()) {
            for (int y = 0; y < height; ++y) {
                for (int x = 0; x < width; ++x)
                    put.at(x, y, c) = s.constant;
            }
            continue;
        }
        const Image scaled = resample(*s.image, width, height, wrap);
        const int channel = std::min(s.channel, scaled.channels - 1);
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const float v = scaled.at(x, y, channel);
                put.at(x, y, c) = s.invert ? 1.0f - v : v;
            }
        }
    }
    return out;
}

} // namespace px::exporter
