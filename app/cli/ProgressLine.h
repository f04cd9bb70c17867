#pragma once
// "baking relaxed-cone map: 42%" on stderr, once the work has run for a second: one updating line
// on a terminal, a line per 10% otherwise. For the bakes of `bake`, and those `recommend` needs.
// PX_BAKE_TEST_INTERRUPT_AT=F (tests only) raises SIGINT once the work is F done, to exercise the
// real Ctrl-C path (Interrupt.h).

#include <chrono>
#include <string>

namespace px::cli {

class ProgressLine {
public:
    explicit ProgressLine(std::string what);
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    // done: the fraction in [0, 1], non-decreasing.
    void operator()(float done);

private:
    std::string m_what;
    std::chrono::steady_clock::time_point m_start;
    bool m_tty;
    bool m_shown = false;
    int m_last = -1;
    float m_interruptAt = -1.0f;
};

} // namespace px::cli
