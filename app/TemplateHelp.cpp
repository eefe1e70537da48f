#include "TemplateHelp.h"

#include "OffscreenPicture.h"
#include "eval/RigProgram.h"
#include "rigging/RigBuilder.h"
#include "templates/Structure.h"

#include <QRegularExpression>
#include <QStringList>

#include <map>

namespace rs::app {

namespace {

QString text(const std::string& s) { return QString::fromStdString(s); }

QString parameterRows(const std::vector<templates::Parameter>& parameters)
{
    QString rows;
    for (const templates::Parameter& p : parameters) {
        QString values = text(formatValue(p.value));
        if (p.isEnum()) {
            QStringList labels;
            for (const auto& [index, label] : p.enumLabels)
                labels << text(label);
            values += " (" + labels.join(", ") + ")";
        } else if (p.min || p.max) {
            values += QString(" (%1 to %2)").arg(p.min ? QString::number(*p.min) : "-inf", p.max ? QString::number(*p.max) : "inf");
        }
        rows += QString("| `%1` | %2 | %3 |\n").arg(text(p.name), values, text(p.help).replace('|', '/').replace('\n', ' '));
    }
    return rows;
}

// A new instance of the template alone, as the template library would add it.
Result<model::GuideDocument> guideOf(const templates::TemplateManifest& manifest, const templates::TemplateRegistry& registry)
{
    model::GuideDocument guide;
    auto instance = rigging::makeInstance(guide, registry, manifest.id, model::kNoId);
    if (!instance)
        return Result<model::GuideDocument>::failure(instance.diagnostics());
    guide.insertInstance(instance.take(), 0);
    return guide;
}

QString hooksOf(const model::GuideDocument& guide, const templates::TemplateManifest& manifest)
{
    const model::TemplateInstance& instance = guide.instances().front();
    // The structure tags each joint carries (what builders, shapes and `ui.hooks` call it).
    const templates::StructureResolver resolver(manifest, instance);
    std::map<model::JointId, QStringList> structureTags;
    for (const auto& [tag, address] : manifest.structure)
        if (auto joints = resolver.tag(tag))
            for (model::JointId joint : *joints)
                structureTags[joint] << "`" + text(tag) + "`";
    QString md = QObject::tr("Every guide joint is a hook: a child template can hang under any of them. "
                             "A new instance has these joints:\n\n| joint | name | guide tags | structure tags |\n|---|---|---|---|\n");
    for (std::size_t j = 0; j < instance.joints.size(); ++j) {
        const model::GuideJoint& joint = instance.joints[j];
        QStringList tags;
        for (const std::string& tag : joint.tags)
            tags << "`" + text(tag) + "`";
        const QStringList& structure = structureTags[joint.id];
        md += QString("| %1 | %2 | %3 | %4 |\n").arg(j).arg(joint.name.empty() ? "-" : "`" + text(joint.name) + "`",
                                                         tags.isEmpty() ? "-" : tags.join(", "),
                                                         structure.isEmpty() ? "-" : structure.join(", "));
    }
    return md;
}

QImage pictureOf(const model::GuideDocument& guide, const templates::TemplateRegistry& registry, QString& problem)
{
    const model::Rig rig = rigging::buildRig(guide, registry);
    if (rig.nodes.size() <= 1) {
        problem = QObject::tr("The template builds no rig node on its own.");
        return {};
    }
    auto program = eval::RigProgram::compile(rig);
    if (!program) {
        problem = QObject::tr("The template's rig does not evaluate on its own.");
        return {};
    }
    eval::EvalState state = program->makeState();
    program->evaluate(program->channels().defaults(), state);
    viewport::Scene scene = viewport::makeScene(guide, &rig, {}, &state);
    const int width = 640, height = 420;
    std::string error;
    QImage image = viewport::renderOffscreen(scene, viewport::pictureCamera(scene, double(width) / height), width, height, error);
    if (image.isNull())
        problem = text(error);
    return image;
}

} // namespace

QString readmeSection(const QString& readme, const std::string& templateId)
{
    const QStringList lines = readme.split('\n');
    const QRegularExpression heading(QString("^(#{2,3})\\s+%1\\s*$").arg(QRegularExpression::escape(text(templateId))));
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const auto match = heading.match(lines[i]);
        if (!match.hasMatch())
            continue;
        const qsizetype level = match.captured(1).size();
        QStringList body;
        for (qsizetype k = i + 1; k < lines.size(); ++k) {
            const qsizetype hashes = lines[k].indexOf(QRegularExpression("[^#]"));
            if (lines[k].startsWith('#') && hashes > 0 && hashes <= level)
                break;
            body << lines[k];
        }
        return body.join('\n').trimmed();
    }
    return {};
}

TemplateHelpPage templateHelpPage(const templates::TemplateManifest& manifest, const templates::TemplateRegistry& registry,
                                  const QString& readme)
{
    TemplateHelpPage page;
    QString& md = page.markdown;
    md = QString("# %1\n\n%2\n\n").arg(text(manifest.id), text(manifest.desc));
    const QString builds = readmeSection(readme, manifest.id);
    md += QObject::tr("## What it builds\n\n%1\n\n")
              .arg(builds.isEmpty() ? QObject::tr("(templates/README.md has no section about this template.)") : builds);
    auto guide = guideOf(manifest, registry);
    if (guide) {
        page.picture = pictureOf(*guide, registry, page.pictureProblem);
        md += page.picture.isNull() ? QObject::tr("*No picture: %1*\n\n").arg(page.pictureProblem)
                                    : QString("![%1](%2)\n\n").arg(QObject::tr("The rig a new instance builds"), kTemplatePictureUrl);
        md += QObject::tr("## Hooks\n\n") + hooksOf(*guide, manifest) + "\n";
    } else {
        page.pictureProblem = text(firstError(guide.diagnostics()));
        md += QObject::tr("*No picture or hooks: a new instance cannot be made (%1).*\n\n").arg(page.pictureProblem);
    }
    for (const auto& [title, parameters] : {std::pair{QObject::tr("Guide parameters"), &manifest.guides},
                                             std::pair{QObject::tr("Options"), &manifest.opts}})
        if (!parameters->empty())
            md += QString("## %1\n\n| name | default | help |\n|---|---|---|\n%2\n").arg(title, parameterRows(*parameters));
    if (!manifest.help.empty())
        md += QString("More: <%1>\n\n").arg(text(manifest.help));
    md += QObject::tr("\nManifest: `%1`\n").arg(text(manifest.file));
    return page;
}

} // namespace rs::app
