// "Missing influences: create": see session/CreateInfluences.h.
#include "session/CreateInfluences.h"

#include "edit/GuideEdits.h"
#include "edit/GuideMove.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

namespace rs::session {

namespace {

constexpr const char* kJointTemplate = "core.joints";
constexpr const char* kSkinTag = "skin.0"; // the skin joint of a one-joint chain

// The first chunk weighting influence `name`, and the joint's index in it.
std::pair<const skin::SkinChunk*, std::size_t> weighting(const std::vector<skin::SkinChunk>& chunks, const std::string& name)
{
    for (const skin::SkinChunk& c : chunks)
        for (std::size_t j = 0; j < c.joints.size() && j < c.weights.joints.size(); ++j)
            if (c.joints[j].name == name)
                for (const model::Influence& i : c.weights.influences)
                    if (i.joint == j && i.weight > 0.0f)
                        return {&c, j};
    return {nullptr, 0};
}

std::size_t depthOf(const skin::SkinChunk& c, std::size_t j)
{
    std::size_t depth = 0;
    for (std::int32_t at = c.weights.parents[j]; at >= 0 && depth <= c.weights.parents.size(); at = c.weights.parents[std::size_t(at)])
        ++depth;
    return depth;
}

// A valid, document-unique instance name from an influence name ("sk_ear_L" -> "ear_L").
std::string instanceNameFor(std::string name, const model::NamingRules& naming, const model::GuideDocument& document,
                            const std::vector<model::TemplateInstance>& planned)
{
    if (!naming.suffixes && name.rfind(naming.skin, 0) == 0 && name.size() > naming.skin.size())
        name = name.substr(naming.skin.size());
    if (naming.suffixes && name.size() > naming.skin.size() && name.compare(name.size() - naming.skin.size(), naming.skin.size(), naming.skin) == 0)
        name.resize(name.size() - naming.skin.size());
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch)))
            ch = '_';
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front())))
        name = "joint_" + name;
    auto taken = [&](const std::string& n) {
        return document.instanceNamed(n) || std::any_of(planned.begin(), planned.end(), [&](const model::TemplateInstance& i) { return i.name == n; });
    };
    std::string out = document.uniqueName(name);
    for (int k = 1; taken(out); ++k)
        out = name + std::to_string(k);
    return out;
}

Mat4 mirroredX(const Mat4& m)
{
    Mat4 flip(1.0);
    flip[0][0] = -1.0;
    return flip * m * flip;
}

} // namespace

Result<CreatedInfluences> planCreatedInfluences(const model::GuideDocument& guide, const model::Rig& rig,
                                                const templates::TemplateRegistry& templates, const std::vector<skin::SkinChunk>& chunks,
                                                const skin::InfluenceMapOptions& influences, std::vector<skin::SkinBone>& bones,
                                                std::vector<std::string>& names)
{
    using Out = Result<CreatedInfluences>;
    CreatedInfluences job;
    Diagnostics notes;
    std::vector<skin::InfluenceMatch> missing = skin::missingInfluences(chunks, bones, names, influences);
    if (missing.empty())
        return job;
    if (!templates.find(kJointTemplate))
        return Out::refused(std::string("missing influences: create needs the ") + kJointTemplate + " template, which the library does not have");
    struct Item {
        std::string name;
        const skin::SkinChunk* chunk;
        std::size_t joint;
    };
    std::vector<Item> items;
    for (const skin::InfluenceMatch& m : missing)
        if (auto [c, j] = weighting(chunks, m.name); c)
            items.push_back({m.name, c, j});
    std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return depthOf(*a.chunk, a.joint) < depthOf(*b.chunk, b.joint); });

    // Rules 1-3 of skin/InfluenceMap.h for one chunk joint, on the bones so far (created ones included).
    auto boneOf = [&](const skin::SkinChunk& c, std::size_t j) -> std::int32_t {
        const std::string name = j < c.joints.size() ? c.joints[j].name : std::string();
        for (std::size_t b = 0; b < bones.size(); ++b)
            if (bones[b].key == c.weights.joints[j] || (!name.empty() && names[b] == name))
                return std::int32_t(b);
        if (auto mapped = influences.names.find(name); mapped != influences.names.end())
            for (std::size_t b = 0; b < bones.size(); ++b)
                if (names[b] == mapped->second)
                    return std::int32_t(b);
        return -1;
    };
    std::map<std::size_t, JointId> createdJoint; // created bone -> its guide joint
    std::map<JointId, Mat4> plannedWorld;        // created guide joint -> world
    model::InstanceId nextInstance = guide.nextInstanceId();
    JointId nextJoint = guide.nextJointId();
    for (const Item& item : items) {
        const skin::SkinChunk& c = *item.chunk;
        std::int32_t parent = -1;
        for (std::int32_t at = c.weights.parents[item.joint]; at >= 0 && parent < 0; at = c.weights.parents[std::size_t(at)])
            parent = boneOf(c, std::size_t(at));
        if (parent < 0) // no ancestor matched: the skeleton's root
            for (std::size_t b = 0; b < bones.size() && parent < 0; ++b)
                if (bones[b].parent < 0)
                    parent = std::int32_t(b);
        const skin::SkinBone above = bones[std::size_t(parent)]; // bones grows below
        JointId hook = model::kNoId;
        Mat4 hookWorld(1.0), world = c.joints[item.joint].bind;
        if (auto it = createdJoint.find(std::size_t(parent)); it != createdJoint.end()) {
            hook = it->second;
            hookWorld = plannedWorld[hook];
        } else {
            const model::RigNode& node = rig.nodes[above.node];
            hook = node.guide;
            if (hook == model::kNoId)
                if (const model::TemplateInstance* owner = guide.instance(node.owner); owner && !owner->joints.empty())
                    hook = owner->joints.front().id;
            if (hook == model::kNoId || !guide.joint(hook))
                return Out::refused("missing influences: create: influence '" + item.name + "' would hang under skin joint '" +
                                       names[std::size_t(parent)] + "', which no guide joint makes; map it to a joint instead");
            hookWorld = guide.jointWorldMatrix(hook);
            // A mirrored branch copy of the hook: place the joint on the authored side.
            const double authoredX = translationOf(hookWorld).x, copyX = translationOf(node.worldMatrix).x;
            if (!above.key.branch.empty() && authoredX * copyX < 0.0 && std::abs(authoredX - copyX) > 1e-6)
                world = mirroredX(world);
        }
        std::string override = item.name; // the skin joint's name; a branch copy adds its side
        const std::string side = guide.naming.side + [&] {
            std::string b = above.key.branch;
            std::replace(b.begin(), b.end(), '.', '_');
            return b;
        }();
        if (!above.key.branch.empty() && override.size() > side.size() && override.compare(override.size() - side.size(), side.size(), side) == 0)
            override.resize(override.size() - side.size());
        const std::string boneName = above.key.branch.empty() ? override : override + side;
        // One instance per hook and name: the other side of a branched parent reuses it.
        model::InstanceId id = model::kNoId;
        for (const model::TemplateInstance& planned : job.instances)
            if (planned.parentJoint == hook && planned.names.at(kSkinTag) == override)
                id = planned.id;
        if (id == model::kNoId) {
            model::TemplateInstance instance;
            instance.id = id = nextInstance++;
            instance.templateId = kJointTemplate;
            instance.name = instanceNameFor(override, guide.naming, guide, job.instances);
            instance.parentJoint = hook;
            const model::TemplateInstance* owner = guide.ownerOf(hook);
            for (const model::TemplateInstance& planned : job.instances)
                if (!planned.joints.empty() && planned.joints.front().id == hook)
                    owner = &planned;
            instance.parent = owner ? owner->id : model::kNoId;
            instance.options["number"] = Value(static_cast<long long>(1));
            instance.names[kSkinTag] = override;
            model::GuideJoint joint;
            joint.id = nextJoint++;
            joint.local = edit::localTransformOf(glm::inverse(hookWorld) * world);
            instance.joints.push_back(joint);
            plannedWorld[joint.id] = world;
            job.instances.push_back(std::move(instance));
        }
        const NodeKey key{id, above.key.branch, kSkinTag};
        skin::SkinBone bone;
        bone.key = key;
        bone.parent = parent;
        bone.head = translationOf(world);
        bones.push_back(bone);
        names.push_back(boneName);
        for (const model::TemplateInstance& planned : job.instances)
            if (planned.id == id)
                createdJoint[bones.size() - 1] = planned.joints.front().id;
        job.influences.push_back({item.name, id, key, boneName, names[std::size_t(parent)]});
        notes.push_back(Diagnostic{Severity::Note, {}, "influence '" + item.name + "' is created: skin joint '" + boneName + "' under '" +
                                             names[std::size_t(parent)] + "' (a " + kJointTemplate + " instance '" +
                                             [&] {
                                                 for (const model::TemplateInstance& i : job.instances)
                                                     if (i.id == id)
                                                         return i.name;
                                                 return std::string();
                                             }() + "'), at its bind position", Subject::ofInstance(id)});
    }
    return Out(std::move(job), std::move(notes));
}

Status addCreatedInstances(edit::History& history, const CreatedInfluences& created)
{
    for (const model::TemplateInstance& instance : created.instances) {
        const model::GuideDocument& guide = history.document();
        if (guide.instance(instance.id) || !guide.joint(instance.parentJoint) ||
            std::any_of(instance.joints.begin(), instance.joints.end(), [&](const model::GuideJoint& j) { return guide.joint(j.id) != nullptr; }))
            return Status::refused("the guide changed since the import was prepared; nothing changed: import again");
        if (Status added = edit::addInstance(history, instance); added.failed())
            return added;
    }
    return Status::success();
}

skin::InfluenceMapOptions rulesWithCreated(const skin::InfluenceMapOptions& influences, const CreatedInfluences& created)
{
    skin::InfluenceMapOptions rules = influences;
    rules.missing = skin::MissingInfluences::Stop;
    for (const CreatedInfluence& c : created.influences)
        if (c.boneName != c.influence)
            rules.names[c.influence] = c.boneName;
    return rules;
}

void markCreated(skin::InfluenceResolution& resolution, const CreatedInfluences& created)
{
    for (skin::InfluenceMatch& m : resolution.matches)
        if (std::any_of(created.influences.begin(), created.influences.end(), [&](const CreatedInfluence& c) { return c.influence == m.name; }))
            m.how = skin::InfluenceMatch::How::Created;
}

} // namespace rs::session
