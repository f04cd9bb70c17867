#include "parallax/image/ImageSet.h"

#include "parallax/io/AtomicWrite.h"
#include "parallax/io/OutputGate.h"
#include "parallax/io/OutputLock.h"
#include "parallax/io/StagedSet.h"

#include <algorithm>
#include <filesystem>

namespace px {

namespace fs = std::filesystem;

std::vector<std::string> numberedFiles(const std::string& out, int count) {
    const std::filesystem::path path(out);
    const std::string extension = path.has_extension() ? path.extension().string() : ".png";
    const std::string stem = (path.parent_path() / path.stem()).string();
    const int digits = std::max(3, static_cast<int>(std::to_string(std::max(count - 1, 0)).size()));
    std::vector<std::string> files;
    files.reserve(static_cast<std::size_t>(std::max(count, 0)));
    for (int i = 0; i < count; ++i) {
        std::string number = std::to_string(i);
        number.insert(0, static_cast<std::size_t>(digits) - number.size(), '0');
        files.push_back(stem + "-" + number + extension);
    }
    return files;
}

Status writeImageSet(const std::vector<std::string>& files,
                     const std::function<Result<Image>(int)>& frame,
                     const ImageWriteOptions& options) {
    if (files.empty())
        return success();
    // One writer of the set at a time; a killed run's stage is finished or removed first.
    const fs::path anchor(files.front());
    const fs::path folder = anchor.parent_path().empty() ? fs::path(".") : anchor.parent_path();
    Result<OutputLock> lock = OutputLock::take(anchor);
    if (!lock)
        return lock.error();
    std::vector<std::string> names;
    for (const std::string& file : files) {
        if (Status s = checkReplaceable(file); !s) // before any frame is made
            return s;
        names.push_back(fs::path(file).filename().string());
    }
    Result<StagedSet> stage = StagedSet::begin(folder, names.front());
    if (!stage)
        return stage.error();
    for (std::size_t i = 0; i < files.size(); ++i) {
        Result<Image> image = frame(static_cast<int>(i));
        if (!image)
            return image.error();
        const std::string staged = stage->pathFor(names[i]);
        if (Status s = writeImage(staged, *image, options); !s) {
            std::string message = s.error().message;
            for (std::size_t at = message.find(staged); at != std::string::npos;
                 at = message.find(staged))
                message.replace(at, staged.size(), files[i]);
            return Error{message, s.error().kind, files[i]};
        }
    }
    StagedSet::Update update; // frame by frame: any prefix is whole frames
    update.moves = names;
    update.commitPoint = "frames-commit";
    update.updatePoint = "frames-update";
    return stage->commit(update);
}

} // namespace px
