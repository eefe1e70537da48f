#include "templates/GuideTemplates.h"

namespace rs::templates {

Diagnostics checkGuideTemplates(const model::GuideDocument& guide, const TemplateRegistry& templates,
                                const std::string& file)
{
    Diagnostics out;
    for (const model::TemplateInstance& instance : guide.instances()) {
        if (templates.find(instance.templateId))
            continue;
        Diagnostic d = makeWarning({file, 0, 0}, "instance '" + instance.name + "': unknown template '" + instance.templateId +
                                                     "' (not in the template folders); the instance is kept but not built, "
                                                     "its children attach above it");
        d.subject = Subject::ofInstance(instance.id);
        out.push_back(std::move(d));
    }
    return out;
}

} // namespace rs::templates
