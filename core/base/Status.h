#pragma once
// Status: the outcome of an operation that returns nothing but can fail (an
// edit refused, a file not written). A success may still carry warnings and
// notes; a failure carries at least one error. The diagnostics have a typed
// subject where the failure is about something in the guide, so a log view can
// select it, and file:line:column where it is about a file.
//
// There is deliberately no conversion to bool: `if (status)` would read as
// "if failed" to anyone used to error codes and as "if ok" to anyone used to
// Result. Write `status.ok()` or `status.failed()`.
#include "base/Diagnostic.h"

#include <utility>

namespace rs {

class Status {
public:
    Status() = default; // success, no messages
    static Status success(Diagnostics notes = {}) { return Status(false, std::move(notes)); }
    static Status failure(Diagnostics diagnostics) { return Status(true, std::move(diagnostics)); }
    static Status failure(Diagnostic diagnostic) { return Status(true, Diagnostics{std::move(diagnostic)}); }
    // A refusal with no file position, about `subject` (or nothing).
    static Status refused(std::string message, Subject subject = {})
    {
        Diagnostic d = makeError({}, std::move(message));
        d.subject = std::move(subject);
        return failure(std::move(d));
    }

    bool ok() const { return !m_failed; }
    bool failed() const { return m_failed; }
    const Diagnostics& diagnostics() const { return m_diagnostics; }
    Diagnostics takeDiagnostics() { return std::move(m_diagnostics); }
    // The messages as one text ("error: ..." lines), for a status bar or stderr.
    std::string message() const { return formatAll(m_diagnostics); }

private:
    Status(bool failed, Diagnostics diagnostics) : m_failed(failed), m_diagnostics(std::move(diagnostics)) {}
    bool m_failed = false;
    Diagnostics m_diagnostics;
};

} // namespace rs
