// parallax-cli sample: writes one of the procedural height maps the project makes itself.

#include "Cli.h"
#include "CommonOptions.h"
#include "parallax/image/ImageFile.h"
#include "parallax/sample/ProceduralMaps.h"

#include <memory>

namespace px::cli {

namespace {

struct SampleOptions {
    std::string name = "bricks";
    int width = 256;
    int height = 0; // 0: square
    unsigned seed = 1;
    float level = 0.5f;
    int bits = 16;
    std::string out;
};

int runSample(const SampleOptions& o) {
    const HeightField field = makeProceduralMap(*parseProceduralMap(o.name), o.width,
                                                o.height > 0 ? o.height : o.width, o.seed, o.level);
    Result<PixelFormat> format = pixelFormatFromBits(o.bits);
    if (!format)
        return fail(format.error().message);
    ImageWriteOptions options;
    options.format = *format;
    if (Status s = writeImage(o.out, field.toImage(), options); !s)
        return fail(s.error().message);
    return 0;
}

} // namespace

Action addSampleCommand(CLI::App& app) {
    auto o = std::make_shared<SampleOptions>();
    CLI::App* cmd = app.add_subcommand("sample", "Write a procedural height map (built-in samples "
                                                 "and test shapes)");
    std::vector<std::string> names(proceduralMapNames().begin(), proceduralMapNames().end());
    cmd->add_option("name", o->name, "Which map")->check(CLI::IsMember(names));
    cmd->add_option("--size", o->width, "Width in texels")->check(inRange(1, 16384));
    cmd->add_option("--height-texels", o->height, "Height in texels (default: square)")
        ->check(inRange(1, 16384));
    cmd->add_option("--seed", o->seed, "Random seed");
    cmd->add_option("--level", o->level, "Height of the flat map")->check(inRange(0.0, 1.0));
    cmd->add_option("--bits", o->bits, "8, 16 or 32 (float)")->check(CLI::IsMember({8, 16, 32}));
    cmd->add_option("--out", o->out, "Output image (.png, .tif, .exr)")->required();
    return [o] { return runSample(*o); };
}

} // namespace px::cli
