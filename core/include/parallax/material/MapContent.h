#pragma once
// What an image's texels say it is, where a file name cannot: a tangent-space normal map (unit
// vectors around +Z), a grey image (a height, roughness or occlusion candidate), an alpha channel
// worth testing as a height; and, for a normal map alone, which way its green points (only one
// convention makes its slopes the gradient of a surface).

#include "parallax/heightfield/HeightField.h"
#include "parallax/image/Image.h"
#include "parallax/material/Material.h"

#include <optional>

namespace px {

struct ImageTraits {
    bool grey = false;       // one channel, or R = G = B within compression noise
    bool normalLike = false; // decodes to unit vectors around +Z
    double meanZ = 0.0;      // of the decoded vectors (n = 2c - 1)
    double meanLength = 0.0;
    bool alphaVaries = false; // a fourth channel that is not constant
};

// Looks at up to about 260 000 texels spread over the image.
ImageTraits imageTraits(const Image& image);

// One channel as a height field, as stored.
HeightField channelField(const Image& image, int channel);

// The green convention under which a normal map's slopes are a gradient field (its curl is
// small), and how clearly: the ratio of the other convention's curl to the chosen one's (1: no
// telling, as on a map whose slopes run along one axis). OpenGL when it cannot tell.
struct GreenFromCurl {
    NormalGreen green = NormalGreen::OpenGL;
    double clarity = 1.0;
    bool told() const { return clarity >= 1.5; }
};
GreenFromCurl greenFromCurl(const Image& normals);

} // namespace px
