#pragma once
// Several files written as one (an export folder, a turntable's frames, every shader variant): an
// interruption leaves no debris and never half a file, and nothing needs finishing later.
//
// The files are written into a stage folder this run creates (mkdirat) on the
// device of the folder they go into (Temporaries.h names it; the run holds its lock and Ctrl-C
// removes it with its files). Then:
// - a folder that did not exist is the stage, made beside it and renamed into place: atomic;
// - files that go into an existing folder (frames among the user's files, an earlier export
//   updated in place keeping an engine's .meta and .import files, a folder that is a mount point)
//   are staged inside that folder and renamed one by one, in an order the caller chooses so that
//   any prefix is a consistent state (an export's manifest first as the union of the old and new
//   lists, last as the new one). Ctrl-C and SIGTERM wait for the last rename. After SIGKILL or a
//   power cut the renamed files are whole new files, the rest whole old ones, and the stage is a
//   dead run's leftover that the next run removes: no journal, nothing found on disk obeyed.

#include "parallax/Result.h"
#include "parallax/io/OutputGate.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace px {

class StagedSet {
public:
    // A stage for files going into the folder `into`, for the set named `anchor` (a bare name:
    // the export folder's, the first frame's). Removes dead runs' stages of the same set first.
    static Result<StagedSet> begin(const std::filesystem::path& into, const std::string& anchor);
    StagedSet(StagedSet&& other) noexcept = default;
    StagedSet& operator=(StagedSet&&) = delete;
    StagedSet(const StagedSet&) = delete;
    StagedSet& operator=(const StagedSet&) = delete;
    ~StagedSet(); // removes the stage and whatever is still in it

    const std::filesystem::path& folder() const { return m_path; }
    // Where to write the set's file `name` (a bare name).
    std::string pathFor(const std::string& name) const { return (m_path / name).string(); }
    // Whether `into` did not exist: the commit renames the stage into place.
    bool fresh() const { return m_fresh; }

    struct Update {
        std::vector<std::string> moves;    // staged names, renamed in this order
        std::vector<std::string> removals; // names in `into` removed after (an earlier export's)
        const char* commitPoint = "";      // test moments (Temporaries.h): all staged; half moved
        const char* updatePoint = "";
        std::function<Status()> then; // last, Ctrl-C still waiting (an export's final manifest)
    };
    // Renames the stage into place (fresh), or moves and removes as `update` says, every target
    // checked by the output gate before the first rename. Returns the removals that were kept
    // (not regular files).
    Result<std::vector<std::string>> commit(const Update& update);

private:
    StagedSet() = default;
    std::filesystem::path m_into, m_path;
    UniqueFd m_parent; // the folder the stage lies in: `into`, or its parent when fresh
    UniqueFd m_stage;  // the stage, locked while this run lives
    std::string m_name;
    int m_handle = -1;
    bool m_fresh = false;
};

} // namespace px
