#include "parallax/io/OutputCheck.h"

#include "parallax/io/AtomicWrite.h"
#include "parallax/io/OutputGate.h"

#include <cerrno>
#include <filesystem>
#include <system_error>
#include <unistd.h>

namespace px {

namespace fs = std::filesystem;

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code ec;
    if (fs::exists(a, ec) && fs::exists(b, ec)) {
        const bool same = fs::equivalent(a, b, ec); // device and inode: hard links too
        if (!ec)
            return same;
    }
    const fs::path ca = fs::weakly_canonical(a, ec);
    if (ec)
        return false;
    const fs::path cb = fs::weakly_canonical(b, ec);
    return !ec && ca == cb;
}

namespace {

Status checkOne(const NamedPath& out) {
    std::error_code ec;
    if (fs::is_directory(out.path, ec))
        return fileError(out.path, out.option + " is a folder; give a file name");
    const fs::path folder = fs::path(out.path).parent_path();
    const fs::path dir = folder.empty() ? fs::path(".") : folder;
    if (!fs::is_directory(dir, ec))
        return fileError(out.path, "cannot create the file: the folder " + folder.string() +
                                       " does not exist");
    // A FIFO, a device, a dangling link: before any work.
    if (Result<fs::path> target = outputTarget(out.path); !target)
        return target.error();
    if (::access(dir.c_str(), W_OK | X_OK) != 0)
        return fileError(out.path, "cannot create the file in " + dir.string() + " (" +
                                       systemReason(errno) + ")");
    return success();
}

} // namespace

Status checkOutputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const NamedPath& out = outputs[i];
        for (const NamedPath& in : inputs) {
            if (sameFile(out.path, in.path))
                return fileError(out.path, out.option + " names the same file as " + in.option +
                                               " " + in.path +
                                               ": refusing to overwrite an input; choose "
                                               "another output");
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (sameFile(out.path, outputs[j].path))
                return fileError(out.path, out.option + " names the same file as " +
                                               outputs[j].option + "; give each output its own");
        }
        if (Status s = checkOne(out); !s)
            return s;
    }
    return success();
}

} // namespace px
