// The fault suite's build of parallax-cli: the shipped program plus the fault-injection hooks
// (Temporaries.h), read from the environment here and only here: PX_TEST_FAIL_WRITE_AT=N fails a
// file's write with ENOSPC once N bytes are written; PX_TEST_RAISE=SIGNAL:POINT raises INT, TERM,
// HUP, KILL or STOP the first time the run reaches POINT (POINT@N: the N-th time);
// PX_BAKE_TEST_INTERRUPT_AT=F raises SIGINT once a command's progress reaches F.

#include "Cli.h"
#include "parallax/io/Temporaries.h"

#include <csignal>
#include <cstdlib>
#include <string>

namespace {

int gSignal = 0;
std::string gPoint;
long gCountdown = 1; // reaches of the point until the signal; once

void raiseAt(const char* point) {
    if (gCountdown > 0 && gPoint == point && --gCountdown == 0)
        std::raise(gSignal);
}

} // namespace

int main(int argc, char** argv) {
    px::TestHooks hooks;
    if (const char* at = std::getenv("PX_TEST_FAIL_WRITE_AT"))
        hooks.failWriteAt = std::atoll(at);
    if (const char* at = std::getenv("PX_BAKE_TEST_INTERRUPT_AT"))
        hooks.interruptAtProgress = std::strtof(at, nullptr);
    if (const char* spec = std::getenv("PX_TEST_RAISE")) {
        const std::string text(spec);
        const std::string name = text.substr(0, text.find(':'));
        gPoint = text.find(':') == std::string::npos ? "" : text.substr(text.find(':') + 1);
        if (const std::size_t at = gPoint.find('@'); at != std::string::npos) {
            gCountdown = std::atol(gPoint.c_str() + at + 1);
            gPoint.resize(at);
        }
        gSignal = name == "TERM"   ? SIGTERM
                  : name == "KILL" ? SIGKILL
                  : name == "STOP" ? SIGSTOP
                  : name == "HUP"  ? SIGHUP
                                   : SIGINT;
        hooks.reached = raiseAt;
    }
    px::setTestHooks(hooks);
    return px::cli::run(argc, argv);
}
