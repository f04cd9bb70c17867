#pragma once
// One record of the files this run reads, known by identity (device and inode), however they were
// reached: the command line, a material file's maps, a mesh's buffers and images, an environment,
// a cache, an import folder. The output gate (OutputGate.h) refuses to replace or delete any of
// them, so `./a/../a/x.png`, a hard link or a symbolic link to an input cannot slip past a
// comparison of names. Every reader opens through InputFile: it never blocks on a FIFO and reads
// only regular files.
//
// The record belongs to one run: an InputSession (a command of parallax-cli, an editor's save,
// export or bake) is the current run of the thread that opened it, and readers and writers on that
// thread use it; sessions opened inside it join it. The editor's concurrent save, export and bake
// run on their own threads and never see each other's inputs. Outside a session nothing is
// recorded and the gate checks only the kinds of files it may replace.

#include "parallax/Result.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace px {

struct FileIdentity {
    std::uint64_t device = 0, inode = 0;
    friend bool operator==(const FileIdentity&, const FileIdentity&) = default;
};

// The identity of what `path` names, following symbolic links; nullopt if it does not exist.
std::optional<FileIdentity> identityOf(const std::string& path);

// "a FIFO (named pipe)", "a folder", ... for the file type in `mode` (st_mode).
std::string fileKind(unsigned mode);

// A regular file open for reading. Opening uses O_NONBLOCK, so a FIFO or a device cannot hang
// the run, and refuses anything but a regular file naming its kind.
class InputFile {
public:
    // Opens `path` and, unless `record` is false (the run's own files: a manifest, a temporary),
    // records it as an input with `role` ("the height map of m.json"); errors name the path.
    static Result<InputFile> open(const std::string& path, std::string_view role = {},
                                  bool record = true);
    InputFile(InputFile&& other) noexcept;
    InputFile& operator=(InputFile&& other) noexcept;
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;
    ~InputFile();

    int fd() const { return m_fd; }
    std::uint64_t size() const { return m_size; }
    const FileIdentity& identity() const { return m_identity; }
    const std::string& path() const { return m_path; }

    // Reads `bytes` at `offset`; a short file is an error naming it.
    Status readAt(std::uint64_t offset, void* out, std::size_t bytes) const;
    // The whole file, refused when it holds more than `limit` bytes.
    Result<std::string> readAll(std::uint64_t limit) const;
    // Records this file as an input (for readers that decide after looking at it).
    Status record(std::string_view role = {}) const;

private:
    InputFile() = default;
    int m_fd = -1;
    std::uint64_t m_size = 0;
    FileIdentity m_identity;
    std::string m_path;
};

// Records the existing file at `path` as an input without reading it (a map a material names but
// this command does not load, an import folder's files). A path that does not exist is not an
// error (nothing there can be lost); one that is a planned output is (see planOutput).
Status noteInput(const std::string& path, std::string_view role = {});

// What the record knows of an input with this identity: the path it was read by and its role
// ("--height", "the albedo map of m.json"); nullopt when it is not an input of this run.
struct InputEntry {
    std::string path;
    std::string role;
};
std::optional<InputEntry> inputWithIdentity(const FileIdentity& identity);

// "h.png (the height map of m.json)" for messages.
std::string describeInput(const InputEntry& entry);

// Declares, before reading, a file the run will write (`option`: "--out", "frame 3 of
// --turntable"): an input met later that is the same file is refused when it is recorded, before
// any work, naming both; so is one already recorded.
Status planOutput(const std::string& path, std::string_view option);

struct NamedPath {
    std::string option; // "--out", "--height", ...
    std::string path;
};

// The command line's files, before any work: records `inputs`, then plans each output
// (planOutput). An output must not be a folder or a special file, its folder must exist and be
// writable, and it must not be the same file as an input (by identity, or the same canonical
// path) nor as another output. Errors name the file, both options and the problem.
Status checkOutputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

// Notes a file this run created (its identity, kept when it is renamed into place): reading it back
// later does not make it an input, since no one else's data can be in it.
void noteCreated(const FileIdentity& identity);

// A run: the current run of this thread while alive (see above); one opened inside another joins
// it, and the record ends with the outermost.
class InputSession {
public:
    InputSession();
    ~InputSession();
    InputSession(const InputSession&) = delete;
    InputSession& operator=(const InputSession&) = delete;
    struct Record;

private:
    Record* m_own = nullptr; // null when joining an outer session
};

} // namespace px
