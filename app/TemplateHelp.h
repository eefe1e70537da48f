#pragma once
// One help page per template: what it builds (its section of
// templates/README.md), a picture of its built rig (rendered when asked, so it
// never goes stale), its hooks (every guide joint of a new instance, with its
// name and tags) and structure tags, and its guide parameters and options.
// Shown by the Help menu (F1) and the Options dock's help button.
#include "templates/Manifest.h"
#include "templates/TemplateRegistry.h"

#include <QImage>
#include <QString>

namespace rs::app {

// The README's section about `templateId` (its "## id" or "### id" heading and
// the text under it, up to the next heading of the same or a higher level);
// empty when the README has none.
QString readmeSection(const QString& readme, const std::string& templateId);

struct TemplateHelpPage {
    QString markdown;  // refers to the picture as kTemplatePictureUrl
    QImage picture;    // null when the template builds nothing alone or no GL context is available
    QString pictureProblem; // why there is no picture
};
inline constexpr const char* kTemplatePictureUrl = "rigsmith-help:built-rig.png";

TemplateHelpPage templateHelpPage(const templates::TemplateManifest& manifest, const templates::TemplateRegistry& registry,
                                  const QString& readme);

} // namespace rs::app
