#include "parallax/export/BatchScan.h"

#include <filesystem>
#include <string_view>

namespace px {

namespace {

constexpr std::string_view kOtherSet = "belongs to the set ";

} // namespace

Result<BatchFolder> scanBatchFolder(const std::string& folder) {
    Result<std::vector<std::string>> files = folderFiles(folder);
    if (!files)
        return files.error();
    BatchFolder out;
    for (const std::string& name : textureSetNames(*files)) {
        Result<TextureSetPlan> plan = planTextureSet(*files, folder, name);
        if (!plan)
            return plan.error();
        if (out.items.empty()) { // every plan ignores the same files of no set
            for (const SkippedFile& f : plan->ignored) {
                if (!f.why.starts_with(kOtherSet))
                    out.unassigned.push_back(f);
            }
        }
        out.items.push_back({plan->name, std::move(*plan)});
    }
    if (out.items.empty()) {
        Result<TextureSetPlan> none = planTextureSet(*files, folder); // the per-file report
        return none ? Error{folder + ": no texture set recognised"} : none.error();
    }
    return out;
}

Result<ImportedSet> importBatchItem(const BatchItem& item, const Material& preset,
                                    const AssetLoadOptions& options) {
    Result<ImportedSet> set = importTextureSet(item.plan, preset, options);
    if (!set)
        return set.error();
    if (set->heightMissing)
        return Error{"the set " + item.name + " has only a normal map (" +
                     std::filesystem::path(set->material.maps.normal).filename().string() +
                     "), no height map to export; `parallax-cli import --derive-height` makes "
                     "one from it"};
    return set;
}

} // namespace px
