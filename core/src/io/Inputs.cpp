#include "parallax/io/Inputs.h"

#include "parallax/io/AtomicWrite.h"
#include "parallax/io/OutputGate.h"

#include <algorithm>
#include <cerrno>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace px {

namespace {

struct Recorded {
    FileIdentity identity;
    std::string path;
    std::string text; // the input's role, or the planned output's option
};

} // namespace

struct InputSession::Record {
    std::vector<Recorded> inputs;
    std::vector<Recorded> outputs;
    std::vector<FileIdentity> created;
};

namespace {

thread_local InputSession::Record* tCurrent = nullptr; // this thread's run

FileIdentity identityFrom(const struct stat& st) {
    return {static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino)};
}

Error sameAsInput(const std::string& output, std::string_view option, const InputEntry& input) {
    // An input of the command line is named by its option; one reached another way, by how.
    const bool named = input.role.starts_with("--");
    return fileError(output, std::string(option) + " names the same file as " +
                                 describeInput(input) + (named ? "" : ", which this run reads") +
                                 ": refusing to overwrite an input; choose another output");
}

// Records an input; refuses one that is a planned output. Without a session, records nothing.
Status recordInput(const FileIdentity& id, const std::string& path, std::string_view role) {
    if (tCurrent == nullptr)
        return success();
    InputSession::Record& r = *tCurrent;
    for (const Recorded& out : r.outputs) {
        if (out.identity == id)
            return sameAsInput(out.path, out.text, {path, std::string(role)});
    }
    const bool known = std::any_of(r.inputs.begin(), r.inputs.end(),
                                   [&](const Recorded& in) { return in.identity == id; });
    const bool ours = std::find(r.created.begin(), r.created.end(), id) != r.created.end();
    if (!known && !ours)
        r.inputs.push_back({id, path, std::string(role)});
    return success();
}

} // namespace

std::optional<FileIdentity> identityOf(const std::string& path) {
    struct stat st {};
    if (path.empty() || ::stat(path.c_str(), &st) != 0)
        return std::nullopt;
    return identityFrom(st);
}

std::string fileKind(unsigned mode) {
    switch (mode & S_IFMT) {
    case S_IFREG:
        return "a regular file";
    case S_IFDIR:
        return "a folder";
    case S_IFIFO:
        return "a FIFO (named pipe)";
    case S_IFCHR:
        return "a character device";
    case S_IFBLK:
        return "a block device";
    case S_IFSOCK:
        return "a socket";
    case S_IFLNK:
        return "a symbolic link";
    default:
        return "not a regular file";
    }
}

Result<InputFile> InputFile::open(const std::string& path, std::string_view role, bool record) {
    if (path.empty())
        return Error{"an empty file name"};
    // O_NONBLOCK: opening a FIFO without a writer, or a device, must not wait; it is cleared below
    // for the regular file that is all this accepts.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        const int code = errno;
        if (code == ENOENT)
            return fileError(path, "no such file");
        return fileError(path, "cannot open the file for reading (" + systemReason(code) + ")");
    }
    InputFile file;
    file.m_fd = fd;
    file.m_path = path;
    struct stat st {};
    if (::fstat(fd, &st) != 0)
        return fileError(path, "cannot read the file's status (" + systemReason(errno) + ")");
    if (S_ISDIR(st.st_mode))
        return fileError(path, "is a folder, not a file");
    if (!S_ISREG(st.st_mode))
        return fileError(path, "is " + fileKind(st.st_mode) +
                                   ", not a regular file; only "
                                   "regular files are read");
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    file.m_size = static_cast<std::uint64_t>(st.st_size);
    file.m_identity = identityFrom(st);
    if (record) {
        if (Status s = file.record(role); !s)
            return s.error();
    }
    return file;
}

InputFile::InputFile(InputFile&& other) noexcept
    : m_fd(other.m_fd), m_size(other.m_size), m_identity(other.m_identity),
      m_path(std::move(other.m_path)) {
    other.m_fd = -1;
}

InputFile& InputFile::operator=(InputFile&& other) noexcept {
    if (this != &other) {
        if (m_fd >= 0)
            ::close(m_fd);
        m_fd = other.m_fd;
        m_size = other.m_size;
        m_identity = other.m_identity;
        m_path = std::move(other.m_path);
        other.m_fd = -1;
    }
    return *this;
}

InputFile::~InputFile() {
    if (m_fd >= 0)
        ::close(m_fd);
}

Status InputFile::readAt(std::uint64_t offset, void* out, std::size_t bytes) const {
    auto* to = static_cast<char*>(out);
    std::size_t done = 0;
    while (done < bytes) {
        const ssize_t n = ::pread(m_fd, to + done, bytes - done, static_cast<off_t>(offset + done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            return fileError(m_path, "reading failed (" + systemReason(errno) + ")");
        if (n == 0)
            return fileError(m_path, "the file ends after " + std::to_string(offset + done) +
                                         " bytes, before the data it announces");
        done += static_cast<std::size_t>(n);
    }
    return success();
}

Result<std::string> InputFile::readAll(std::uint64_t limit) const {
    if (m_size > limit)
        return fileError(m_path, "the file is " + std::to_string(m_size) +
                                     " bytes, more than the " + std::to_string(limit) +
                                     " this reads");
    std::string text(static_cast<std::size_t>(m_size), '\0');
    if (Status s = readAt(0, text.data(), text.size()); !s)
        return s.error();
    return text;
}

Status InputFile::record(std::string_view role) const {
    return recordInput(m_identity, m_path, role);
}

Status noteInput(const std::string& path, std::string_view role) {
    struct stat st {};
    if (path.empty() || ::stat(path.c_str(), &st) != 0)
        return success();
    return recordInput(identityFrom(st), path, role);
}

std::optional<InputEntry> inputWithIdentity(const FileIdentity& identity) {
    if (tCurrent == nullptr)
        return std::nullopt;
    for (const Recorded& in : tCurrent->inputs) {
        if (in.identity == identity)
            return InputEntry{in.path, in.text};
    }
    return std::nullopt;
}

std::string describeInput(const InputEntry& entry) {
    if (entry.role.empty() || entry.role == entry.path)
        return entry.path;
    if (entry.role.starts_with("--"))
        return entry.role + " " + entry.path;
    return entry.path + " (" + entry.role + ")";
}

Status planOutput(const std::string& path, std::string_view option) {
    struct stat st {};
    if (tCurrent == nullptr || path.empty() || ::stat(path.c_str(), &st) != 0)
        return success(); // a file that is not there yet cannot be an input
    const FileIdentity id = identityFrom(st);
    for (const Recorded& in : tCurrent->inputs) {
        if (in.identity == id)
            return sameAsInput(path, option, {in.path, in.text});
    }
    tCurrent->outputs.push_back({id, path, std::string(option)});
    return success();
}

namespace {

// Both paths name the same existing file, or the same canonical path (two outputs not there yet).
bool sameFile(const std::string& a, const std::string& b) {
    namespace fs = std::filesystem;
    const std::optional<FileIdentity> ia = identityOf(a), ib = identityOf(b);
    if (ia && ib)
        return *ia == *ib; // hard links too
    std::error_code ec;
    const fs::path ca = fs::weakly_canonical(a, ec);
    if (ec)
        return false;
    const fs::path cb = fs::weakly_canonical(b, ec);
    return !ec && ca == cb;
}

Status checkOutput(const NamedPath& out) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(out.path, ec))
        return fileError(out.path, out.option + " is a folder; give a file name");
    const fs::path folder = fs::path(out.path).parent_path();
    const fs::path dir = folder.empty() ? fs::path(".") : folder;
    if (!fs::is_directory(dir, ec))
        return fileError(out.path, "cannot create the file: the folder " + folder.string() +
                                       " does not exist");
    if (Result<fs::path> target = outputTarget(out.path); !target) // a FIFO, a dangling link
        return target.error();
    if (::access(dir.c_str(), W_OK | X_OK) != 0)
        return fileError(out.path, "cannot create the file in " + dir.string() + " (" +
                                       systemReason(errno) + ")");
    return success();
}

} // namespace

Status checkOutputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
    const InputSession run; // the caller's run, or one for this check alone
    for (const NamedPath& in : inputs) {
        if (Status s = noteInput(in.path, in.option); !s)
            return s;
    }
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const NamedPath& out = outputs[i];
        for (std::size_t j = 0; j < i; ++j) {
            if (sameFile(out.path, outputs[j].path))
                return fileError(out.path, out.option + " names the same file as " +
                                               outputs[j].option + "; give each output its own");
        }
        if (Status s = planOutput(out.path, out.option); !s) // not an input, by identity
            return s;
        if (Status s = checkOutput(out); !s)
            return s;
    }
    return success();
}

void noteCreated(const FileIdentity& identity) {
    if (tCurrent != nullptr)
        tCurrent->created.push_back(identity);
}

InputSession::InputSession() {
    if (tCurrent == nullptr) {
        m_own = new Record;
        tCurrent = m_own;
    }
}

InputSession::~InputSession() {
    if (m_own != nullptr) {
        tCurrent = nullptr;
        delete m_own;
    }
}

} // namespace px
