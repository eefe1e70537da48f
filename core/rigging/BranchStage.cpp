#include "rigging/BranchStage.h"

#include "base/TextScalars.h"

#include <algorithm>
#include <optional>

namespace rs::rigging {

namespace {

using model::InstanceId;
using model::JointId;
using model::TemplateInstance;

// The plane a two-branch list mirrors across: 0 x, 1 y, 2 z; -1 when unknown.
int pairPlane(const std::vector<std::string>& b)
{
    static const std::vector<std::pair<std::pair<std::string, std::string>, int>> pairs = {
        {{"L", "R"}, 0}, {{"l", "r"}, 0}, {{"ex", "in"}, 0}, {{"ext", "int"}, 0},
        {{"up", "dn"}, 1}, {{"ft", "bk"}, 2}};
    for (const auto& [names, plane] : pairs)
        if (b.size() == 2 && b[0] == names.first && b[1] == names.second)
            return plane;
    return -1;
}

std::string optionText(const TemplateInstance& instance, const templates::TemplateManifest* manifest, const std::string& name)
{
    if (auto it = instance.options.find(name); it != instance.options.end())
        return formatValue(it->second);
    if (manifest)
        if (const auto* p = manifest->findOpt(name))
            return formatValue(p->value);
    return {};
}

// Removes every repeat of a branch name (the first stays, in order); returns
// the first name that was repeated.
std::optional<std::string> dropRepeatedBranches(std::vector<std::string>& branches)
{
    std::optional<std::string> repeated;
    std::vector<std::string> kept;
    for (std::string& branch : branches) {
        if (std::find(kept.begin(), kept.end(), branch) == kept.end())
            kept.push_back(std::move(branch));
        else if (!repeated)
            repeated = branch;
    }
    branches = std::move(kept);
    return repeated;
}

struct Context { // one copy of an authored instance
    InstanceId expandedId;
    std::unordered_map<JointId, JointId> joints; // authored -> expanded
    std::string id, suffix;
    bool flip = false;
    Mat4 mirror{1.0};
};

} // namespace

ExpandedGuide expandBranches(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                             Diagnostics& diagnostics)
{
    ExpandedGuide out;
    out.document.name = guide.name;
    out.document.naming = guide.naming;
    std::unordered_map<InstanceId, std::vector<Context>> contexts; // authored instance -> its copies
    InstanceId nextInstance = guide.nextInstanceId();
    JointId nextJoint = guide.nextJointId();

    for (const TemplateInstance& authored : guide.instances()) {
        const auto* manifest = templates.find(authored.templateId);
        std::vector<std::string> branches;
        if (manifest && manifest->findOpt("branches")) {
            const std::string text = optionText(authored, manifest, "branches");
            if (auto list = parseFlowList(text)) {
                branches = list.take();
                if (const auto duplicate = dropRepeatedBranches(branches)) {
                    // One error here, rather than one per node and name the second copy would clash on.
                    diagnostics.push_back(makeError({}, "instance '" + authored.name + "': option 'branches' = '" + text +
                                                            "' names branch '" + *duplicate + "' twice; each branch is built once"));
                    diagnostics.back().subject = Subject::ofInstance(authored.id);
                }
            } else {
                diagnostics.push_back(makeWarning({}, "instance '" + authored.name + "': option 'branches' = '" + text +
                                                          "' is not a YAML list (" + firstError(list.diagnostics()) + "); built once"));
                diagnostics.back().subject = Subject::ofInstance(authored.id);
            }
        }
        int plane = -1;
        if (branches.size() == 2) {
            const std::string sym = optionText(authored, manifest, "sym");
            plane = sym == "x" ? 0 : sym == "y" ? 1 : sym == "z" ? 2 : pairPlane(branches);
            if (plane < 0) plane = 0;
        }
        // Parent copies: one per branch of the parent (an unbranched parent has one).
        std::vector<const Context*> parents{nullptr};
        if (authored.parent != model::kNoId && contexts.count(authored.parent)) {
            parents.clear();
            for (const Context& c : contexts[authored.parent]) parents.push_back(&c);
        }
        const std::vector<std::string> own = branches.empty() ? std::vector<std::string>{""} : branches;
        InstanceId twin = model::kNoId;
        for (const Context* parent : parents)
            for (std::size_t b = 0; b < own.size(); ++b) {
                Context c;
                c.id = (parent ? parent->id : "") + (own[b].empty() ? "" : "." + own[b]);
                c.suffix = (parent ? parent->suffix : "") + (own[b].empty() ? "" : "_" + own[b]);
                c.flip = (parent && parent->flip) != (plane >= 0 && b == 1);
                c.mirror = parent ? parent->mirror : Mat4(1.0);
                if (plane >= 0 && b == 1) {
                    Mat4 reflect(1.0);
                    reflect[plane][plane] = -1.0;
                    c.mirror = c.mirror * reflect;
                }
                const bool first = twin == model::kNoId && (!parent || parent->expandedId == authored.parent);
                TemplateInstance copy = authored;
                copy.id = first ? authored.id : nextInstance++;
                copy.name = authored.name + c.id;
                c.expandedId = copy.id;
                if (parent) {
                    copy.parent = parent->expandedId;
                    auto hook = parent->joints.find(authored.parentJoint);
                    copy.parentJoint = hook == parent->joints.end() ? authored.parentJoint : hook->second;
                }
                for (auto& joint : copy.joints) {
                    const JointId authoredId = joint.id;
                    joint.id = first ? authoredId : nextJoint++;
                    c.joints[authoredId] = joint.id;
                    out.original[joint.id] = authoredId;
                }
                for (auto& joint : copy.joints)
                    if (joint.parent != model::kNoId)
                        joint.parent = c.joints[joint.parent];
                if (twin == model::kNoId) twin = copy.id;
                out.copies[copy.id] = {authored.id, twin, authored.name, c.id, c.suffix, c.flip, c.mirror};
                out.document.insertInstance(std::move(copy), out.document.instances().size());
                contexts[authored.id].push_back(std::move(c));
            }
    }
    return out;
}

} // namespace rs::rigging
