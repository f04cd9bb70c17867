#include "parallax/io/AtomicWrite.h"

#include <atomic>
#include <fstream>
#include <sstream>
#include <system_error>
#include <unistd.h>

namespace px {

std::filesystem::path temporaryPathFor(const std::filesystem::path& target) {
    static std::atomic<unsigned> counter{0};
    return target.parent_path() / ("." + target.filename().string() + ".tmp" +
                                   std::to_string(::getpid()) + "-" + std::to_string(counter++));
}

Status commitTemporary(const std::filesystem::path& temp, const std::filesystem::path& target) {
    std::error_code ec;
    std::filesystem::rename(temp, target, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        return fileError(target.string(), "cannot replace the file (" + ec.message() + ")");
    }
    return success();
}

Status writeTextFile(const std::string& path, std::string_view contents) {
    const std::filesystem::path target(path);
    const std::filesystem::path temp = temporaryPathFor(target);
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out)
            return fileError(path, "cannot create the file (is the folder there and writable?)");
        out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
        out.flush();
        if (!out) {
            out.close();
            std::error_code ignored;
            std::filesystem::remove(temp, ignored);
            return fileError(path, "writing failed (disk full?)");
        }
    }
    return commitTemporary(temp, target);
}

Result<std::string> readTextFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return fileError(path, "no such file");
    if (std::filesystem::is_directory(path, ec))
        return fileError(path, "is a folder, not a file");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return fileError(path, "cannot open the file for reading");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad())
        return fileError(path, "reading failed");
    return buffer.str();
}

} // namespace px
