// Control sizes relative to the character. A manifest's shape `size` is in
// metres for a guide of the template's default proportions (the joints its
// builder proposes for a new instance). Each instance's shapes are scaled by
// how much larger its guide is than that default: the mean length of its
// segments (each guide joint to its parent joint in the instance) over the
// default guide's. So the shapes of a giant's arm, a child's fingers or a rig
// modelled in centimetres fit the character without editing a single size; a
// chain with more joints of the same spacing keeps its sizes; a mirrored copy
// gets its twin's scale.
//
// A segment to a guide joint tagged `target` (a camera's aim target) or `axis`
// (a wheel's axle, offset from its steering pivot) is not measured: how far
// away a rigger puts what something looks at, or how far inboard a wheel
// steers, says nothing of the character's size (a wheel measures its radius).
//
// An instance whose segments say nothing (a single joint, or joints on one
// point: a world, a COG, a camera) takes the scale of the nearest ancestor
// that has one; a root with none takes the median of the whole guide's (the
// character's); a guide with none keeps 1.
#include "rigging/RigAssembly.h"
#include "rigging/RigBuilder.h"

#include <algorithm>

namespace rs::rigging {

namespace {

constexpr double kMinLength = 1e-6; // metres: below it a mean segment says nothing

// Whether the segment to a guide joint with these tags says nothing of size (see above).
bool unmeasured(const std::vector<std::string>& tags)
{
    return std::any_of(tags.begin(), tags.end(), [](const std::string& tag) { return tag == "target" || tag == "axis"; });
}

// The mean segment length of the joints the builder proposes for a new instance (its default guide).
double defaultSegment(const templates::TemplateManifest& manifest, const BuilderRegistry& builders)
{
    std::map<std::string, Value> guideValues;
    for (const auto& p : manifest.guides)
        guideValues[p.name] = p.value;
    Diagnostics ignored; // the gather stage reports an unresolved builder
    const auto specs = builders.resolve(manifest, ignored).createGuide(manifest, guideValues);
    std::vector<Mat4> world;
    double sum = 0.0;
    int count = 0;
    for (const GuideJointSpec& spec : specs) {
        const bool inside = spec.parent >= 0 && std::size_t(spec.parent) < world.size();
        world.push_back((inside ? world[spec.parent] : Mat4(1.0)) * spec.local.matrix());
        if (inside && !unmeasured(spec.tags)) {
            sum += glm::length(translationOf(world.back()) - translationOf(world[spec.parent]));
            ++count;
        }
    }
    return count ? sum / count : 0.0;
}

// The mean length of an instance's segments as its guide places them now.
double segmentOf(const RigAssembly& a, const model::TemplateInstance& instance)
{
    std::unordered_map<model::JointId, Vec3> at;
    for (const auto& joint : instance.joints)
        at[joint.id] = translationOf(a.guideWorldMatrix(joint.id));
    double sum = 0.0;
    int count = 0;
    for (const auto& joint : instance.joints)
        if (auto parent = at.find(joint.parent); parent != at.end() && !unmeasured(joint.tags)) {
            sum += glm::length(at[joint.id] - parent->second);
            ++count;
        }
    return count ? sum / count : 0.0;
}

} // namespace

void computeControlScales(RigAssembly& a, const BuilderRegistry& builders, std::map<std::string, double>* defaultSegments)
{
    std::map<std::string, double> local;
    std::map<std::string, double>& defaults = defaultSegments ? *defaultSegments : local;
    std::unordered_map<model::InstanceId, double> measured;
    std::vector<double> all;
    for (const InstanceRecord& r : a.records) {
        const model::TemplateInstance& instance = *r.instance;
        if (instance.joints.size() < 2)
            continue;
        auto found = defaults.find(instance.templateId);
        if (found == defaults.end())
            found = defaults.emplace(instance.templateId, defaultSegment(*r.manifest, builders)).first;
        if (found->second < kMinLength)
            continue;
        const double segment = segmentOf(a, instance);
        if (segment < kMinLength)
            continue;
        measured[instance.id] = segment / found->second;
        all.push_back(segment / found->second);
    }
    double character = 1.0;
    if (!all.empty()) {
        std::nth_element(all.begin(), all.begin() + all.size() / 2, all.end());
        character = all[all.size() / 2];
    }
    a.controlScales.clear();
    for (const InstanceRecord& r : a.records) {
        double scale = character;
        for (const model::TemplateInstance* at = r.instance; at; at = at->parent == model::kNoId ? nullptr : a.guide.instance(at->parent))
            if (auto it = measured.find(at->id); it != measured.end()) {
                scale = it->second;
                break;
            }
        a.controlScales[r.instance->id] = scale;
    }
}

double RigAssembly::controlScaleOf(model::InstanceId expandedInstance) const
{
    auto it = controlScales.find(expandedInstance);
    return it == controlScales.end() ? 1.0 : it->second;
}

} // namespace rs::rigging
