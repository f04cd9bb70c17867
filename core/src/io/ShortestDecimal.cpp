#include "io/ShortestDecimal.h"

#include <cstdio>
#include <cstdlib>

namespace px {

double shortestDecimal(float value) {
    char buffer[32];
    for (int precision = 6; precision <= 9; ++precision) {
        std::snprintf(buffer, sizeof buffer, "%.*g", precision, static_cast<double>(value));
        if (std::strtof(buffer, nullptr) == value)
            break;
    }
    return std::strtod(buffer, nullptr);
}

} // namespace px
