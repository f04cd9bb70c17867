#include "parallax/io/StagedSet.h"

#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Temporaries.h"

#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace px {

namespace fs = std::filesystem;

namespace {

bool bareName(const std::string& name) {
    return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos;
}

} // namespace

Result<StagedSet> StagedSet::begin(const fs::path& into, const std::string& anchor) {
    StagedSet set;
    set.m_into = into;
    const fs::path parent = into.parent_path().empty() ? fs::path(".") : into.parent_path();
    Result<UniqueFd> folder = openFolder(into);
    set.m_fresh = !folder;
    if (set.m_fresh) {
        folder = openFolder(parent);
        if (!folder)
            return folder.error();
        removeStaleTemporaries(folder->get(), into.filename().string());
    } else {
        removeStaleTemporaries(folder->get(), anchor);
    }
    set.m_parent = std::move(*folder);
    const std::string& key = set.m_fresh ? into.filename().string() : anchor;
    set.m_name = temporaryName(key, "stage");
    set.m_path = (set.m_fresh ? parent : into) / set.m_name;
    // A fresh stage becomes the user's folder: the usual mode (umask applied); one inside the
    // target is only ever ours.
    if (::mkdirat(set.m_parent.get(), set.m_name.c_str(), set.m_fresh ? 0777 : 0700) != 0)
        return fileError(into.string(), std::string("cannot create the working folder ") +
                                            (set.m_fresh ? "beside" : "in") + " it (" +
                                            systemReason(errno) + ")");
    set.m_stage = UniqueFd(::openat(set.m_parent.get(), set.m_name.c_str(),
                                    O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
    if (set.m_stage.get() < 0)
        return fileError(into.string(),
                         "cannot open its working folder (" + systemReason(errno) + ")");
    holdTemporary(set.m_stage.get());
    set.m_handle = registerTemporary(set.m_parent.get(), set.m_name, set.m_stage.get());
    return set;
}

StagedSet::~StagedSet() {
    if (m_parent.get() < 0 || m_name.empty())
        return;
    releaseTemporary(m_handle);
    discardTemporaryAt(m_parent.get(), m_name);
}

Status StagedSet::commit(const Update& update) {
    if (m_fresh) {
        testInterruptPoint(update.commitPoint);
        if (Status s = replaceAt(m_parent.get(), m_name, m_parent.get(), m_into.filename().string(),
                                 m_into.string(), true);
            !s)
            return s.error();
        releaseTemporary(m_handle);
        m_name.clear(); // it is the target now
        return success();
    }
    // Everything that can be refused is refused before the first file moves.
    const int into = m_parent.get();
    for (const std::string& name : update.moves) {
        if (!bareName(name))
            return Error{"internal: \"" + name + "\" is not a file name"};
        if (Status s = checkReplaceableAt(into, name, (m_into / name).string()); !s)
            return s.error();
    }
    testInterruptPoint(update.commitPoint);
    const InterruptDeferral deferral; // Ctrl-C waits for the last rename
    for (std::size_t i = 0; i < update.moves.size(); ++i) {
        if (i == update.moves.size() / 2)
            testInterruptPoint(update.updatePoint);
        const std::string& name = update.moves[i];
        if (Status s = replaceAt(m_stage.get(), name, into, name, (m_into / name).string()); !s)
            return Error{s.error().message + (i == 0 ? "" : "; the files before it were replaced"),
                         s.error().kind, s.error().file};
    }
    releaseTemporary(m_handle);
    discardTemporaryAt(into, m_name); // empty now
    m_name.clear();
    ::fsync(into);
    return success();
}

} // namespace px
