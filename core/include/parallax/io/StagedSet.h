#pragma once
// Several files written as one (an export folder, a turntable's frames): an interruption leaves
// either the whole old set or the whole new one.
//
// The files are written into a hidden stage folder beside the set's name (".NAME.<role>PID-N.HOST",
// Temporaries.h), registered so that Ctrl-C removes it, and locked so that no other run's sweep
// takes it while this one lives. Then:
// - a new folder (an export where there was none) is the stage renamed into place: atomic;
// - files that go among others (frames beside the user's files; an earlier export updated in
//   place, keeping an engine's .meta and .import files) are moved one by one. First a journal
//   listing every move and removal is written into the stage and flushed: from then on the commit
//   is decided. Ctrl-C and SIGTERM wait for the last move (a few milliseconds). After SIGKILL or a
//   power cut in those milliseconds the journal remains, and the next run on the same name
//   finishes the commit before anything else (finishCommittedStage), so the set is whole again.

#include "parallax/Result.h"
#include "parallax/io/Inputs.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace px {

class StagedSet {
public:
    // A stage beside `anchor` (the set's name: the export folder, or the turntable's --out).
    static Result<StagedSet> begin(const std::filesystem::path& anchor, std::string_view role);
    StagedSet(StagedSet&& other) noexcept;
    StagedSet& operator=(StagedSet&&) = delete;
    StagedSet(const StagedSet&) = delete;
    StagedSet& operator=(const StagedSet&) = delete;
    ~StagedSet(); // removes the stage unless it was committed (or is half-committed: see above)

    const std::filesystem::path& folder() const { return m_stage; }
    // Where to write the set's file `name` (a bare name), registered for removal on Ctrl-C.
    std::string pathFor(const std::string& name) const;

    // Renames the stage to `target`, absent or an empty folder.
    Status commitAsFolder(const std::filesystem::path& target);

    struct Update {
        std::filesystem::path into;     // the folder the files go to
        std::vector<std::string> moves; // staged names, moved in this order (the last: a manifest)
        std::vector<std::string> removals; // names in `into` to remove (an earlier export's)
        const char* commitPoint = "";      // test hooks (Temporaries.h): all staged; half moved
        const char* updatePoint = "";
    };
    // Moves and removes as `update` says, every target checked by the output gate before the
    // first move. Returns the removals that were kept (not regular files).
    Result<std::vector<std::string>> commitInto(const Update& update);

private:
    StagedSet() = default;
    std::filesystem::path m_stage;
    int m_fd = -1;     // the stage folder, locked while this run lives
    int m_handle = -1; // registered temporary
    mutable std::vector<int> m_fileHandles;
    bool m_done = false;
};

// If `stage` (a dead run's) holds a commit journal, finishes that commit: moves what is left,
// removes what it listed (when still the same file), then the stage. Returns whether it did.
bool finishCommittedStage(const std::filesystem::path& stage);

} // namespace px
