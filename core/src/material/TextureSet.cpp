#include "parallax/material/TextureSet.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>

namespace px {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

bool sameName(const std::string& a, const std::string& b) {
    return lower(a) == lower(b);
}

std::string fileName(const std::string& path) {
    return fs::path(path).filename().string();
}

// A file named only by its suffix ("disp.png") belongs to the set named after its folder.
std::string setNameOf(const SuffixMatch& match, const std::string& path) {
    if (!match.setName.empty())
        return match.setName;
    return fs::absolute(fs::path(path)).parent_path().filename().string();
}

std::optional<SuffixMatch> roleOf(const std::string& path) {
    return isImageFileName(path) ? mapKindFromFileName(path) : std::nullopt;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names)
        text += (text.empty() ? "" : ", ") + name;
    return text;
}

void assign(TextureSetPlan& plan, SetFile file) {
    if (const SetFile* first = plan.find(file.kind)) {
        plan.duplicates.push_back({file.path, "a second " +
                                                  lower(std::string(mapTitle(file.kind))) +
                                                  " map: " + fileName(first->path) + " is used"});
        return;
    }
    plan.assigned.push_back(std::move(file));
}

} // namespace

const SetFile* TextureSetPlan::find(MapKind kind) const {
    const auto it = std::find_if(assigned.begin(), assigned.end(),
                                 [kind](const SetFile& f) { return f.kind == kind; });
    return it == assigned.end() ? nullptr : &*it;
}

std::vector<std::string> textureSetNames(const std::vector<std::string>& files) {
    std::vector<std::string> names;
    for (const std::string& file : files) {
        if (const std::optional<SuffixMatch> match = roleOf(file)) {
            const std::string name = setNameOf(*match, file);
            if (std::none_of(names.begin(), names.end(),
                             [&](const std::string& n) { return sameName(n, name); }))
                names.push_back(name);
        }
    }
    std::sort(names.begin(), names.end(),
              [](const std::string& a, const std::string& b) { return lower(a) < lower(b); });
    return names;
}

Result<TextureSetPlan> planTextureSet(const std::vector<std::string>& files,
                                      const std::string& source, const std::string& set) {
    const std::vector<std::string> names = textureSetNames(files);
    if (names.empty())
        return fileError(source, "no image whose name ends in a map suffix (_albedo, _height, "
                                 "_disp, _normal, ...)");
    std::string chosen;
    if (set.empty()) {
        if (names.size() > 1)
            return fileError(source, "holds " + std::to_string(names.size()) + " texture sets (" +
                                         joined(names) + "): choose one, they are never mixed");
        chosen = names.front();
    } else {
        const auto it = std::find_if(names.begin(), names.end(),
                                     [&](const std::string& n) { return sameName(n, set); });
        if (it == names.end())
            return fileError(source, "holds no texture set named '" + set + "' (it holds " +
                                         joined(names) + ")");
        chosen = *it;
    }

    std::vector<std::string> sorted = files;
    std::sort(sorted.begin(), sorted.end());
    TextureSetPlan plan;
    plan.name = chosen;
    std::vector<std::string> albedoByName;
    for (const std::string& file : sorted) {
        const std::string stem = fs::path(file).stem().string();
        if (!isImageFileName(file)) {
            plan.ignored.push_back({file, "not an image file"});
        } else if (const std::optional<SuffixMatch> match = mapKindFromFileName(file)) {
            const std::string owner = setNameOf(*match, file);
            if (!sameName(owner, chosen))
                plan.ignored.push_back({file, "belongs to the set " + owner});
            else
                assign(plan, {match->kind, file, match->depth,
                              "suffix '" + stem.substr(match->setName.size()) + "'"});
        } else if (sameName(stem, chosen)) {
            albedoByName.push_back(file); // after the suffixed files: "_albedo" wins
        } else if (std::any_of(names.begin(), names.end(),
                               [&](const std::string& n) { return sameName(n, stem); })) {
            plan.ignored.push_back({file, "the albedo of the set " + stem});
        } else {
            plan.ignored.push_back(
                {file,
                 "no map suffix like _albedo, _disp or _normal, and not named after the set"});
        }
    }
    for (const std::string& file : albedoByName)
        assign(plan, {MapKind::Albedo, file, false, "named after the set, no suffix"});
    // The height map first: cone maps are checked against it.
    std::stable_sort(plan.assigned.begin(), plan.assigned.end(),
                     [](const SetFile& a, const SetFile& b) {
                         return a.kind == MapKind::Height && b.kind != MapKind::Height;
                     });
    return plan;
}

Result<std::vector<std::string>> folderFiles(const std::string& folder) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return fileError(folder, "not a folder");
    std::vector<std::string> files;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->is_regular_file(ec))
            files.push_back(it->path().string());
    }
    if (ec)
        return fileError(folder, "cannot read the folder (" + ec.message() + ")");
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace px
