#include "parallax/image/ImageSet.h"

#include "parallax/io/AtomicWrite.h"

#include <algorithm>
#include <filesystem>

namespace px {

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
    std::vector<std::filesystem::path> staged;
    auto discard = [&staged] {
        for (const std::filesystem::path& p : staged) {
            std::error_code ignored;
            std::filesystem::remove(p, ignored);
        }
    };
    for (std::size_t i = 0; i < files.size(); ++i) {
        Result<Image> image = frame(static_cast<int>(i));
        if (!image) {
            discard();
            return image.error();
        }
        // The temporary keeps the extension: the writer picks the format from it.
        std::filesystem::path temp = temporaryPathFor(files[i]);
        temp += std::filesystem::path(files[i]).extension();
        if (Status s = writeImage(temp.string(), *image, options); !s) {
            discard();
            std::string message = s.error().message;
            const std::string name = temp.string();
            for (std::size_t at = message.find(name); at != std::string::npos;
                 at = message.find(name))
                message.replace(at, name.size(), files[i]);
            return Error{message, s.error().kind, files[i]};
        }
        staged.push_back(temp);
    }
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (Status s = commitTemporary(staged[i], files[i]); !s) {
            staged.erase(staged.begin(), staged.begin() + static_cast<std::ptrdiff_t>(i + 1));
            discard();
            return s;
        }
    }
    return success();
}

} // namespace px
