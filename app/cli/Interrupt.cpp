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
    const char* message = signal == SIGTERM
                              ? "\nerror: terminated (SIGTERM): stopped, temporary files removed\n"
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
    sigaddset(&action.sa_mask, SIGINT);
    sigaddset(&action.sa_mask, SIGTERM);
    for (int signal : {SIGINT, SIGTERM})
        ::sigaction(signal, &action, nullptr);
}

} // namespace px::cli
