#include "ProgressLine.h"

#include "parallax/io/Temporaries.h"

#include <csignal>
#include <cstdio>
#include <unistd.h>

namespace px::cli {

ProgressLine::ProgressLine(std::string what)
    : m_what(std::move(what)), m_start(std::chrono::steady_clock::now()),
      m_tty(isatty(STDERR_FILENO) != 0) {
    m_interruptAt = testHooks().interruptAtProgress; // set by the fault suite's build only
}

ProgressLine::~ProgressLine() {
    if (m_shown && m_tty)
        std::fputc('\n', stderr);
}

void ProgressLine::operator()(float done) {
    if (m_interruptAt >= 0.0f && done >= m_interruptAt) {
        m_interruptAt = -1.0f;
        std::raise(SIGINT);
    }
    if (std::chrono::steady_clock::now() - m_start < std::chrono::seconds(1))
        return;
    const int percent = static_cast<int>(done * 100.0f);
    if (m_tty) {
        if (percent != m_last)
            std::fprintf(stderr, "\r%s: %3d%%", m_what.c_str(), percent);
    } else if (percent / 10 != m_last / 10 || !m_shown) {
        std::fprintf(stderr, "%s: %d%%\n", m_what.c_str(), percent);
    }
    m_last = percent;
    m_shown = true;
}

} // namespace px::cli
