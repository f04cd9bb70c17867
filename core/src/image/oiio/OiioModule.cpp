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
#include <sys/mman.h>
#include <unistd.h>

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

// A decoder's input: OpenImageIO reads the bytes through a memory proxy where the format's reader
// takes one, else through a memory file (memfd) it opens by its /proc name. Either way nothing
// opens the user's path again: the file read is the file opened and recorded (Inputs.h).
class MemorySource {
public:
    explicit MemorySource(std::shared_ptr<const std::string> bytes)
        : m_bytes(std::move(bytes)), m_proxy(const_cast<char*>(m_bytes->data()), m_bytes->size()) {
    } // only read
    MemorySource(const MemorySource&) = delete;
    MemorySource& operator=(const MemorySource&) = delete;
    ~MemorySource() {
        if (m_fd >= 0)
            ::close(m_fd);
    }

    // The name to open and the configuration to open it with (the path, for the reader's
    // messages, where it reads through the proxy); an error if no memory file can be made.
    Result<std::string> prepare(const OIIO::ImageInput& reader, const std::string& path,
                                OIIO::ImageSpec& config) {
        if (reader.supports("ioproxy")) {
            void* proxy = &m_proxy;
            config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
            return path;
        }
        m_fd = ::memfd_create("parallax-image", MFD_CLOEXEC);
        std::size_t written = 0;
        while (m_fd >= 0 && written < m_bytes->size()) {
            const ssize_t n = ::write(m_fd, m_bytes->data() + written, m_bytes->size() - written);
            if (n <= 0)
                return Error{"the image could not be copied to memory for its reader"};
            written += static_cast<std::size_t>(n);
        }
        if (m_fd < 0)
            return Error{"the image could not be copied to memory for its reader"};
        return "/proc/self/fd/" + std::to_string(m_fd);
    }

private:
    std::shared_ptr<const std::string> m_bytes;
    OIIO::Filesystem::IOMemReader m_proxy;
    int m_fd = -1;
};

// "albedo" for "albedo.R"; "" for a channel of no layer ("R", "Y").
std::string layerOf(const std::string& channel) {
    const std::size_t dot = channel.find_last_of('.');
    return dot == std::string::npos ? std::string() : channel.substr(0, dot);
}

std::string sizeOf(const OIIO::ImageSpec& spec) {
    return std::to_string(spec.width) + "x" + std::to_string(spec.height);
}

class OiioDecoder final : public ImageDecoder {
public:
    OiioDecoder(std::unique_ptr<MemorySource> source, std::unique_ptr<OIIO::ImageInput> input)
        : m_source(std::move(source)), m_input(std::move(input)) {}

    // Settles the subimage and the channels to read, or says what there is to choose from.
    Status choose(const ImageSource& source) {
        std::vector<OIIO::ImageSpec> subimages;
        for (int s = 0; m_input->seek_subimage(s, 0); ++s)
            subimages.push_back(m_input->spec());
        const bool exr = source.format == "openexr";
        const std::string kind = exr ? "part" : "page";
        auto nameOf = [&](std::size_t s) {
            const std::string name = subimages[s].get_string_attribute("name");
            return exr && !name.empty() ? name : std::to_string(s);
        };
        auto list = [&] {
            std::string text;
            for (std::size_t s = 0; s < subimages.size(); ++s)
                text += (s ? ", " : "") + nameOf(s) + " (" + sizeOf(subimages[s]) + ", " +
                        std::to_string(subimages[s].nchannels) +
                        (subimages[s].nchannels == 1 ? " channel)" : " channels)");
            return text;
        };
        if (subimages.empty())
            return Error{"the file holds no image"};
        int chosen = -1;
        bool layerNamedPart = false;
        if (source.page >= 0) {
            if (source.page >= static_cast<int>(subimages.size()))
                return Error{"the file has no " + kind + " " + std::to_string(source.page) +
                             "; it holds " + std::to_string(subimages.size()) + ": " + list()};
            chosen = source.page;
        } else if (subimages.size() > 1) {
            for (std::size_t s = 0; s < subimages.size() && !source.layer.empty(); ++s)
                if (exr && nameOf(s) == source.layer)
                    chosen = static_cast<int>(s), layerNamedPart = true;
            if (chosen < 0)
                return Error{"the file holds " + std::to_string(subimages.size()) + " " + kind +
                             "s: " + list() + "; choose one (" + (exr ? "--layer NAME or " : "") +
                             "--page N)"};
        } else {
            chosen = 0;
        }
        if (!m_input->seek_subimage(chosen, 0))
            return Error{"the " + kind + " cannot be read (" + oiioMessage(m_input->geterror()) +
                         ")"};
        (void)m_input->geterror(); // the count's seek past the last one leaves an error behind
        const OIIO::ImageSpec& spec = m_input->spec();
        if (subimages.size() > 1)
            m_header.chosen = kind + " " + nameOf(static_cast<std::size_t>(chosen));
        m_subimage = chosen;

        // The layers of the chosen image (an EXR's "albedo.R", "height.Y"): one, or the one named.
        std::vector<std::string> layers;
        for (const std::string& name : spec.channelnames)
            if (std::find(layers.begin(), layers.end(), layerOf(name)) == layers.end())
                layers.push_back(layerOf(name));
        m_chBegin = 0;
        m_chEnd = spec.nchannels;
        const std::string wanted = layerNamedPart ? std::string() : source.layer;
        auto layerList = [&] {
            std::string text;
            for (const std::string& l : layers) {
                std::string channels;
                for (const std::string& name : spec.channelnames)
                    if (layerOf(name) == l)
                        channels += (channels.empty() ? "" : ",") + name;
                text +=
                    (text.empty() ? "" : "; ") + (l.empty() ? "(unnamed): " : l + ": ") + channels;
            }
            return text;
        };
        if (!wanted.empty() || layers.size() > 1) {
            const auto at = std::find(layers.begin(), layers.end(), wanted);
            if (wanted.empty())
                return Error{"the file holds " + std::to_string(layers.size()) +
                             " layers: " + layerList() + "; choose one (--layer NAME)"};
            if (at == layers.end())
                return Error{"the file has no layer '" + wanted + "'; its layers: " + layerList()};
            int first = -1, last = -1;
            for (int c = 0; c < spec.nchannels; ++c) {
                if (layerOf(spec.channelnames[c]) == wanted) {
                    first = first < 0 ? c : first;
                    last = c;
                }
            }
            for (int c = first; c <= last; ++c)
                if (layerOf(spec.channelnames[c]) != wanted)
                    return Error{"the layer '" + wanted + "' has channels apart from each other"};
            m_chBegin = first;
            m_chEnd = last + 1;
            m_header.chosen +=
                (m_header.chosen.empty() ? "" : ", ") + std::string("layer ") + wanted;
        }

        m_header.width = spec.width;
        m_header.height = spec.height;
        m_header.channels = m_chEnd - m_chBegin;
        m_header.depth = spec.depth;
        // Bits as stored: the channels' own formats (EXR mixes half and float), or fewer than 8
        // bits a sample where the format says so.
        for (int c = m_chBegin; c < m_chEnd; ++c)
            m_header.bitsPerTexel += static_cast<std::int64_t>(spec.channelformat(c).size()) * 8;
        if (const int bits = spec.get_int_attribute("oiio:BitsPerSample"); bits > 0)
            m_header.bitsPerTexel = static_cast<std::int64_t>(bits) * m_header.channels;
        m_header.format = m_input->format_name();
        m_header.compression = spec.get_string_attribute("compression");
        m_header.alphaOnly = m_header.channels == 1 && spec.alpha_channel == m_chBegin;
        m_header.orientation = std::clamp(spec.get_int_attribute("Orientation", 1), 1, 8);
        return success();
    }

    const ImageHeader& header() const override { return m_header; }

    Status read(float* texels) override {
        if (!m_input->read_image(m_subimage, 0, m_chBegin, m_chEnd, OIIO::TypeDesc::FLOAT, texels))
            return Error{"the image data could not be read, the file may be truncated (" +
                         oiioMessage(m_input->geterror()) + ")"};
        // Some readers (JPEG, TIFF strips) meet damage as a warning, fill in and succeed.
        const std::string warned = m_input->geterror();
        m_input->close();
        if (!warned.empty())
            return Error{"the image data is damaged or truncated (" + oiioMessage(warned) + ")"};
        return success();
    }

private:
    std::unique_ptr<MemorySource> m_source; // outlives the reader that reads it
    std::unique_ptr<OIIO::ImageInput> m_input;
    ImageHeader m_header;
    int m_subimage = 0, m_chBegin = 0, m_chEnd = 0;
};

Result<std::unique_ptr<ImageDecoder>> open(const ImageSource& source) {
    auto input = OIIO::ImageInput::create(source.format);
    if (!input)
        return Error{"no reader for its format (" + source.format + ") in this build (" +
                     oiioMessage(OIIO::geterror()) + ")"};
    auto memory = std::make_unique<MemorySource>(source.bytes);
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1); // material maps are not premultiplied
    Result<std::string> name = memory->prepare(*input, source.path, config);
    if (!name)
        return name.error();
    OIIO::ImageSpec spec;
    if (!input->open(*name, spec, config))
        return Error{"not a readable " + source.format + " image (" +
                     oiioMessage(input->geterror()) + ")"};
    auto decoder = std::make_unique<OiioDecoder>(std::move(memory), std::move(input));
    if (Status chosen = decoder->choose(source); !chosen)
        return chosen.error();
    return std::unique_ptr<ImageDecoder>(std::move(decoder));
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
