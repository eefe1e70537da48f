#pragma once
// Result<T>: a value, or the diagnostics explaining why there is none.
// A successful result may still carry warnings. Exceptions never cross a library
// boundary; functions that can fail on user input return a Result instead.
#include "base/Diagnostic.h"

#include <cassert>
#include <optional>
#include <utility>

namespace rs {

template <class T>
class Result {
public:
    Result(T value, Diagnostics warnings = {})
        : m_value(std::move(value)), m_diagnostics(std::move(warnings)) {}
    static Result failure(Diagnostics diagnostics) { return Result(std::move(diagnostics)); }
    static Result failure(Diagnostic diagnostic) { return Result(Diagnostics{std::move(diagnostic)}); }
    // A refusal with no file position, about `subject` (or nothing), as Status::refused.
    static Result refused(std::string message, Subject subject = {})
    {
        Diagnostic d = makeError({}, std::move(message));
        d.subject = std::move(subject);
        return failure(std::move(d));
    }

    bool ok() const { return m_value.has_value(); }
    explicit operator bool() const { return ok(); }
    T& value() { assert(ok()); return *m_value; }
    const T& value() const { assert(ok()); return *m_value; }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() { return value(); }
    const T& operator*() const { return value(); }
    T take() { assert(ok()); return std::move(*m_value); }

    const Diagnostics& diagnostics() const { return m_diagnostics; }
    Diagnostics takeDiagnostics() { return std::move(m_diagnostics); }

private:
    explicit Result(Diagnostics diagnostics) : m_diagnostics(std::move(diagnostics)) {}
    std::optional<T> m_value;
    Diagnostics m_diagnostics;
};

} // namespace rs
