#include "base/Diagnostic.h"

#include <algorithm>

namespace rs {

const char* severityName(Severity severity)
{
    switch (severity) {
    case Severity::Note: return "note";
    case Severity::Warning: return "warning";
    case Severity::Error: return "error";
    }
    return "error";
}

std::string Diagnostic::format() const
{
    std::string text;
    if (!where.file.empty()) {
        text += where.file;
        if (where.line > 0) {
            text += ':' + std::to_string(where.line);
            if (where.column > 0)
                text += ':' + std::to_string(where.column);
        }
        text += ": ";
    }
    text += severityName(severity);
    text += ": ";
    text += message;
    return text;
}

Diagnostic makeError(SourceLocation where, std::string message)
{
    return {Severity::Error, std::move(where), std::move(message), {}};
}

Diagnostic makeWarning(SourceLocation where, std::string message)
{
    return {Severity::Warning, std::move(where), std::move(message), {}};
}

bool hasErrors(const Diagnostics& diagnostics)
{
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

std::string firstError(const Diagnostics& diagnostics)
{
    const auto error = std::find_if(diagnostics.begin(), diagnostics.end(),
                                    [](const Diagnostic& d) { return d.severity == Severity::Error; });
    return error == diagnostics.end() ? std::string() : error->message;
}

std::string formatAll(const Diagnostics& diagnostics)
{
    std::string text;
    for (const Diagnostic& d : diagnostics)
        text += d.format() + '\n';
    return text;
}

} // namespace rs
