#pragma once
// What the GL tests share: one headless context per test process.

#include "HeadlessContext.h"

#include <memory>

namespace px::test {

// Creates the context on first use and keeps it current; QFAILs through the caller when none can
// be made (the message says what the machine offers).
HeadlessContext* glContext();

} // namespace px::test
