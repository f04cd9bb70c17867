#include "parallax/export/BatchScan.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>

namespace px {

namespace fs = std::filesystem;

namespace {

constexpr std::array<std::string_view, 5> kHeight{"_height", "_h", "_displacement", "_disp",
                                                  "_depth"};
constexpr std::array<std::string_view, 4> kAlbedo{"_albedo", "_diffuse", "_basecolor", "_color"};
constexpr std::array<std::string_view, 3> kNormal{"_normal", "_nrm", "_n"};
constexpr std::array<std::string_view, 2> kAo{"_ao", "_occlusion"};
constexpr std::array<std::string_view, 1> kRoughness{"_roughness"};
constexpr std::array<std::string_view, 1> kMetallic{"_metallic"};
constexpr std::array<std::string_view, 8> kImageExtensions{".png", ".tif",  ".tiff", ".exr",
                                                           ".jpg", ".jpeg", ".bmp",  ".tga"};

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

// The suffix of `stem` among `suffixes` (longest first wins: "_displacement" before "_disp").
template <std::size_t N>
std::string_view suffixOf(const std::string& lowerStem,
                          const std::array<std::string_view, N>& suffixes) {
    std::string_view best;
    for (std::string_view s : suffixes) {
        if (lowerStem.size() > s.size() && lowerStem.ends_with(s) && s.size() > best.size())
            best = s;
    }
    return best;
}

struct Entry {
    std::string path;
    std::string lowerStem;
};

// The first file (by name) whose stem is base + one of the suffixes (earlier suffixes first).
template <std::size_t N>
std::string findSibling(const std::vector<Entry>& files, const std::string& lowerBase,
                        const std::array<std::string_view, N>& suffixes) {
    for (std::string_view suffix : suffixes) {
        const std::string wanted = lowerBase + std::string(suffix);
        for (const Entry& file : files) {
            if (file.lowerStem == wanted)
                return file.path;
        }
    }
    return {};
}

} // namespace

std::span<const std::string_view> heightSuffixes() {
    return kHeight;
}

Result<std::vector<BatchItem>> scanBatchFolder(const std::string& folder, const Material& preset) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return fileError(folder, fs::exists(folder, ec) ? "is not a folder" : "no such folder");
    std::vector<Entry> files;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        if (!it->is_regular_file(ec))
            continue;
        const fs::path& p = it->path();
        const std::string ext = lower(p.extension().string());
        if (std::find(kImageExtensions.begin(), kImageExtensions.end(), ext) ==
            kImageExtensions.end())
            continue;
        files.push_back({fs::absolute(p).lexically_normal().string(), lower(p.stem().string())});
    }
    if (ec)
        return fileError(folder, "cannot list the folder (" + ec.message() + ")");
    std::sort(files.begin(), files.end(),
              [](const Entry& a, const Entry& b) { return a.path < b.path; });

    std::vector<BatchItem> items;
    std::map<std::string, std::string> seen; // lower base -> first height file
    for (const Entry& file : files) {
        const std::string_view suffix = suffixOf(file.lowerStem, kHeight);
        if (suffix.empty())
            continue;
        const std::string stem = fs::path(file.path).stem().string();
        BatchItem item;
        item.name = stem.substr(0, stem.size() - suffix.size());
        item.heightFile = file.path;
        const std::string lowerBase = lower(item.name);
        if (auto [it, inserted] = seen.emplace(lowerBase, file.path); !inserted) {
            item.problem = "a second height map for \"" + item.name + "\" (the first is " +
                           fs::path(it->second).filename().string() + ")";
            items.push_back(std::move(item));
            continue;
        }
        Material& m = item.material;
        m = preset;
        m.name = item.name;
        m.maps = {};
        m.maps.height = file.path;
        if (suffix == "_depth")
            m.heightIsDepth = true;
        m.maps.albedo = findSibling(files, lowerBase, kAlbedo);
        m.maps.normal = findSibling(files, lowerBase, kNormal);
        m.maps.ao = findSibling(files, lowerBase, kAo);
        m.maps.roughness = findSibling(files, lowerBase, kRoughness);
        m.maps.metallic = findSibling(files, lowerBase, kMetallic);
        items.push_back(std::move(item));
    }
    return items;
}

} // namespace px
