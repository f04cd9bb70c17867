#pragma once
// How the material messages print ranges and values.

#include "MaterialLimits.h"

#include <cstdio>
#include <string>

namespace px::material {

// Shortest round-trippable-enough text of a number: 0.05, 100, 1e-06.
inline std::string numberText(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    return buffer;
}

inline std::string expectedNumber(NumberRange range) {
    return "expected a number " + numberText(range.lo) + ".." + numberText(range.hi);
}

inline std::string expectedInteger(IntRange range) {
    return "expected an integer " + std::to_string(range.lo) + ".." + std::to_string(range.hi);
}

} // namespace px::material
