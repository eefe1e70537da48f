#pragma once
// Whether the template library has what a guide's instances use. Checked when
// a guide is opened (the editor's Build log, rigsmith-cli add), so a missing
// template is said at once rather than at the next build.
#include "base/Diagnostic.h"
#include "model/GuideDocument.h"
#include "templates/TemplateRegistry.h"

#include <string>

namespace rs::templates {

// One warning per instance whose template `templates` lacks, its subject the
// instance; `file` (the guide's path, may be empty) is where it points. The
// instance stays in the guide; a build skips it and hangs its children above it.
Diagnostics checkGuideTemplates(const model::GuideDocument& guide, const TemplateRegistry& templates,
                                const std::string& file = {});

} // namespace rs::templates
