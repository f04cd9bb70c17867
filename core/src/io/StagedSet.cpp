#include "parallax/io/StagedSet.h"

#include "parallax/io/AtomicWrite.h"
#include "parallax/io/OutputGate.h"
#include "parallax/io/Temporaries.h"

#include <cerrno>
#include <fcntl.h>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace px {

namespace fs = std::filesystem;

namespace {

constexpr const char* kJournal = ".parallax-commit";
constexpr const char* kJournalHeader = "parallax-commit 1";

void syncFolder(const fs::path& folder) {
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

bool bareName(const std::string& name) {
    return !name.empty() && name != "." && name != ".." &&
           name.find_first_of("/\n") == std::string::npos;
}

struct Journal {
    fs::path into;
    std::vector<std::string> moves;
    struct Removal {
        std::string name;
        std::uint64_t device = 0, inode = 0;
    };
    std::vector<Removal> removals;
};

// The folder a stage lies in, absolute (a stage may be named relative to the working folder).
fs::path stageParent(const fs::path& stage) {
    std::error_code ec;
    return fs::absolute(stage, ec).lexically_normal().parent_path();
}

std::string journalText(const fs::path& stage, const Journal& j) {
    std::error_code ec;
    // Relative to the stage's folder, so that a folder moved as a whole still recovers.
    const fs::path into =
        fs::absolute(j.into, ec).lexically_normal().lexically_relative(stageParent(stage));
    std::string text = std::string(kJournalHeader) + "\n";
    text += "into " + (into.empty() ? std::string(".") : into.string()) + "\n";
    for (const std::string& name : j.moves)
        text += "move " + name + "\n";
    for (const Journal::Removal& r : j.removals)
        text += "remove " + std::to_string(r.device) + " " + std::to_string(r.inode) + " " +
                r.name + "\n";
    return text;
}

std::optional<Journal> readJournal(const fs::path& stage) {
    Result<InputFile> file = InputFile::open((stage / kJournal).string(), {}, false);
    if (!file)
        return std::nullopt;
    Result<std::string> text = file->readAll(16 << 20);
    if (!text)
        return std::nullopt;
    std::istringstream lines(*text);
    std::string line;
    if (!std::getline(lines, line) || line != kJournalHeader)
        return std::nullopt;
    Journal j;
    while (std::getline(lines, line)) {
        const std::size_t space = line.find(' ');
        const std::string word = line.substr(0, space);
        const std::string rest = space == std::string::npos ? "" : line.substr(space + 1);
        if (word == "into") {
            j.into = (stageParent(stage) / rest).lexically_normal();
        } else if (word == "move" && bareName(rest)) {
            j.moves.push_back(rest);
        } else if (word == "remove") {
            std::istringstream fields(rest);
            Journal::Removal r;
            fields >> r.device >> r.inode;
            fields.get();
            std::getline(fields, r.name);
            if (fields.fail() || !bareName(r.name))
                return std::nullopt;
            j.removals.push_back(r);
        } else {
            return std::nullopt; // a journal this version does not understand: leave it alone
        }
    }
    if (j.into.empty())
        return std::nullopt;
    return j;
}

// The journal's moves and removals, on any run: each step is idempotent.
Status carryOut(const fs::path& stage, const Journal& j, const char* halfway) {
    std::error_code ec;
    for (std::size_t i = 0; i < j.moves.size(); ++i) {
        if (i == j.moves.size() / 2)
            testInterruptPoint(halfway);
        const fs::path from = stage / j.moves[i];
        if (!fs::exists(fs::symlink_status(from, ec)))
            continue; // moved before an interruption
        if (Status s = replaceWith(from, j.into / j.moves[i]); !s)
            return s;
    }
    for (const Journal::Removal& r : j.removals) {
        const fs::path path = j.into / r.name;
        struct stat st {};
        if (::lstat(path.c_str(), &st) == 0 && static_cast<std::uint64_t>(st.st_dev) == r.device &&
            static_cast<std::uint64_t>(st.st_ino) == r.inode)
            static_cast<void>(removeOwned(path, Removal::EarlierExport)); // refused: kept
    }
    syncFolder(j.into);
    return success();
}

} // namespace

Result<StagedSet> StagedSet::begin(const fs::path& anchor, std::string_view role) {
    StagedSet set;
    set.m_stage = temporarySibling(anchor, role);
    const fs::path parent = anchor.parent_path().empty() ? fs::path(".") : anchor.parent_path();
    if (::mkdir(set.m_stage.c_str(), 0777) != 0)
        return fileError(anchor.string(), "cannot create the working folder beside it in " +
                                              parent.string() + " (" + systemReason(errno) + ")");
    set.m_handle = registerTemporary(set.m_stage);
    set.m_fd = ::open(set.m_stage.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (set.m_fd >= 0)
        holdTemporary(set.m_fd);
    return set;
}

StagedSet::StagedSet(StagedSet&& other) noexcept
    : m_stage(std::move(other.m_stage)), m_fd(other.m_fd), m_handle(other.m_handle),
      m_fileHandles(std::move(other.m_fileHandles)), m_done(other.m_done) {
    other.m_stage.clear();
    other.m_fd = -1;
    other.m_handle = -1;
    other.m_fileHandles.clear();
    other.m_done = true;
}

StagedSet::~StagedSet() {
    if (!m_done && !m_stage.empty())
        discardTemporary(m_stage);
    for (int handle : m_fileHandles)
        releaseTemporary(handle);
    releaseTemporary(m_handle);
    if (m_fd >= 0)
        ::close(m_fd);
}

std::string StagedSet::pathFor(const std::string& name) const {
    const fs::path path = m_stage / name;
    m_fileHandles.push_back(registerTemporary(path));
    return path.string();
}

Status StagedSet::commitAsFolder(const fs::path& target) {
    if (Status s = moveFolderInto(m_stage, target); !s)
        return s;
    m_done = true;
    syncFolder(target.parent_path().empty() ? fs::path(".") : target.parent_path());
    return success();
}

Result<std::vector<std::string>> StagedSet::commitInto(const Update& update) {
    // Everything that can be refused is refused before the first file moves.
    Journal journal;
    journal.into = update.into;
    std::vector<std::string> kept;
    for (const std::string& name : update.moves) {
        if (!bareName(name))
            return Error{"internal: \"" + name + "\" is not a file name"};
        if (Status s = checkReplaceable(update.into / name); !s)
            return s.error();
        journal.moves.push_back(name);
    }
    for (const std::string& name : update.removals) {
        const fs::path path = update.into / name;
        struct stat st {};
        if (!bareName(name) || ::lstat(path.c_str(), &st) != 0)
            continue;
        if (!S_ISREG(st.st_mode)) {
            kept.push_back(name);
            continue;
        }
        if (Status s = checkReplaceable(path); !s) // a regular file: refused only as an input
            return s.error();
        journal.removals.push_back(
            {name, static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino)});
    }
    testInterruptPoint(update.commitPoint);

    const InterruptDeferral deferral; // from the journal on, the commit is decided
    if (Status s =
            writeFileAtomically((m_stage / kJournal).string(), journalText(m_stage, journal));
        !s)
        return s.error();
    syncFolder(m_stage);
    // Decided: neither Ctrl-C nor this object may remove the stage now; a failure leaves it to the
    // next run, which finishes the commit.
    m_done = true;
    for (int handle : m_fileHandles)
        releaseTemporary(handle);
    m_fileHandles.clear();
    releaseTemporary(m_handle);
    m_handle = -1;
    if (Status s = carryOut(m_stage, journal, update.updatePoint); !s)
        return Error{s.error().message + "; the update is half done: the next run writing " +
                         update.into.string() + " finishes it",
                     s.error().kind, s.error().file};
    discardTemporary(m_stage);
    return kept;
}

bool finishCommittedStage(const fs::path& stage) {
    std::error_code ec;
    if (!fs::is_directory(fs::symlink_status(stage, ec)) ||
        !fs::exists(fs::symlink_status(stage / kJournal, ec)))
        return false;
    const std::optional<Journal> journal = readJournal(stage);
    if (!journal)
        return true; // not ours to judge: kept
    if (carryOut(stage, *journal, ""))
        discardTemporary(stage);
    return true;
}

} // namespace px
