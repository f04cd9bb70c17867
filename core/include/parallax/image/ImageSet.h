#pragma once
// Writing a numbered set of images as one: a turntable's frames. Each frame is made on demand and
// staged in a private folder beside the first (StagedSet.h); the frames are moved into place only
// once every one is written, so a failure, a cancel or Ctrl-C leaves the previous set as it was and
// nothing behind; a kill during the moves leaves whole frames, old or new, never half a file. One
// writer at a time (OutputLock.h). Frames of an earlier, longer set past the new count are left as
// they were.

#include "parallax/Result.h"
#include "parallax/image/ImageFile.h"

#include <functional>
#include <string>
#include <vector>

namespace px {

// OUT.png -> OUT-000.png, OUT-001.png, ... (at least three digits, more when `count` needs them).
std::vector<std::string> numberedFiles(const std::string& out, int count);

// Writes frame(i) to files[i] (all in one folder) for every i. Errors name the target file, never
// a temporary; a target that is an input, a folder, a link or a special file is refused before
// the first frame is made.
Status writeImageSet(const std::vector<std::string>& files,
                     const std::function<Result<Image>(int)>& frame,
                     const ImageWriteOptions& options);

} // namespace px
