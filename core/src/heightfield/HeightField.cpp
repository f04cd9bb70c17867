#include "parallax/heightfield/HeightField.h"

#include <algorithm>

namespace px {

float HeightField::maxHeight() const {
    return texels.empty() ? 0.0f : *std::max_element(texels.begin(), texels.end());
}

float HeightField::minHeight() const {
    return texels.empty() ? 0.0f : *std::min_element(texels.begin(), texels.end());
}

Image HeightField::toImage() const {
    Image image(width, height, 1);
    image.pixels = texels;
    return image;
}

} // namespace px
