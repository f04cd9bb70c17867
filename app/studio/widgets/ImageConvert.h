#pragma once
// The core's float images as QImages for thumbnails and placeholders (values shown as stored:
// sRGB albedo as is, heights and cones as grey). Downsampled to at most `maxSide` by averaging.

#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/image/Image.h"

#include <QImage>

namespace px::studio {

QImage toQImage(const Image& image, int maxSide);
QImage toQImage(const HeightField& field, int maxSide);
QImage toQImage(const ConeMap& cone, int maxSide); // sqrt(ratio) as grey

} // namespace px::studio
