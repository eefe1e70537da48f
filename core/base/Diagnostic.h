#pragma once
// A compiler-style message about an input: "file:line:col: error: message".
// Lines and columns are 1-based; 0 means "unknown" and is left out of the text.
#include "base/Identity.h"

#include <string>
#include <vector>

namespace rs {

enum class Severity { Note, Warning, Error };

struct SourceLocation {
    std::string file;
    int line = 0;
    int column = 0;
};

struct Diagnostic {
    Severity severity = Severity::Error;
    SourceLocation where;
    std::string message;
    // What the message is about (an instance, a rig node, a guide joint...), so
    // a log view can select the cause. None when the cause is a file position.
    Subject subject;

    std::string format() const;
};

using Diagnostics = std::vector<Diagnostic>;

Diagnostic makeError(SourceLocation where, std::string message);
Diagnostic makeWarning(SourceLocation where, std::string message);
bool hasErrors(const Diagnostics& diagnostics);
// The message of the first error ("" when there is none): for a caller that
// puts a parser's complaint into its own, located message.
std::string firstError(const Diagnostics& diagnostics);
std::string formatAll(const Diagnostics& diagnostics);
const char* severityName(Severity severity);

} // namespace rs
