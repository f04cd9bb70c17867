#pragma once
// Files that store their rows in another order than they are meant to be seen: a phone photo's
// EXIF Orientation, a TIFF's Orientation tag, a Radiance HDR stored bottom-up (+Y, which
// OpenImageIO reports as Orientation 4). Every map is turned upright as it is read, as a viewer
// shows it, and the reader says so (docs/image-files.md).

#include "parallax/image/Image.h"

#include <string>

namespace px {

// The image as displayed for EXIF/TIFF Orientation 1 to 8 (2: mirrored left-right, 3: turned 180°,
// 4: mirrored top-bottom, 5: transposed, 6: stored turned 90° anticlockwise, so turned 90°
// clockwise here, 7: transverse, 8: turned 90° anticlockwise here); 5 to 8 swap width and height.
Image upright(const Image& stored, int orientation);

// What `upright` did, for a note: "rotated 90° clockwise" ...; empty for 1.
std::string orientationChange(int orientation);

} // namespace px
