#pragma once
// Writing a numbered set of images as one: a turntable's frames. Each frame is made on demand,
// staged under a temporary name beside its target and renamed only once every frame is written,
// so a failure (or a cancel) leaves the previous set as it was and nothing behind.

#include "parallax/Result.h"
#include "parallax/image/ImageFile.h"

#include <functional>
#include <string>
#include <vector>

namespace px {

// OUT.png -> OUT-000.png, OUT-001.png, ... (at least three digits, more when `count` needs them).
std::vector<std::string> numberedFiles(const std::string& out, int count);

// Writes frame(i) to files[i] for every i. Errors name the target file, never a temporary.
Status writeImageSet(const std::vector<std::string>& files,
                     const std::function<Result<Image>(int)>& frame,
                     const ImageWriteOptions& options);

} // namespace px
