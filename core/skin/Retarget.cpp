#include "skin/Retarget.h"

#include <algorithm>
#include <map>

namespace rs::skin {

namespace {

std::string keyText(const NodeKey& key)
{
    return "#" + std::to_string(key.instance) + (key.branch.empty() ? "" : "." + key.branch) + "::" + key.tag;
}

} // namespace

Result<model::MeshWeights> retargetWeights(const model::MeshWeights& weights, const std::vector<SkinBone>& bones,
                                           const std::string& label)
{
    if (bones.empty())
        return Result<model::MeshWeights>::failure(makeError({}, "mesh '" + label + "': the rig has no skin joint for its weights"));
    std::map<NodeKey, std::uint32_t> boneOf;
    std::uint32_t root = 0;
    for (std::uint32_t b = 0; b < bones.size(); ++b) {
        boneOf[bones[b].key] = b;
        if (bones[b].parent < 0 && bones[b].key != bones[root].key && bones[root].parent >= 0)
            root = b;
    }
    Diagnostics notes;
    // Old joint -> new bone, walking up the old skin hierarchy past missing joints.
    std::vector<std::uint32_t> target(weights.joints.size());
    for (std::size_t j = 0; j < weights.joints.size(); ++j) {
        std::int64_t at = std::int64_t(j);
        for (std::size_t guard = 0; at >= 0 && guard <= weights.joints.size(); ++guard) {
            if (auto it = boneOf.find(weights.joints[std::size_t(at)]); it != boneOf.end())
                break;
            at = std::size_t(at) < weights.parents.size() ? weights.parents[std::size_t(at)] : -1;
        }
        auto found = at >= 0 ? boneOf.find(weights.joints[std::size_t(at)]) : boneOf.end();
        target[j] = found != boneOf.end() ? found->second : root;
        if (std::int64_t(j) != at) {
            Diagnostic d = makeWarning({}, "mesh '" + label + "': skin joint " + keyText(weights.joints[j]) + " is gone; its weights go to " +
                                               (found != boneOf.end() ? "its ancestor " : "the skeleton's root ") + keyText(bones[target[j]].key));
            d.subject = Subject::ofInstance(weights.joints[j].instance, weights.joints[j].branch);
            notes.push_back(std::move(d));
        }
    }
    model::MeshWeights out;
    for (const SkinBone& bone : bones) {
        out.joints.push_back(bone.key);
        out.parents.push_back(bone.parent);
    }
    out.offsets.reserve(weights.offsets.size());
    out.offsets.push_back(0);
    std::vector<model::Influence> merged;
    for (std::size_t v = 0; v < weights.vertexCount(); ++v) {
        merged.clear();
        float sum = 0.0f;
        for (const model::Influence* i = weights.begin(v); i != weights.end(v); ++i) {
            const std::uint32_t joint = i->joint < target.size() ? target[i->joint] : root;
            auto same = std::find_if(merged.begin(), merged.end(), [&](const auto& m) { return m.joint == joint; });
            if (same != merged.end())
                same->weight += i->weight;
            else
                merged.push_back({joint, i->weight});
            sum += i->weight;
        }
        if (merged.empty() || !(sum > 0.0f)) {
            merged = {{root, 1.0f}};
            sum = 1.0f;
        }
        std::sort(merged.begin(), merged.end(), [](const auto& a, const auto& b) { return a.weight > b.weight; });
        for (model::Influence& m : merged)
            out.influences.push_back({m.joint, m.weight / sum});
        out.offsets.push_back(std::uint32_t(out.influences.size()));
    }
    return Result<model::MeshWeights>(std::move(out), std::move(notes));
}

} // namespace rs::skin
