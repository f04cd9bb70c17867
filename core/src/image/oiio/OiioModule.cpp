// The OpenImageIO module (ImageModule.h): every format but PNG, resampling and the JPEG round
// trip, in a shared object of its own that the core loads on first need.

#include "../ImageModule.h"
#include "parallax/Version.h"
#include "parallax/io/FileExtension.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>

namespace px {
namespace {

// OIIO's messages end with newlines and sometimes repeat the file name; keep one clean line.
std::string oiioMessage(std::string message) {
    while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
        message.pop_back();
    std::replace(message.begin(), message.end(), '\n', ' ');
    return message.empty() ? std::string("unknown image library error") : message;
}

OIIO::TypeDesc typeOf(PixelFormat format) {
    switch (format) {
    case PixelFormat::UInt8:
        return OIIO::TypeDesc::UINT8;
    case PixelFormat::UInt16:
        return OIIO::TypeDesc::UINT16;
    case PixelFormat::Half:
        return OIIO::TypeDesc::HALF;
    case PixelFormat::Float:
        return OIIO::TypeDesc::FLOAT;
    }
    return OIIO::TypeDesc::UINT8;
}

class OiioDecoder final : public ImageDecoder {
public:
    explicit OiioDecoder(std::unique_ptr<OIIO::ImageInput> input) : m_input(std::move(input)) {
        const OIIO::ImageSpec& spec = m_input->spec();
        m_header.width = spec.width;
        m_header.height = spec.height;
        m_header.channels = spec.nchannels;
        m_header.depth = spec.depth;
        // Bits as stored: the channels' own formats (EXR mixes half and float), or fewer than 8
        // bits a sample where the format says so.
        for (int c = 0; c < spec.nchannels; ++c)
            m_header.bitsPerTexel += static_cast<std::int64_t>(spec.channelformat(c).size()) * 8;
        if (const int bits = spec.get_int_attribute("oiio:BitsPerSample"); bits > 0)
            m_header.bitsPerTexel = static_cast<std::int64_t>(bits) * spec.nchannels;
        m_header.format = m_input->format_name();
        m_header.compression = spec.get_string_attribute("compression");
        m_header.alphaOnly = spec.nchannels == 1 && spec.alpha_channel == 0;
    }

    const ImageHeader& header() const override { return m_header; }

    Status read(float* texels) override {
        if (!m_input->read_image(0, 0, 0, m_header.channels, OIIO::TypeDesc::FLOAT, texels))
            return Error{"the image data could not be read, the file may be truncated (" +
                         oiioMessage(m_input->geterror()) + ")"};
        m_input->close();
        return success();
    }

private:
    std::unique_ptr<OIIO::ImageInput> m_input;
    ImageHeader m_header;
};

Result<std::unique_ptr<ImageDecoder>> open(const std::string& path) {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1); // material maps are not premultiplied
    auto input = OIIO::ImageInput::open(path, &config);
    if (!input)
        return Error{"not a readable image (" + oiioMessage(OIIO::geterror()) + ")"};
    return std::unique_ptr<ImageDecoder>(std::make_unique<OiioDecoder>(std::move(input)));
}

Result<std::vector<unsigned char>> encode(const std::string& path, const Image& image,
                                          const ImageWriteOptions& options) {
    auto output = OIIO::ImageOutput::create(path);
    if (!output)
        return Error{"no image writer for this extension"};
    OIIO::ImageSpec spec(image.width, image.height, image.channels, typeOf(options.format));
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (options.srgb)
        spec.attribute("oiio:ColorSpace", "sRGB");
    else
        spec.attribute("oiio:ColorSpace", "Linear");
    if (lowerExtension(path) == ".exr")
        spec.attribute("compression", "zip");
    // Encoded in memory: the caller writes the file with every step checked (the image writers
    // do not all report a full disk).
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    if (!output->supports("ioproxy") || !output->set_ioproxy(&memory))
        return Error{"this file type cannot be encoded in memory"};
    if (!output->open(path, spec))
        return Error{"cannot encode the image (" + oiioMessage(output->geterror()) + ")"};
    const bool written = output->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    const bool closed = output->close();
    if (!written || !closed)
        return Error{"encoding failed (" + oiioMessage(output->geterror()) + ")"};
    return encoded;
}

Image resize(const Image& map, int width, int height) {
    const OIIO::ImageBuf source(
        OIIO::ImageSpec(map.width, map.height, map.channels, OIIO::TypeDesc::FLOAT),
        const_cast<float*>(map.pixels.data())); // only read
    OIIO::ImageBuf resampled(OIIO::ImageSpec(width, height, map.channels, OIIO::TypeDesc::FLOAT));
    OIIO::ImageBufAlgo::resize(resampled, source, "triangle");
    Image out(width, height, map.channels);
    resampled.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, map.channels),
                         OIIO::TypeDesc::FLOAT, out.pixels.data());
    return out;
}

Result<std::vector<unsigned char>> throughJpeg(const std::vector<unsigned char>& grey, int width,
                                               int height, int quality) {
    std::vector<unsigned char> file;
    OIIO::Filesystem::IOVecOutput sink(file);
    OIIO::ImageSpec spec(width, height, 1, OIIO::TypeDesc::UINT8);
    spec.attribute("Compression", "jpeg:" + std::to_string(quality));
    void* sinkPtr = &sink;
    spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &sinkPtr);
    auto writer = OIIO::ImageOutput::create("map.jpg");
    if (!writer || !writer->open("map.jpg", spec) ||
        !writer->write_image(OIIO::TypeDesc::UINT8, grey.data()) || !writer->close())
        return Error{"OpenImageIO could not encode a JPEG"};
    OIIO::Filesystem::IOMemReader source(file.data(), file.size());
    OIIO::ImageSpec config;
    void* sourcePtr = &source;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &sourcePtr);
    auto reader = OIIO::ImageInput::open("map.jpg", &config);
    std::vector<unsigned char> decoded(grey.size());
    if (!reader || reader->spec().width != width || reader->spec().height != height ||
        !reader->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT8, decoded.data()))
        return Error{"OpenImageIO could not decode its JPEG"};
    return decoded;
}

const ImageModule kModule{kImageModuleAbi, kVersion, open, encode, resize, throughJpeg};

} // namespace
} // namespace px

extern "C" __attribute__((visibility("default"))) const px::ImageModule* pxImageModule() {
    return &px::kModule;
}
