#include "Interrupt.h"

#include "parallax/io/Temporaries.h"

#include <csignal>
#include <cstring>
#include <unistd.h>

namespace px::cli {

namespace {

extern "C" void onInterrupt(int signal) {
    if (px::deferInterrupt(signal))
        return;
    px::removeTemporariesNow();
    const char* message =
        signal == SIGTERM  ? "\nerror: terminated (SIGTERM): stopped, temporary files removed\n"
        : signal == SIGHUP ? "\nerror: hung up (SIGHUP): stopped, temporary files removed\n"
                           : "\nerror: interrupted (SIGINT): stopped, temporary files removed\n";
    // write() and _exit() are async-signal-safe; stdio and exit() are not.
    [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, message, std::strlen(message));
    ::_exit(kInterruptedStatus);
}

} // namespace

void installInterruptHandlers() {
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    // SIGHUP too: the terminal closed under a long bake stops it as cleanly as Ctrl-C.
    for (int signal : {SIGINT, SIGTERM, SIGHUP})
        sigaddset(&action.sa_mask, signal);
    for (int signal : {SIGINT, SIGTERM, SIGHUP})
        ::sigaction(signal, &action, nullptr);
}

} // namespace px::cli
