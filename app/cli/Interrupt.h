#pragma once
// SIGINT, SIGTERM and SIGHUP for every command: the process removes the temporary files and folders
// it has open (px::removeTemporariesNow), says so, and exits 130 at once, whatever it was doing.
// The previous outputs are untouched because every write ends with a rename (AtomicWrite.h); the
// few renames that must happen together defer the signal (px::InterruptDeferral).

namespace px::cli {

inline constexpr int kInterruptedStatus = 130; // as shells report Ctrl-C

void installInterruptHandlers();

} // namespace px::cli
