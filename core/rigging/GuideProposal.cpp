// Guide phase: new template instances with their proposed guide joints, and
// an instance's joints proposed again when a guide parameter changes.
#include "rigging/RigBuilder.h"

#include <cmath>
#include <map>

namespace rs::rigging {

using model::JointId;

Result<model::TemplateInstance> makeInstance(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                                             const std::string& templateId, JointId parentJoint,
                                             const BuilderRegistry& builders)
{
    return makeInstance(guide, templates, templateId, parentJoint, {}, builders);
}

Result<model::TemplateInstance> makeInstance(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                                             const std::string& templateId, JointId parentJoint,
                                             const std::map<std::string, Value>& options, const BuilderRegistry& builders)
{
    const templates::TemplateManifest* manifest = templates.find(templateId);
    if (!manifest)
        return Result<model::TemplateInstance>::failure(makeError({}, "unknown template '" + templateId + "'"));
    model::TemplateInstance instance;
    instance.id = guide.nextInstanceId();
    instance.templateId = templateId;
    instance.name = guide.uniqueName(manifest->name.empty() ? manifest->module : manifest->name);
    if (parentJoint != model::kNoId) {
        const model::TemplateInstance* parent = guide.ownerOf(parentJoint);
        if (!parent)
            return Result<model::TemplateInstance>::refused("the hook joint does not exist", Subject::ofJoint(model::kNoId, parentJoint));
        instance.parent = parent->id;
        instance.parentJoint = parentJoint;
    }
    instance.options = options;
    Diagnostics diagnostics;
    const auto values = resolveOptions(*manifest, instance, diagnostics);
    for (const auto& [name, value] : options)
        if (!values.count(name) && !manifest->findByOtherName(name))
            return Result<model::TemplateInstance>::failure(makeError({}, templateId + " has no option '" + name + "'"));
    std::map<std::string, Value> guideValues;
    for (const auto& p : manifest->guides)
        guideValues[p.name] = values.at(p.name);
    const auto specs = builders.resolve(*manifest, diagnostics).createGuide(*manifest, guideValues);
    if (specs.empty())
        return Result<model::TemplateInstance>::failure(makeError({}, templateId + " proposed no guide joints"));
    JointId next = guide.nextJointId();
    const JointId first = next;
    for (const GuideJointSpec& spec : specs) {
        model::GuideJoint joint;
        joint.id = next++;
        joint.parent = spec.parent < 0 ? model::kNoId : first + JointId(spec.parent);
        joint.local = spec.local;
        for (int axis = 0; axis < 3; ++axis) // proposals are to the micrometre: clean, diffable files
            joint.local.translate[axis] = std::round(joint.local.translate[axis] * 1e6) / 1e6 + 0.0;
        joint.tags = spec.tags;
        joint.name = spec.name;
        instance.joints.push_back(std::move(joint));
    }
    return Result<model::TemplateInstance>(std::move(instance), std::move(diagnostics));
}

namespace {

std::string jointSignature(const model::GuideJoint& joint)
{
    std::string out = joint.name;
    for (const auto& tag : joint.tags)
        out += "|" + tag;
    return out;
}

// For each new joint, the old joint it continues (-1: a new joint). Named or
// tagged joints match by name and tags; the plain chain joints match in order,
// and the last with the last, so the tip (a chest, a hand) stays the tip.
std::vector<int> matchJoints(const std::vector<model::GuideJoint>& old, const std::vector<model::GuideJoint>& fresh)
{
    std::vector<int> match(fresh.size(), -1);
    std::vector<bool> used(old.size(), false);
    std::vector<int> plainOld, plainNew;
    for (std::size_t k = 0; k < old.size(); ++k)
        if (jointSignature(old[k]).empty())
            plainOld.push_back(int(k));
    for (std::size_t k = 0; k < fresh.size(); ++k) {
        const std::string signature = jointSignature(fresh[k]);
        if (signature.empty()) {
            plainNew.push_back(int(k));
            continue;
        }
        for (std::size_t o = 0; o < old.size(); ++o)
            if (!used[o] && jointSignature(old[o]) == signature) {
                match[k] = int(o);
                used[o] = true;
                break;
            }
    }
    const std::size_t n = std::min(plainOld.size(), plainNew.size());
    for (std::size_t i = 0; i + 1 < n; ++i)
        match[std::size_t(plainNew[i])] = plainOld[i];
    if (n > 0)
        match[std::size_t(plainNew.back())] = plainOld.back();
    return match;
}

} // namespace

Result<model::TemplateInstance> regenerateGuide(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                                                model::InstanceId id, const std::map<std::string, Value>& options,
                                                const BuilderRegistry& builders)
{
    const model::TemplateInstance* old = guide.instance(id);
    if (!old)
        return Result<model::TemplateInstance>::refused("no instance with id " + std::to_string(id), Subject::ofInstance(id));
    auto made = makeInstance(guide, templates, old->templateId, model::kNoId, options, builders);
    if (!made) { // refused options are this instance's
        Diagnostics diagnostics = made.takeDiagnostics();
        for (Diagnostic& d : diagnostics)
            if (d.subject.isNone()) d.subject = Subject::ofInstance(id);
        return Result<model::TemplateInstance>::failure(std::move(diagnostics));
    }
    model::TemplateInstance fresh = made.take();
    const std::vector<int> match = matchJoints(old->joints, fresh.joints);
    std::map<JointId, std::size_t> freshIndex;
    for (std::size_t k = 0; k < fresh.joints.size(); ++k)
        freshIndex[fresh.joints[k].id] = k;
    // Matched joints keep their id, rotation and scale, and their world position.
    const Mat4 base = guide.jointWorldMatrix(old->joints.front().id) * glm::inverse(old->joints.front().local.matrix());
    std::vector<Mat4> world(fresh.joints.size());
    std::vector<JointId> ids(fresh.joints.size());
    for (std::size_t k = 0; k < fresh.joints.size(); ++k)
        ids[k] = match[k] >= 0 ? old->joints[std::size_t(match[k])].id : fresh.joints[k].id;
    for (std::size_t k = 0; k < fresh.joints.size(); ++k) {
        auto& joint = fresh.joints[k];
        const bool root = joint.parent == model::kNoId;
        const Mat4 parentWorld = root ? base : world[freshIndex.at(joint.parent)];
        if (!root)
            joint.parent = ids[freshIndex.at(joint.parent)];
        if (match[k] >= 0) {
            const model::GuideJoint& before = old->joints[std::size_t(match[k])];
            joint.local = before.local;
            const Vec3 position = translationOf(guide.jointWorldMatrix(before.id));
            joint.local.translate = Vec3(glm::inverse(parentWorld) * Vec4(position, 1.0));
        }
        joint.id = ids[k];
        world[k] = parentWorld * joint.local.matrix();
    }
    model::TemplateInstance out = *old; // everything else stays as the rigger set it
    out.options = std::move(fresh.options);
    out.joints = std::move(fresh.joints);
    return out;
}

} // namespace rs::rigging
