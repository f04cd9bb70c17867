#pragma once
// Several files written as one (an export folder, a turntable's frames, every shader variant),
// staged in a folder this run creates on the device of the folder they go into (Temporaries.h
// names it; the run holds its lock; Ctrl-C removes it). A folder that did not exist is the stage,
// made beside it and renamed into place; files going into an existing folder (among the user's
// files, an earlier export keeping an engine's .meta files, a mount point) are staged inside it and
// renamed one by one in an order where any prefix is consistent, Ctrl-C waiting for the last.
// After SIGKILL every file is whole, old or new, and the stage is a dead run's leftover that the
// next run removes: no journal, nothing found on disk obeyed.

#include "parallax/Result.h"
#include "parallax/io/OutputGate.h"

#include <filesystem>
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
        std::vector<std::string> moves; // staged names, renamed in this order
        const char* commitPoint = "";   // test moments (Temporaries.h): all staged; half moved
        const char* updatePoint = "";
    };
    // Renames the stage into place (fresh), or moves its files as `update` says, every target
    // checked by the output gate before the first rename. Nothing already in `into` is removed:
    // what a file found there says is never a reason to delete anything.
    Status commit(const Update& update);

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
