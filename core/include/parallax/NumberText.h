#pragma once
// One reading of a number a user writes: a command-line option, a value in a sweep or in a list.
// Decimal, the whole text, finite, within its range, an integer that fits (never wrapped, never
// read as octal or hex). Every refusal is one sentence, "WHAT: 'TEXT' is ...", so the same
// mistake reads the same wherever it is made; WHAT empty leaves the prefix to the caller (CLI11
// puts the option's name in front of a validator's message).

#include "parallax/Result.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

namespace px {

struct NumberRange {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool minExclusive = false; // "positive": min < value
};

namespace detail {

inline std::string numberWords(double v) {
    if (std::abs(v) < 1e15 && v == std::floor(v))
        return std::to_string(static_cast<long long>(v));
    char text[32];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, v);
    return ec == std::errc() ? std::string(text, end) : std::to_string(v);
}

inline Error numberError(std::string_view what, std::string_view text, const std::string& problem) {
    std::string message = what.empty() ? std::string() : std::string(what) + ": ";
    return Error{message + "'" + std::string(text) + "' " + problem};
}

inline std::string rangeWords(const NumberRange& range) {
    if (range.minExclusive && range.min == 0 && std::isinf(range.max))
        return "is not positive";
    if (std::isinf(range.max))
        return "is less than " + numberWords(range.min);
    if (std::isinf(range.min))
        return "is more than " + numberWords(range.max);
    return "is out of range (" + numberWords(range.min) + " to " + numberWords(range.max) + ")";
}

// The text without one leading '+', which std::from_chars does not take.
inline std::string_view unsigned_(std::string_view text) {
    return text.starts_with('+') && text.size() > 1 && text[1] != '-' ? text.substr(1) : text;
}

} // namespace detail

// A finite decimal number (1, -0.5, 2e-3) in `range`.
inline Result<double> parseReal(std::string_view text, std::string_view what = {},
                                NumberRange range = {}) {
    const std::string_view digits = detail::unsigned_(text);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value,
                                           std::chars_format::general);
    if (digits.empty() || end != digits.data() + digits.size() ||
        (ec != std::errc() && ec != std::errc::result_out_of_range))
        return detail::numberError(what, text, "is not a number");
    if (ec == std::errc::result_out_of_range || !std::isfinite(value))
        return detail::numberError(what, text, "is not a finite number");
    if (value < range.min || value > range.max || (range.minExclusive && value == range.min))
        return detail::numberError(what, text, detail::rangeWords(range));
    return value;
}

// A decimal integer ("010" is ten) from `min` to `max`; one that overflows is out of range.
inline Result<long long> parseInteger(std::string_view text, std::string_view what, long long min,
                                      long long max) {
    const std::string_view digits = detail::unsigned_(text);
    long long value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    const bool whole = !digits.empty() && end == digits.data() + digits.size();
    if (!whole || (ec != std::errc() && ec != std::errc::result_out_of_range)) {
        // A number all the same (nan, 1.5, 1e3): say why it is not an integer.
        if (Result<double> real = parseReal(text, what); !real)
            return real.error();
        return detail::numberError(what, text, "is not a whole number");
    }
    const NumberRange range{static_cast<double>(min), static_cast<double>(max)};
    if (ec == std::errc::result_out_of_range || value < min || value > max)
        return detail::numberError(what, text, detail::rangeWords(range));
    return value;
}

} // namespace px
