#include "DistanceOption.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace px::cli {

CLI::Option* addDistanceOption(CLI::App& command, const std::string& name, double& distance,
                               const std::string& help) {
    return command.add_option_function<std::string>(
        name,
        [&distance, name](const std::string& text) {
            const char* begin = text.c_str();
            char* end = nullptr;
            errno = 0;
            const double value = std::strtod(begin, &end);
            // strtod also reads "nan" and hexadecimal: only decimal numbers and inf pass.
            const bool number = end != begin && *end == '\0' && errno == 0 &&
                                text.find_first_of("xXnN") == std::string::npos;
            const bool infinite = text == "inf";
            if (!(infinite || (number && std::isfinite(value) && value > 0.0)))
                throw CLI::ValidationError(name, "\"" + text +
                                                     "\" is not a distance: give a number > 0 "
                                                     "(uv units) or inf");
            distance = infinite ? INFINITY : value;
        },
        help);
}

} // namespace px::cli
