#pragma once
// A horizontal uv distance given on the command line: a number > 0, or "inf" for unlimited (the
// occlusion bakes' --distance, export's --ao-distance, bench-ao's --distance).

#include <CLI/CLI.hpp>
#include <string>

namespace px::cli {

// Adds `name` to `command`, read into `distance`; anything but a number > 0 or inf is refused
// with one line naming the option and the value.
CLI::Option* addDistanceOption(CLI::App& command, const std::string& name, double& distance,
                               const std::string& help);

} // namespace px::cli
