#pragma once
// A value or a sentence for the user. The core never throws across its API: every fallible call
// returns a Result, and the editor shows `error().message` while the CLI prints "error: ...".
// (std::expected is C++23; this is the small subset the project needs.)

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace px {

struct Error {
    std::string message; // one sentence, naming the file and the problem where there is one
};

// Formats "FILE: problem" so every message names its file the same way.
inline Error fileError(const std::string& file, const std::string& problem) {
    return Error{file + ": " + problem};
}

template <typename T> class [[nodiscard]] Result {
public:
    Result(T value) : m_state(std::in_place_index<0>, std::move(value)) {}
    Result(Error error) : m_state(std::in_place_index<1>, std::move(error)) {}

    bool ok() const { return m_state.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & {
        assert(ok());
        return std::get<0>(m_state);
    }
    const T& value() const& {
        assert(ok());
        return std::get<0>(m_state);
    }
    T&& value() && {
        assert(ok());
        return std::get<0>(std::move(m_state));
    }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const {
        assert(!ok());
        return std::get<1>(m_state);
    }

private:
    std::variant<T, Error> m_state;
};

// For calls that produce nothing but can fail.
struct Done {};
using Status = Result<Done>;
inline Status success() {
    return Done{};
}

} // namespace px
