#pragma once
// PNG read and written by libpng in the core: most maps are PNG, and reading one must not load
// the OpenImageIO module (ImageModule.h), whose libraries take about half a second of CPU to load
// in every run of the command line. Values come out as OpenImageIO's reader gives them (tested
// against it, core.image.PngCodec): palettes and 1-4 bit grey expanded, a tRNS chunk as an alpha
// channel, no gamma applied, no alpha association.

#include "ImageCodec.h"
#include "parallax/image/ImageFile.h"

#include <memory>
#include <string>
#include <vector>

namespace px {

// Reads the header of the PNG file whose whole content is `bytes` (read once, through the input's
// own descriptor: InputFile); libpng's errors are kept (never printed) and come back as the
// problem.
Result<std::unique_ptr<ImageDecoder>> openPng(std::shared_ptr<const std::string> bytes);

// Encodes 8 or 16 bits a channel, 1 to 4 channels. Values clamp to [0, 1] and round to nearest,
// half up (as OpenImageIO's writer, which differs only within a float's precision of a half).
// NaN writes 0. `srgb` writes the sRGB chunk with its gAMA and cHRM;
// otherwise no colour chunk at all (a gAMA 1.0 makes Godot and Unity apply a curve).
Result<std::vector<unsigned char>> encodePng(const Image& image, PixelFormat format, bool srgb);

} // namespace px
