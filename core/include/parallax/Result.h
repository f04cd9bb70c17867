#pragma once
// A value or a sentence for the user. The core never throws across its API: every fallible call
// returns a Result, and the editor shows `error().message` while the CLI prints "error: ...".
// (std::expected is C++23; this is the small subset the project needs.)

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace px {

// What happened: callers branch on the kind, never on the text (a message that gains a prefix
// on its way up must not turn a cancel into an error dialog).
enum class ErrorKind {
    Failed,    // the operation could not be done; the message says why
    Cancelled, // the user stopped it (Cancel, Ctrl-C); nothing was produced
};

struct Error {
    Error() = default;
    explicit Error(std::string text, ErrorKind what = ErrorKind::Failed, std::string about = {})
        : message(std::move(text)), kind(what), file(std::move(about)) {}

    std::string message; // one sentence, naming the file and the problem where there is one
    ErrorKind kind = ErrorKind::Failed;
    std::string file; // the file it concerns, as the user named it; empty if none

    bool cancelled() const { return kind == ErrorKind::Cancelled; }
    // The same kind and file with more context in front: "pom: " + message.
    Error prefixed(const std::string& context) const {
        return Error{context + message, kind, file};
    }
};

// Formats "FILE: problem" so every message names its file the same way.
inline Error fileError(const std::string& file, const std::string& problem) {
    return Error{file + ": " + problem, ErrorKind::Failed, file};
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
