// parallax-cli import: a texture set (a folder, or its files) made into a material file, decided
// as the editor decides (parallax/material/TextureSetImport.h), with the same summary.

#include "Cli.h"
#include "parallax/image/ImageFile.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Inputs.h"
#include "parallax/material/MapKind.h"
#include "parallax/material/MapPaths.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/material/TextureSetImport.h"

#include <filesystem>
#include <iostream>
#include <memory>

namespace px::cli {

namespace {

struct ImportOptions {
    std::vector<std::string> inputs; // one folder, or image files
    std::string set;                 // which set, where there are several
    std::string name;                // the material's name (default: the set's)
    std::string out;
    bool force = false;
    bool deriveHeight = false; // a normal-only set: integrate its normal map into a height map
};

// Where a derived height map goes: beside the material file, named after it.
std::string derivedHeightPath(const std::string& materialFile) {
    const std::filesystem::path out(materialFile);
    return (out.parent_path() / (out.stem().string() + "_height.png")).string();
}

Result<std::vector<std::string>> inputFiles(const ImportOptions& o) {
    std::error_code ec;
    if (o.inputs.size() == 1 && std::filesystem::is_directory(o.inputs.front(), ec))
        return folderFiles(o.inputs.front());
    for (const std::string& file : o.inputs) {
        if (std::filesystem::is_directory(file, ec))
            return fileError(file, "a folder among files: give one folder, or files");
        if (!std::filesystem::exists(file, ec))
            return fileError(file, "no such file");
    }
    return o.inputs;
}

int runImport(const ImportOptions& o) {
    std::error_code ec;
    if (!o.force && std::filesystem::exists(o.out, ec))
        return fail(o.out + ": already exists; --force replaces it");
    Result<std::vector<std::string>> files = inputFiles(o);
    if (!files)
        return fail(files.error().message);
    // The set's images, read or not, are inputs: none may be written over. (Other files, such as
    // an earlier import's material file, may be replaced with --force.)
    for (const std::string& file : *files) {
        if (!isImageFileName(file))
            continue;
        if (Status s = noteInput(file, "an image of the texture set"); !s)
            return fail(s.error().message);
    }
    const std::string source = o.inputs.size() == 1 ? o.inputs.front() : "the files";
    Result<TextureSetPlan> plan = planTextureSet(*files, source, o.set);
    if (!plan) {
        const bool several = textureSetNames(*files).size() > 1 && o.set.empty();
        return fail(plan.error().message + (several ? "; say which with --set NAME" : ""));
    }
    Result<ImportedSet> set = importTextureSet(*plan);
    if (!set)
        return fail(set.error().message);
    if (!o.name.empty())
        set->material.name = o.name;
    OutputBatch outputs; // the material file and its derived height map, both or neither
    std::string heightFile;
    if (set->heightMissing) {
        if (!o.deriveHeight) {
            for (const std::string& line : importSummary(*set))
                std::cout << line << "\n";
            return fail(source + ": the set " + plan->name +
                        " has no height map, only a normal map; --derive-height makes one "
                        "from it");
        }
        heightFile = derivedHeightPath(o.out);
        if (std::filesystem::exists(heightFile, ec)) {
            if (!o.force)
                return fail(heightFile + ": already exists; --force replaces it");
        }
        if (Status s = deriveHeight(*set); !s)
            return fail(s.error().message);
        ImageWriteOptions write;
        write.format = PixelFormat::UInt16;
        if (Status s = writeImage(heightFile, set->assets.height.toImage(), write); !s)
            return fail(s.error().message);
        set->material.maps.height = absolutePath(heightFile);
    }
    Material material = set->material;
    material.maps = relativeMapPaths(material.maps, o.out);
    if (Status s = saveMaterial(material, o.out); !s)
        return fail(s.error().message);
    if (Status s = outputs.commit(); !s)
        return fail(s.error().message);
    for (const std::string& line : importSummary(*set))
        std::cout << line << "\n";
    if (!heightFile.empty())
        std::cout << "wrote " << heightFile << "\n";
    std::cout << "wrote " << o.out << "\n";
    return 0;
}

} // namespace

Action addImportCommand(CLI::App& app) {
    auto o = std::make_shared<ImportOptions>();
    CLI::App* cmd = app.add_subcommand(
        "import", "Make a material file from a texture set: a folder or its files, each map known "
                  "by its name as texture libraries and engines write them (_disp, _nor_gl, "
                  "NormalDX, _arm, _ddna, ...) or by its texels, height or depth and the normal "
                  "map's green told from the data; every file is reported");
    cmd->add_option("inputs", o->inputs, "A folder, or the set's image files")->required();
    cmd->add_option("--set", o->set, "Which set, where the folder holds several (its name)");
    cmd->add_option("--name", o->name, "The material's name (default: the set's)");
    cmd->add_option("--out", o->out, "The material file to write (.json)")->required();
    cmd->add_flag("--force", o->force,
                  "Replace an existing material file (and derived height map)");
    cmd->add_flag("--derive-height", o->deriveHeight,
                  "A set with only a normal map: make its height map by integrating the normal "
                  "map (written beside --out as NAME_height.png, marked as derived)");
    return [o] { return runImport(*o); };
}

} // namespace px::cli
