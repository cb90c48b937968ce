#pragma once
// Errors are values (sokol style): every fallible call returns Result<T>, and
// tests assert on the Error it carries. Error::where names the file or the
// JSON path; Error::what says what is wrong with it, in one line.

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace dermis {

struct Error {
    std::string where;  // file, or file plus a JSON pointer / field name
    std::string what;   // the problem, in one sentence

    std::string message() const { return where.empty() ? what : where + ": " + what; }
};

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : mState(std::move(value)) {}
    Result(Error error) : mState(std::move(error)) {}

    bool ok() const { return std::holds_alternative<T>(mState); }
    explicit operator bool() const { return ok(); }

    T& value() & { assert(ok()); return std::get<T>(mState); }
    const T& value() const& { assert(ok()); return std::get<T>(mState); }
    T&& value() && { assert(ok()); return std::get<T>(std::move(mState)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const { assert(!ok()); return std::get<Error>(mState); }

private:
    std::variant<T, Error> mState;
};

// Result<void>: success carries nothing.
struct Ok {};
using Status = Result<Ok>;
inline Status success() { return Ok{}; }

inline Error makeError(std::string where, std::string what) { return Error{std::move(where), std::move(what)}; }

}  // namespace dermis
