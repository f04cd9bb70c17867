#include "parallax/material/TextureSet.h"

#include "parallax/io/Inputs.h"
#include "parallax/material/MapFileName.h"
#include "parallax/material/MapKind.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <sys/stat.h>

namespace px {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

std::string folderNameOf(const std::string& path) {
    return fs::absolute(fs::path(path)).parent_path().filename().string();
}

// Game and engine formats a set may ship in that the image reader does not take.
bool unreadImageFormat(const std::string& path) {
    const std::string ext = lower(fs::path(path).extension().string());
    for (const char* known : {".dds", ".ktx", ".ktx2", ".webp", ".psd", ".gif", ".vtf"}) {
        if (ext == known)
            return true;
    }
    return false;
}

// What a path that is there but is no regular file is ("a FIFO (named pipe)", "a symbolic link
// to nothing that exists", "a folder"); empty for a regular file or a path that is not there (a
// list of names the caller made up).
std::string notARegularFile(const std::string& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0)
        return {};
    if (S_ISLNK(st.st_mode)) {
        struct stat target {};
        if (::stat(path.c_str(), &target) != 0)
            return "a symbolic link to nothing that exists";
        st = target;
    }
    return S_ISREG(st.st_mode) ? std::string() : fileKind(st.st_mode);
}

// One file as the grouping sees it.
struct Entry {
    std::string path;
    bool image = false;
    std::vector<NameReading> readings; // readMapFileName's: tagged first, the plain one last
    const NameReading* chosen = nullptr;
    std::string set; // the set it belongs to, as spelled; empty: none
    std::string why;
};

std::string setOf(const NameReading& r, const std::string& path) {
    return r.stem.empty() ? folderNameOf(path) : r.stem;
}

// "a" in "crate1a" beside the set "crate1": one letter, glued or after a separator.
bool isVariantOf(const std::string& stem, const std::string& set) {
    const std::string s = lower(stem), base = lower(set);
    if (s.size() <= base.size() || !s.starts_with(base))
        return false;
    std::string rest = s.substr(base.size());
    if (rest.size() == 2 && (rest[0] == '_' || rest[0] == '-' || rest[0] == ' '))
        rest = rest.substr(1);
    return rest.size() == 1 && std::isalpha(static_cast<unsigned char>(rest[0]));
}

struct Grouping {
    std::vector<Entry> entries;
    std::map<std::string, std::string> sets; // lower-case name -> name as first spelled
};

Grouping group(const std::vector<std::string>& files) {
    Grouping g;
    for (const std::string& file : files) {
        Entry e;
        e.path = file;
        // A FIFO, socket, device, dangling link or folder named like a map is said, never read.
        const std::string kind = notARegularFile(file);
        e.image = kind.empty() && isImageFileName(file);
        if (e.image)
            e.readings = readMapFileName(file);
        if (!kind.empty())
            e.why = kind + ", not a regular file: not read";
        g.entries.push_back(std::move(e));
    }
    // The names that spell each stem by a firm reading (a separated tag, or no tag) or a glued
    // one: a glued tag needs another file with its stem. One name in two formats (stones.png and
    // stones.jpg, a download's BMP and PNG) is one file, not a sibling of itself.
    std::map<std::string, std::set<std::string>> firm, glued;
    for (const Entry& e : g.entries) {
        const std::string fileName = lower(fs::path(e.path).stem().string());
        for (const NameReading& r : e.readings)
            (r.glued ? glued : firm)[lower(setOf(r, e.path))].insert(fileName);
    }
    for (Entry& e : g.entries) {
        for (const NameReading& r : e.readings) {
            if (r.tag && r.glued) {
                // Its own plain reading spells another stem, so any firm name is a sibling's.
                const std::string key = lower(setOf(r, e.path));
                if (firm[key].empty() && glued[key].size() < 2)
                    continue;
            }
            e.chosen = &r;
            break;
        }
    }
    for (Entry& e : g.entries) {
        if (!e.chosen || !e.chosen->tag || e.chosen->tag->role == MapRole::Unused)
            continue;
        const std::string name = setOf(*e.chosen, e.path);
        g.sets.try_emplace(lower(name), name);
    }
    for (Entry& e : g.entries) {
        if (!e.image && !e.why.empty())
            continue; // not a regular file
        if (!e.image) {
            e.why = unreadImageFormat(e.path) ? "an image format not read here (" +
                                                    lower(fs::path(e.path).extension().string()) +
                                                    "): convert it to PNG, TGA, TIFF or EXR"
                                              : "not an image file";
            continue;
        }
        const NameReading& r = *e.chosen;
        const std::string name = setOf(r, e.path);
        const auto found = g.sets.find(lower(name));
        if (r.tag) {
            if (found != g.sets.end())
                e.set = found->second;
            else
                e.why = "tag " + r.tagText + " (" +
                        std::string(r.tag->what.empty() ? roleName(r.tag->role) : r.tag->what) +
                        "), of no texture set here";
            continue;
        }
        if (found != g.sets.end()) {
            e.set = found->second;
            continue;
        }
        for (const auto& [key, set] : g.sets) {
            if (isVariantOf(r.stem, set)) {
                e.set = set;
                break;
            }
        }
        if (e.set.empty())
            e.why = "no map tag (_albedo, _disp, _normal, ...), and not named after a set here";
    }
    return g;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names)
        text += (text.empty() ? "" : ", ") + name;
    return text;
}

std::string fileName(const std::string& path) {
    return fs::path(path).filename().string();
}

} // namespace

std::vector<std::string> textureSetNames(const std::vector<std::string>& files) {
    std::vector<std::string> names;
    for (const auto& [key, name] : group(files).sets)
        names.push_back(name);
    return names; // sorted by their lower-case keys
}

Result<TextureSetPlan> planTextureSet(const std::vector<std::string>& files,
                                      const std::string& source, const std::string& set) {
    std::vector<std::string> sorted = files;
    std::sort(sorted.begin(), sorted.end());
    const Grouping g = group(sorted);
    std::vector<std::string> names;
    for (const auto& [key, name] : g.sets)
        names.push_back(name);
    if (names.empty()) {
        std::string report = source + ": no texture set recognised (no file named as a height, "
                                      "normal or colour map of a set)";
        for (const Entry& e : g.entries)
            report += "\n  " + fileName(e.path) + ": " + e.why;
        if (g.entries.empty())
            report += "\n  (no files)";
        return Error{report};
    }
    std::string chosen;
    if (set.empty()) {
        if (names.size() > 1)
            return fileError(source, "holds " + std::to_string(names.size()) + " texture sets (" +
                                         joined(names) + "): choose one, they are never mixed");
        chosen = names.front();
    } else {
        const auto it = g.sets.find(lower(set));
        if (it == g.sets.end())
            return fileError(source, "holds no texture set named '" + set + "' (it holds " +
                                         joined(names) + ")");
        chosen = it->second;
    }

    TextureSetPlan plan;
    plan.name = chosen;
    for (const Entry& e : g.entries) {
        if (e.set.empty()) {
            plan.ignored.push_back({e.path, e.why});
        } else if (lower(e.set) != lower(chosen)) {
            plan.ignored.push_back({e.path, "belongs to the set " + e.set});
        } else if (e.chosen->tag) {
            const NameReading& r = *e.chosen;
            plan.files.push_back(
                {e.path, r.tag->role, r.green,
                 std::string(r.glued ? "tag glued to the name: " : "tag ") + r.tagText});
        } else {
            plan.files.push_back({e.path, std::nullopt, GreenHint::None,
                                  lower(e.chosen->stem) == lower(chosen)
                                      ? "named after the set, no tag"
                                      : "the set's name and a variant letter, no tag"});
        }
    }
    return plan;
}

Result<std::vector<std::string>> folderFiles(const std::string& folder) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return fileError(folder, "not a folder");
    std::vector<std::string> files;
    std::vector<fs::path> folders;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.starts_with("."))
            continue;
        // A folder named like an image is listed (and reported), not entered; anything else
        // that is no regular file (a FIFO, a socket, a dangling link) is listed to be reported.
        if (it->is_directory(ec) && !isImageFileName(name))
            folders.push_back(it->path());
        else
            files.push_back(it->path().string());
    }
    if (ec)
        return fileError(folder, "cannot read the folder (" + ec.message() + ")");
    // Downloads often keep the maps one folder down (Poly Haven's textures/ beside the .blend).
    for (const fs::path& sub : folders) {
        for (fs::directory_iterator it(sub, ec), end; !ec && it != end; it.increment(ec)) {
            const std::string name = it->path().filename().string();
            if (!name.starts_with(".") && (!it->is_directory(ec) || isImageFileName(name)))
                files.push_back(it->path().string());
        }
        if (ec)
            return fileError(sub.string(), "cannot read the folder (" + ec.message() + ")");
    }
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace px
