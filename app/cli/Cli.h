#pragma once
// parallax-cli: one CLI11 app, one subcommand per file (TraceCommand.cpp, ...).

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace px::cli {

// A subcommand's action: returns the process exit status; prints its own "error: ..." lines.
using Action = std::function<int()>;

// Every subcommand registers itself through one of these (declared here, defined in its file).
Action addTraceCommand(CLI::App& app);
Action addSampleCommand(CLI::App& app);
Action addShaderCommand(CLI::App& app);
Action addRenderCommand(CLI::App& app);
Action addExportCommand(CLI::App& app);
Action addBenchCommand(CLI::App& app);
Action addBenchAoCommand(CLI::App& app);
Action addStabilityCommand(CLI::App& app);
Action addBakeCommand(CLI::App& app);
Action addRecommendCommand(CLI::App& app);
Action addImportCommand(CLI::App& app);

// Prints "error: <message>" to stderr and returns the failure status.
int fail(const std::string& message);

// Registers every subcommand on `app`, with the number checks every numeric option gets
// (CommonOptions.h); returns each subcommand with its action, in order. (The tests enumerate the
// options through it.)
std::vector<std::pair<CLI::App*, Action>> addCommands(CLI::App& app);

int run(int argc, char** argv);

} // namespace px::cli
