#include "parallax/material/TextureSetImport.h"

#include "parallax/bake/HeightFromNormals.h"
#include "parallax/image/ImageFile.h"
#include "parallax/material/MapContent.h"
#include "parallax/material/MapPaths.h"
#include "parallax/material/MaterialNames.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

namespace px {

namespace {

// Agreement with the normal map's slopes that makes a normal map's alpha a height map (its
// place in the classic parallax packing: a weak hint already).
constexpr double kHeightAgreement = 0.5;
// ... and a grey file named after the set, which is an albedo unless strong evidence says
// otherwise: a near-grey albedo's shading follows the relief's slopes too (r = 0.54 was seen).
constexpr double kUntaggedHeightAgreement = 0.8;
// A file named as a normal map whose vectors do not point out of the surface on average (a
// sky-box face named SKY_n: mean z -0.05) contradicts the name, and the name loses. A normal map
// has mean z over 0.8 when normalised; an unnormalised one still over 0.4 (LearnOpenGL's
// toy_box_normal.png: mean length 0.58, mean z 0.50, used as named with a warning).
constexpr double kNormalMinMeanZ = 0.25;

std::string fileName(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

// Of several files for one map, the deepest format first: float, then 16-bit capable, then 8-bit.
int formatRank(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".exr" ? 3 : (ext == ".tif" || ext == ".tiff") ? 2 : ext == ".png" ? 1 : 0;
}

std::string fixed2(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", value);
    return text;
}

std::string shortNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

// A file value as the user would type it back: up to 7 significant digits.
std::string fileValue(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", value);
    return text;
}

const char* greenName(NormalGreen green) {
    return green == NormalGreen::OpenGL ? "OpenGL (Y+)" : "DirectX (Y-)";
}

// The decisions of one import, file by file.
class Importer {
public:
    Importer(const TextureSetPlan& plan, const AssetLoadOptions& options)
        : m_plan(plan), m_options(options) {
        for (const SetFile& f : plan.files)
            m_out.files.push_back({f.path, "", "", false});
    }

    Result<ImportedSet> run(const Material& base);

private:
    ImportedFile& report(const SetFile& f) {
        for (ImportedFile& r : m_out.files) {
            if (r.path == f.path)
                return r;
        }
        return m_out.files.front();
    }
    void use(const SetFile& f, std::string role, std::string why) {
        ImportedFile& r = report(f);
        r.role = std::move(role);
        r.why = std::move(why);
        r.used = true;
    }
    void skip(const SetFile& f, std::string why) {
        ImportedFile& r = report(f);
        r.why = std::move(why);
        r.used = false;
    }
    // The files named as `role`, the preferred first.
    std::vector<const SetFile*> named(MapRole role) const {
        std::vector<const SetFile*> out;
        for (const SetFile& f : m_plan.files) {
            if (f.role == role)
                out.push_back(&f);
        }
        std::stable_sort(out.begin(), out.end(), [](const SetFile* a, const SetFile* b) {
            return formatRank(a->path) > formatRank(b->path);
        });
        return out;
    }
    // Keeps the first of `files` for `role` when none is chosen yet, the rest reported unused.
    const SetFile* pick(const std::vector<const SetFile*>& files, const SetFile* chosen) {
        for (const SetFile* f : files) {
            if (!chosen)
                chosen = f;
            else if (f != chosen)
                skip(*f, "another file for the same map: " + fileName(chosen->path) + " is used");
        }
        return chosen;
    }
    Result<Image> load(const SetFile& f) {
        if (auto it = m_images.find(f.path); it != m_images.end())
            return it->second;
        ImageReadOptions read;
        read.maxSide = m_options.allowLarge ? (1 << 30) : 16384;
        Result<Image> image = readImage(f.path, read);
        if (image)
            m_images[f.path] = *image;
        else
            m_problems += (m_problems.empty() ? "" : "\n") + image.error().message;
        return image;
    }

    void chooseNormal();
    void chooseHeight();
    void readAlpha();
    void readRelief();
    void chooseSurface();
    void reportTheRest();

    const TextureSetPlan& m_plan;
    const AssetLoadOptions& m_options;
    ImportedSet m_out;
    std::map<std::string, Image> m_images;
    std::string m_problems;
    const SetFile* m_normal = nullptr;
    const SetFile* m_height = nullptr; // a file of its own
    bool m_heightInAlpha = false;
    bool m_depthByName = false;
    ReliefReading m_alphaReading;
    const SetFile* m_albedo = nullptr;
    std::vector<const SetFile*> m_untagged;
    std::set<const SetFile*> m_contradicted; // named as normal maps, whose texels say otherwise
};

void Importer::chooseNormal() {
    // OpenGL named first (Poly Haven ships _nor_gl beside _nor_dx), then unnamed, then DirectX.
    std::vector<const SetFile*> normals = named(MapRole::Normal);
    std::stable_sort(normals.begin(), normals.end(), [](const SetFile* a, const SetFile* b) {
        auto rank = [](GreenHint g) {
            return g == GreenHint::OpenGL ? 0 : g == GreenHint::None ? 1 : 2;
        };
        return rank(a->green) < rank(b->green);
    });
    for (const SetFile* f : named(MapRole::NormalGloss))
        normals.push_back(f);
    // A name contradicted by the texels is no normal map: the next file named as one is tried.
    for (const SetFile* f : normals) {
        Result<Image> image = load(*f);
        if (!image)
            continue; // the problem is reported
        const ImageTraits t = imageTraits(*image);
        if (!t.normalLike && t.meanZ < kNormalMinMeanZ) {
            skip(*f, f->why +
                         ", but its texels are not a normal map: they do not point out of "
                         "the surface (mean z " +
                         fixed2(t.meanZ) + ", mean length " + fixed2(t.meanLength) +
                         "; a normal map's mean z is over 0.4): not used");
            m_contradicted.insert(f);
        }
    }
    std::erase_if(normals, [&](const SetFile* f) { return m_contradicted.contains(f); });
    m_normal = pick(normals, nullptr);
    // A "bump" file may be a normal map (older packs call normal maps bump maps); its texels say.
    for (const SetFile* f : named(MapRole::Bump)) {
        Result<Image> image = load(*f);
        if (image && imageTraits(*image).normalLike) {
            if (!m_normal) {
                m_normal = f;
                use(*f, "normal map", f->why + ", and its texels are a normal map");
            } else {
                skip(*f, "its texels are a normal map, and " + fileName(m_normal->path) +
                             " is the set's");
            }
        }
    }
    // A file named after the set whose texels are a normal map.
    for (const SetFile& f : m_plan.files) {
        if (!f.role)
            m_untagged.push_back(&f);
    }
    for (const SetFile* f : m_untagged) {
        Result<Image> image = load(*f);
        if (!m_normal && image && imageTraits(*image).normalLike) {
            m_normal = f;
            use(*f, "normal map", f->why + ", and its texels are a normal map");
        }
    }
    if (m_normal && report(*m_normal).role.empty()) {
        Result<Image> image = load(*m_normal);
        use(*m_normal, "normal map", m_normal->why);
        if (image) {
            const ImageTraits t = imageTraits(*image);
            if (!t.normalLike)
                m_out.notes.push_back(fileName(m_normal->path) +
                                      " is named as a normal map, but its texels are not unit "
                                      "vectors around +Z (mean length " +
                                      fixed2(t.meanLength) + ", mean z " + fixed2(t.meanZ) +
                                      "): used as named; check the preview.");
        }
    }
}

void Importer::chooseHeight() {
    std::vector<const SetFile*> heights = named(MapRole::Height);
    for (const SetFile* f : named(MapRole::Depth))
        heights.push_back(f);
    m_height = pick(heights, nullptr);
    if (m_height) {
        m_depthByName = m_height->role == MapRole::Depth;
        use(*m_height, "height map", m_height->why);
    }
    // A grey bump map is a height map where there is no other.
    for (const SetFile* f : named(MapRole::Bump)) {
        if (!report(*f).why.empty())
            continue; // a normal map, decided above
        if (!m_height) {
            m_height = f;
            use(*f, "height map", f->why + " (a bump map is a height map)");
        } else {
            skip(*f, "a bump map: the height map " + fileName(m_height->path) + " is used");
        }
    }
    // A grey file named after the set is its relief when it follows the normal map's slopes.
    if (m_height || !m_normal)
        return;
    Result<Image> normals = load(*m_normal);
    for (const SetFile* f : m_untagged) {
        Result<Image> image = load(*f);
        if (!normals || !image || !report(*f).role.empty() || !imageTraits(*image).grey)
            continue;
        Result<ReliefReading> reading = px::readRelief(channelField(*image, 0), *normals,
                                                       WrapMode::Repeat, false, m_normal->path);
        if (reading && reading->fromData && reading->score >= kUntaggedHeightAgreement) {
            m_height = f;
            use(*f, "height map",
                f->why + ", grey, and its slopes follow the normal map's (agreement " +
                    fixed2(reading->score) + ")");
            return;
        }
    }
}

// A normal map's alpha: the height of the classic parallax packing (Cube 2 / Tesseract _nm,
// DarkPlaces _norm) when it follows the normal map's slopes; gloss or a mask when not.
void Importer::readAlpha() {
    if (!m_normal)
        return;
    Result<Image> image = load(*m_normal);
    if (!image || image->channels < 4 || !imageTraits(*image).alphaVaries)
        return;
    const bool glossByName = m_normal->role == MapRole::NormalGloss;
    Result<ReliefReading> reading =
        px::readRelief(channelField(*image, 3), *image, WrapMode::Repeat, false, m_normal->path);
    const bool agrees = reading && reading->fromData && reading->score >= kHeightAgreement;
    const std::string r = reading ? fixed2(reading->score) : "n/a";
    ImportedFile& line = report(*m_normal);
    if (agrees && !m_height) {
        m_heightInAlpha = true;
        m_alphaReading = *reading;
        line.role = "normal map, height in alpha";
        line.why += "; its alpha follows the normal map's slopes (agreement " + r + ")";
    } else if (agrees) {
        line.why += "; its alpha is a height map too (agreement " + r + "), " +
                    fileName(m_height->path) + " is used";
    } else if (glossByName) {
        line.role = "normal map, gloss in alpha";
        line.why += "; its alpha does not follow the slopes (agreement " + r +
                    "): gloss, as CryEngine's _ddna holds";
    } else {
        line.why += "; its alpha does not follow the slopes (agreement " + r +
                    "): not a height map (gloss or a mask?), not used";
    }
}

void Importer::readRelief() {
    Material& m = m_out.material;
    const Image* normals = nullptr;
    if (m_normal) {
        if (auto it = m_images.find(m_normal->path); it != m_images.end())
            normals = &it->second;
    }
    if (m_heightInAlpha && m_normal) { // the alpha is the normal map's
        m.maps.height = absolutePath(m_normal->path);
        m.heightChannel = HeightChannel::Alpha;
        m_out.relief = m_alphaReading;
        m_out.relief.summary = "Height in the normal map's alpha: " + m_alphaReading.summary;
    } else if (m_height) {
        m.maps.height = absolutePath(m_height->path);
        m.heightChannel = HeightChannel::Red;
        m_out.relief = reliefByName(m_depthByName, m_height->path);
        HeightLoadOptions raw;
        raw.allowLarge = m_options.allowLarge;
        // A float map in its own units (signed, or any range) is read by its range, recorded.
        Result<FittedHeight> fitted = loadHeightFieldFitted(m_height->path, raw);
        if (!fitted) {
            m_problems += (m_problems.empty() ? "" : "\n") + fitted.error().message;
            return;
        }
        m.heightRange = fitted->range;
        if (m.heightRange)
            m_out.notes.push_back(fileName(m_height->path) + " holds heights from " +
                                  fileValue(m.heightRange->lo) + " to " +
                                  fileValue(m.heightRange->hi) +
                                  " (a float map in its own units): read as stored, that range "
                                  "as 0 to 1; the material records it, and the height scale is "
                                  "the depth of the whole range.");
        // Grey files named after the set are albedo unless a normal map says they are relief.
        if (normals) {
            Result<ReliefReading> reading =
                px::readRelief(fitted->field, *normals, m.wrap, m_depthByName, m_normal->path);
            if (reading)
                m_out.relief = std::move(*reading);
        }
    }
    m.heightIsDepth = m_out.relief.depth;
    if (!m_normal)
        return;
    // Green: the data where a height map tells it, else the name, else the curl of the slopes.
    const GreenHint hint = m_normal->green;
    const NormalGreen named =
        hint == GreenHint::DirectX ? NormalGreen::DirectX : NormalGreen::OpenGL;
    if ((m_height || m_heightInAlpha) && m_out.relief.fromData) {
        m.normalGreen = m_out.relief.green;
        if (hint != GreenHint::None && named != m.normalGreen)
            m_out.notes.push_back(fileName(m_normal->path) + " is named " +
                                  (named == NormalGreen::OpenGL ? "OpenGL" : "DirectX") +
                                  ", but its slopes follow the height map with " +
                                  greenName(m.normalGreen) + " green: read as the data says.");
    } else if (hint != GreenHint::None) {
        m.normalGreen = named;
        m_out.notes.push_back("The normal map's green is " + std::string(greenName(named)) +
                              " by its name.");
    } else if (normals) {
        const GreenFromCurl curl = greenFromCurl(*normals);
        m.normalGreen = curl.green;
        m_out.notes.push_back(
            curl.told()
                ? "The normal map's green is " + std::string(greenName(curl.green)) +
                      ": only that reading makes its slopes one surface's (" +
                      fixed2(curl.clarity) + " times less curl)."
                : "The normal map's green could not be told from its texels: read as " +
                      std::string(greenName(curl.green)) + "; flip it if the light looks wrong.");
    }
}

void Importer::chooseSurface() {
    Material& m = m_out.material;
    // Colour: a tagged file, else one named after the set.
    m_albedo = pick(named(MapRole::Albedo), nullptr);
    if (m_albedo)
        use(*m_albedo, "albedo", m_albedo->why);
    for (const SetFile* f : m_untagged) {
        if (!report(*f).role.empty() || !report(*f).why.empty())
            continue;
        if (!m_albedo) {
            m_albedo = f;
            use(*f, "albedo", f->why);
        } else {
            skip(*f, f->why + ": " + fileName(m_albedo->path) + " is the albedo");
        }
    }
    if (m_albedo)
        m.maps.albedo = absolutePath(m_albedo->path);
    if (m_normal)
        m.maps.normal = absolutePath(m_normal->path);

    // Occlusion, roughness, metallic: files of their own first, then packed ones by channel.
    struct Packed {
        MapRole role;
        std::optional<HeightChannel> ao, roughness, metallic;
        bool gloss;
        const char* layout;
    };
    const Packed packings[] = {
        {MapRole::Orm, HeightChannel::Red, HeightChannel::Green, HeightChannel::Blue, false, "ORM"},
        {MapRole::MaskMap, HeightChannel::Green, HeightChannel::Alpha, HeightChannel::Red, true,
         "mask map"},
        {MapRole::MetallicSmoothness, std::nullopt, HeightChannel::Alpha, HeightChannel::Red, true,
         "metallic-smoothness map"},
    };
    const SetFile* ao = pick(named(MapRole::Ao), nullptr);
    const SetFile* roughness = pick(named(MapRole::Roughness), nullptr);
    const SetFile* gloss = pick(named(MapRole::Gloss), nullptr);
    const SetFile* metallic = pick(named(MapRole::Metallic), nullptr);
    if (ao)
        use(*ao, "occlusion map", ao->why);
    if (metallic)
        use(*metallic, "metallic map", metallic->why);
    if (roughness)
        use(*roughness, "roughness map", roughness->why);
    if (gloss && !roughness) {
        use(*gloss, "roughness map, from gloss (1 - gloss)", gloss->why);
        m.surface.gloss = true;
    } else if (gloss) {
        skip(*gloss, "a gloss map: the roughness map " + fileName(roughness->path) + " is used");
    }
    const SetFile* roughFile = roughness ? roughness : gloss;
    for (const Packed& p : packings) {
        const SetFile* file = pick(named(p.role), nullptr);
        if (!file)
            continue;
        std::string channels;
        Result<Image> image = load(*file);
        const int present = image ? image->channels : 0;
        auto take = [&](const SetFile*& slot, std::optional<HeightChannel> channel,
                        HeightChannel& into, const char* what) {
            // A grey file named as packed holds one map only: its red.
            if (slot || !channel || static_cast<int>(*channel) >= present)
                return;
            slot = file;
            into = *channel;
            channels += std::string(channels.empty() ? "" : ", ") + what + " from " +
                        std::string(toString(*channel));
        };
        take(ao, p.ao, m.surface.ao, "occlusion");
        if (!roughFile && p.roughness) {
            m.surface.gloss = p.gloss;
            take(roughFile, p.roughness, m.surface.roughness,
                 p.gloss ? "roughness = 1 - smoothness" : "roughness");
        }
        take(metallic, p.metallic, m.surface.metallic, "metallic");
        if (channels.empty())
            skip(*file, std::string("a packed ") + p.layout + ": its maps come from other files");
        else
            use(*file, std::string(p.layout) + " (" + channels + ")", file->why);
    }
    // CryEngine's _ddna: gloss in the normal map's alpha.
    if (!roughFile && m_normal && m_normal->role == MapRole::NormalGloss && !m_heightInAlpha) {
        Result<Image> image = load(*m_normal);
        if (image && image->channels >= 4) {
            roughFile = m_normal;
            m.surface.roughness = HeightChannel::Alpha;
            m.surface.gloss = true;
            report(*m_normal).role += " (roughness = 1 - alpha)";
        }
    }
    if (ao)
        m.maps.ao = absolutePath(ao->path);
    if (roughFile)
        m.maps.roughness = absolutePath(roughFile->path);
    if (metallic)
        m.maps.metallic = absolutePath(metallic->path);
    if (roughFile || metallic) {
        m.lighting = LightingModel::MetallicRoughness;
        m_out.notes.push_back("Lighting: metallic-roughness (the set has roughness or metallic "
                              "maps).");
    }
    // Specular: no map of the preview's, but engines read one (glTF, Unreal): kept for export.
    if (const SetFile* f = pick(named(MapRole::Specular), nullptr)) {
        use(*f, "specular map", f->why + "; kept for the exports that read one, not drawn here");
        m.maps.specular = absolutePath(f->path);
    }
    for (MapRole cone : {MapRole::Cone, MapRole::RelaxedCone}) {
        if (const SetFile* f = pick(named(cone), nullptr)) {
            use(*f, std::string(roleName(cone)), f->why);
            (cone == MapRole::Cone ? m.maps.cone : m.maps.relaxedCone) = absolutePath(f->path);
        }
    }
}

void Importer::reportTheRest() {
    for (const SetFile& f : m_plan.files) {
        ImportedFile& r = report(f);
        if (r.used || !r.why.empty())
            continue;
        if (f.role == MapRole::Unused)
            r.why = "recognised (" + f.why + "), not a map a parallax material uses";
        else
            r.why = "not used (" + f.why + ")";
    }
}

Result<ImportedSet> Importer::run(const Material& base) {
    Material& m = m_out.material;
    m = base;
    m.name = m_plan.name;
    m.maps = {};
    m.surface = {};
    m.heightChannel = HeightChannel::Red;
    m.heightRange.reset();
    m.heightDerivedFrom.clear();
    m_out.plan = m_plan;
    chooseNormal();
    chooseHeight();
    readAlpha();
    chooseSurface();
    readRelief();
    reportTheRest();
    if (!m_problems.empty())
        return Error{m_problems};
    if (!m_height && !m_heightInAlpha && !m_normal) {
        m_out.heightMissing = true;
        std::string text = "The texture set " + m_plan.name +
                           " has no height map and no normal map: nothing gives it relief.";
        for (const std::string& line : importSummary(m_out))
            text += "\n  " + line;
        return Error{text};
    }
    m.normalSource = m_normal                              ? NormalSource::Map
                     : m.normalSource == NormalSource::Map ? NormalSource::HeightCentral
                                                           : m.normalSource;
    if (m_normal)
        m_out.notes.push_back("The normal map shades the surface (Normals: map).");
    m_out.heightMissing = !m_height && !m_heightInAlpha;
    if (m_out.heightMissing)
        m_out.relief.summary = "No height map: the set has only a normal map, " +
                               fileName(m_normal->path) +
                               ". A height map can be made from it (integrated from its slopes).";

    Result<MaterialAssets> loaded =
        loadMaterialAssets(m, m.maps.height, mapsPresent(m.maps), m_options);
    if (!loaded)
        return loaded.error();
    m_out.assets = std::move(*loaded);
    return std::move(m_out);
}

} // namespace

Result<ImportedSet> importTextureSet(const TextureSetPlan& plan, const Material& base,
                                     const AssetLoadOptions& options) {
    Importer importer(plan, options);
    return importer.run(base);
}

Status deriveHeight(ImportedSet& set, const BakeControl& control) {
    if (!set.heightMissing || set.assets.normal.empty())
        return Error{"the texture set " + set.plan.name + " has a height map already"};
    HeightFromNormalsOptions options;
    options.green = set.material.normalGreen;
    Result<DerivedHeight> derived = heightFromNormals(set.assets.normal, options, control);
    if (!derived)
        return fileError(set.material.maps.normal, derived.error().message);
    Material& m = set.material;
    const std::string normal = fileName(m.maps.normal);
    m.maps.height.clear(); // made here: no file until the material is saved
    m.heightChannel = HeightChannel::Red;
    m.heightIsDepth = false;
    m.heightRange.reset();
    m.heightScale = derived->heightScale;
    m.heightDerivedFrom = normal;
    set.assets.height = std::move(derived->height);
    set.heightMissing = false;
    set.relief = {};
    set.relief.summary = "Height map derived from the normal map " + normal +
                         " (least-squares integration of its slopes, " +
                         (derived->periodic ? "tiling" : "free") + " borders; " +
                         fixed2(100.0 * derived->misfit) +
                         "% of the slopes left unexplained): a guess at the relief, not a "
                         "measured one. Height scale " +
                         shortNumber(derived->heightScale) + " matches the normal map's slopes.";
    // The mean slope is no relief: said, so a user who wanted a ramp knows where it went.
    if (std::max(std::abs(derived->tiltU), std::abs(derived->tiltV)) > 0.01 * derived->heightScale)
        set.relief.summary += " Removed from it: the normal map's mean slope (a tilt of " +
                              shortNumber(derived->tiltU) + " across the tile in u, " +
                              shortNumber(derived->tiltV) +
                              " in v, in uv units: the bias of its red and green), which would "
                              "have been a ramp across the tile.";
    set.notes.push_back("The height map is derived from " + normal +
                        ", marked so in the "
                        "material and in exports.");
    return success();
}

std::vector<std::string> importSummary(const ImportedSet& set) {
    std::vector<std::string> lines;
    lines.push_back("Texture set " + set.plan.name + " imported as the material " +
                    set.material.name + ":");
    const Material& m = set.material;
    // Relief first, then colour, then the rest, as a reader looks for them.
    std::vector<const ImportedFile*> used;
    for (const ImportedFile& f : set.files) {
        if (f.used)
            used.push_back(&f);
    }
    auto order = [](const std::string& role) {
        return role.starts_with("height")   ? 0
               : role.starts_with("normal") ? 1
               : role.starts_with("albedo") ? 2
                                            : 3;
    };
    std::stable_sort(used.begin(), used.end(), [&](const ImportedFile* a, const ImportedFile* b) {
        return order(a->role) < order(b->role);
    });
    for (const ImportedFile* pf : used) {
        const ImportedFile& f = *pf;
        std::string line = "  " + f.role + ": " + fileName(f.path) + " (" + f.why + ")";
        if (absolutePath(f.path) == m.maps.height)
            line += m.heightIsDepth ? ", read as depth (white = deep)"
                                    : ", read as height (white = high)";
        if (absolutePath(f.path) == m.maps.normal)
            line += std::string(", green ") + greenName(m.normalGreen);
        lines.push_back(line);
    }
    if (!m.heightDerivedFrom.empty())
        lines.push_back("  height map: derived from " + m.heightDerivedFrom);
    if (!set.relief.summary.empty())
        lines.push_back(set.relief.summary);
    lines.insert(lines.end(), set.notes.begin(), set.notes.end());
    for (const ImportedFile& f : set.files) {
        if (!f.used)
            lines.push_back("Not used: " + fileName(f.path) + " (" + f.why + ")");
    }
    // Other sets' files one a line while they are few; in a library folder (hundreds of sets)
    // they are one line, so the set's own report stays readable.
    constexpr std::size_t kListedOthers = 8;
    const std::string otherSet = "belongs to the set ";
    std::vector<const SkippedFile*> others;
    std::set<std::string> otherSets;
    for (const SkippedFile& f : set.plan.ignored) {
        if (f.why.starts_with(otherSet)) {
            others.push_back(&f);
            otherSets.insert(f.why.substr(otherSet.size()));
        }
    }
    const bool summarised = others.size() > kListedOthers;
    for (const SkippedFile& f : set.plan.ignored) {
        if (!summarised || !f.why.starts_with(otherSet))
            lines.push_back("Ignored: " + fileName(f.path) + " (" + f.why + ")");
    }
    if (summarised) {
        std::string names;
        for (auto it = otherSets.begin();
             it != otherSets.end() && std::distance(otherSets.begin(), it) < 3; ++it)
            names += (names.empty() ? "" : ", ") + *it;
        lines.push_back("Ignored: " + std::to_string(others.size()) + " files of " +
                        std::to_string(otherSets.size()) + " other texture sets (" + names +
                        (otherSets.size() > 3 ? ", ..." : "") + "), each imported on its own");
    }
    return lines;
}

} // namespace px
