#pragma once
// One export in progress: the material, its loaded maps, the staging folder, and the helpers
// every target's writer uses.

#include "parallax/eval/EngineLayers.h"
#include "parallax/export/ExportFolder.h"
#include "parallax/export/Exporter.h"

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace px::exporter {

struct ExportJob {
    const Material& material;
    const ExportOptions& options;
    MaterialAssets assets;
    ExportFolder& folder;
    ExportResult& result;
    std::string stem;         // the material's name made safe for file names
    std::string materialFile; // map paths are relative to its folder
    // Technique "auto" for Godot and Unity: the layer counts the engine's own march needs
    // (EngineLayers.h).
    std::optional<EngineLayersAdvice> engineLayers = std::nullopt;
    // Where assets.ao came from, for the notes: its file's name, or "baked here".
    std::string occlusionSource = {};

    // Writes into the export folder and records the file. Errors name the file.
    Status image(const std::string& name, const Image& image, PixelFormat format,
                 bool srgb = false);
    Status text(const std::string& name, std::string_view contents);

    // "STEM_height.png" (16-bit) or "STEM_height.exr" (float), as the options say.
    std::string heightName(const std::string& base) const;

    // The normal map a target without height-derived normals needs, in `green`: the loaded map
    // converted, or one baked from the height map at the material's scale. Empty when the
    // material has neither (adds a note then).
    Result<Image> normals(NormalGreen green);
    // Writes normals(green) as `name` at the options' bit depth; false when there is none.
    Result<bool> writeNormals(const std::string& name, NormalGreen green);

    // Occlusion (R), roughness (G), metallic (B) packed as glTF, Godot and Unreal read them. A
    // roughness or metallic channel without a map holds 1 for targets that multiply it by a
    // factor (glTF, Godot, the package: factors from surfaceFactors()), the material's number for
    // those that read the texel as the value (Unreal); see SurfaceFactors.h. Occlusion without a
    // map: 1. nullopt when the material has none of the three maps.
    enum class MissingChannel { One, Number };
    std::optional<Image> orm(MissingChannel missing) const;

    // Notes where the occlusion map went ("R of bricks_orm.png, glTF's occlusionTexture"), when
    // there is one.
    void noteOcclusion(const std::string& where);

    // The cone map of `kind`: the loaded one, or baked from the height map (with a note).
    ConeMap cones(ConeKind kind);
};

// The float as the shortest decimal that reads back to it (io/ShortestDecimal.h), as text: "0.05".
std::string formatDecimal(float value);

// A file name stem from a material name: letters and digits of any script (UTF-8), '-' and '_'
// kept; spaces, punctuation, controls, invisible and bidirectional-override characters and bytes
// that are not UTF-8 become '_'; at most 100 bytes, cut between characters.
std::string fileStem(const std::string& name);

// Adds the material's specialised shaders to a package (and their lines to `files`); returns
// the usage note's section about them.
Result<std::string> writePackageShader(ExportJob& job, const Material& packaged,
                                       std::vector<std::pair<std::string, std::string>>& files);

// The writers, one per target (PackageExport.cpp, GltfExport.cpp, ...).
Status writePackage(ExportJob& job);
Status writeGltf(ExportJob& job);
Status writeGodot(ExportJob& job);
Status writeUnreal(ExportJob& job);
Status writeUnity(ExportJob& job);

} // namespace px::exporter
