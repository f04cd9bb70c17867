#pragma once
// The editor's entry point: application set-up, the OpenGL check, the window, and the
// --screenshot mode.

namespace px::studio {

int runStudio(int argc, char** argv);

} // namespace px::studio
