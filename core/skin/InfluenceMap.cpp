// Resolving imported chunks' influences onto the rig's skin joints: see
// skin/InfluenceMap.h for the rules.
#include "skin/InfluenceMap.h"

#include <algorithm>
#include <optional>
#include <set>

namespace rs::skin {

const char* missingInfluencesName(MissingInfluences rule)
{
    switch (rule) {
    case MissingInfluences::Stop: return "stop";
    case MissingInfluences::Map: return "map";
    case MissingInfluences::Create: return "create";
    }
    return "stop";
}

std::optional<MissingInfluences> parseMissingInfluences(const std::string& name)
{
    if (name == "stop")
        return MissingInfluences::Stop;
    if (name == "map")
        return MissingInfluences::Map;
    if (name == "create")
        return MissingInfluences::Create;
    return std::nullopt;
}

std::size_t InfluenceResolution::count(InfluenceMatch::How how) const
{
    return std::size_t(std::count_if(matches.begin(), matches.end(), [&](const InfluenceMatch& m) { return m.how == how; }));
}

namespace {

using How = InfluenceMatch::How;

struct Lookup {
    std::map<NodeKey, std::int32_t> byKey;
    std::map<std::string, std::int32_t> byName;
    const InfluenceMapOptions* options = nullptr;
    std::int32_t root = 0;
    std::vector<std::string> mapUsed; // map entries rule 3 took

    // Rules 1-3 for one influence.
    std::optional<std::pair<std::int32_t, How>> direct(const ChunkJoint& joint, const NodeKey& key)
    {
        if (auto it = byKey.find(key); it != byKey.end())
            return std::pair(it->second, How::Identity);
        if (auto it = byName.find(joint.name); it != byName.end() && !joint.name.empty())
            return std::pair(it->second, How::Name);
        if (auto entry = options->names.find(joint.name); entry != options->names.end())
            if (auto it = byName.find(entry->second); it != byName.end()) {
                mapUsed.push_back(entry->first);
                return std::pair(it->second, How::Mapped);
            }
        return std::nullopt;
    }
};

std::vector<bool> weightedJoints(const SkinChunk& c)
{
    std::vector<bool> weighted(c.weights.joints.size(), false);
    for (const model::Influence& i : c.weights.influences)
        if (i.joint < weighted.size() && i.weight > 0.0f)
            weighted[i.joint] = true;
    return weighted;
}

ChunkJoint jointOf(const SkinChunk& c, std::size_t j)
{
    ChunkJoint joint = j < c.joints.size() ? c.joints[j] : ChunkJoint{};
    joint.key = c.weights.joints[j];
    return joint;
}

// One entry per influence name and how; the meshes whose chunks weight it.
void record(std::vector<InfluenceMatch>& matches, How how, const std::string& name, const std::string& target, const std::string& mesh,
            bool weighted = true)
{
    auto it = std::find_if(matches.begin(), matches.end(), [&](const InfluenceMatch& m) { return m.name == name && m.how == how; });
    if (it == matches.end())
        it = matches.insert(matches.end(), InfluenceMatch{how, name, target, {}});
    if (weighted && how != How::Unused && std::find(it->meshes.begin(), it->meshes.end(), mesh) == it->meshes.end())
        it->meshes.push_back(mesh);
}

// Rule 4 under Create: the nearest ancestor rules 1-3 match, else the root.
std::pair<std::int32_t, bool> rehome(const SkinChunk& c, std::size_t j, Lookup& lookup)
{
    std::int32_t at = j < c.weights.parents.size() ? c.weights.parents[j] : -1;
    for (std::size_t guard = 0; at >= 0 && guard <= c.weights.joints.size(); ++guard) {
        if (auto found = lookup.direct(jointOf(c, std::size_t(at)), c.weights.joints[std::size_t(at)]))
            return {found->first, true};
        at = std::size_t(at) < c.weights.parents.size() ? c.weights.parents[std::size_t(at)] : -1;
    }
    return {lookup.root, false};
}

std::string meshList(const std::vector<std::string>& meshes)
{
    std::string out;
    for (std::size_t m = 0; m < meshes.size(); ++m)
        out += (m ? ", '" : "'") + meshes[m] + "'";
    return out;
}

Diagnostics missingErrors(const std::vector<InfluenceMatch>& missing, MissingInfluences rule)
{
    Diagnostics errors;
    for (const InfluenceMatch& m : missing)
        errors.push_back(makeError({}, "influence '" + m.name + "' (weighting mesh" + (m.meshes.size() > 1 ? "es " : " ") +
                                           meshList(m.meshes) + ") is not a skin joint of the rig" +
                                           (rule == MissingInfluences::Map ? " and the name map does not name it"
                                                                           : "; map it to one by name, or create it as a joint under "
                                                                             "its matched parent (missing influences: create)")));
    return errors;
}

} // namespace

namespace {

// One chunk's influences: targets, matches, the missing ones and notes.
void resolveChunk(const SkinChunk& c, Lookup& lookup, const std::vector<std::string>& boneNames, InfluenceResolution& out,
                  std::vector<InfluenceMatch>& missing, Diagnostics& problems)
{
    const std::vector<bool> weighted = weightedJoints(c);
    std::vector<std::int32_t>& target = out.target.emplace_back(c.weights.joints.size(), -1);
    for (std::size_t j = 0; j < c.weights.joints.size(); ++j) {
        const ChunkJoint joint = jointOf(c, j);
        if (auto found = lookup.direct(joint, joint.key)) {
            target[j] = found->first;
            record(out.matches, found->second, joint.name, boneNames[std::size_t(found->first)], c.mesh, weighted[j]);
        } else if (!weighted[j]) {
            record(out.matches, How::Unused, joint.name, "", c.mesh);
        } else if (lookup.options->missing == MissingInfluences::Create) {
            const auto [bone, ancestor] = rehome(c, j, lookup);
            target[j] = bone;
            record(out.matches, How::Created, joint.name, boneNames[std::size_t(bone)], c.mesh);
            problems.push_back(makeWarning({}, "mesh '" + c.mesh + "': influence '" + joint.name + "' is not a skin joint of the rig; its weights go to " +
                                                   (ancestor ? "its ancestor '" : "the skeleton's root '") + boneNames[std::size_t(bone)] + "'"));
        } else {
            record(missing, How::Created, joint.name, "", c.mesh);
        }
    }
}

Lookup lookupOf(const std::vector<SkinBone>& bones, const std::vector<std::string>& boneNames, const InfluenceMapOptions& options)
{
    Lookup lookup;
    lookup.options = &options;
    for (std::int32_t b = std::int32_t(bones.size()) - 1; b >= 0; --b) {
        lookup.byKey[bones[std::size_t(b)].key] = b;
        lookup.byName[boneNames[std::size_t(b)]] = b;
        if (bones[std::size_t(b)].parent < 0)
            lookup.root = b;
    }
    return lookup;
}

} // namespace

Result<InfluenceResolution> resolveInfluences(const std::vector<SkinChunk>& chunks, const std::vector<SkinBone>& bones,
                                              const std::vector<std::string>& boneNames, const InfluenceMapOptions& options)
{
    if (bones.empty() || boneNames.size() != bones.size())
        return Result<InfluenceResolution>::refused("the rig has no skin joint to import weights onto");
    Lookup lookup = lookupOf(bones, boneNames, options);
    Diagnostics problems;
    for (const auto& [from, to] : options.names)
        if (!lookup.byName.count(to))
            problems.push_back(makeError({}, "the name map sends '" + from + "' to '" + to + "', which is not a skin joint of the rig"));
    InfluenceResolution out;
    std::vector<InfluenceMatch> missing;
    for (const SkinChunk& c : chunks)
        resolveChunk(c, lookup, boneNames, out, missing, problems);
    std::set<std::string> placed; // an influence is unused only when no chunk weights it
    for (const InfluenceMatch& m : out.matches)
        if (m.how != How::Unused)
            placed.insert(m.name);
    std::erase_if(out.matches, [&](const InfluenceMatch& m) { return m.how == How::Unused && placed.count(m.name); });
    for (const auto& entry : options.names)
        if (std::find(lookup.mapUsed.begin(), lookup.mapUsed.end(), entry.first) == lookup.mapUsed.end())
            problems.push_back(makeWarning({}, "the name map's entry for '" + entry.first + "' is not needed: no chunk has a missing influence of that name"));
    Diagnostics errors = missingErrors(missing, options.missing);
    problems.insert(problems.end(), errors.begin(), errors.end());
    if (hasErrors(problems))
        return Result<InfluenceResolution>::failure(std::move(problems));
    return Result<InfluenceResolution>(std::move(out), std::move(problems));
}

std::vector<InfluenceMatch> missingInfluences(const std::vector<SkinChunk>& chunks, const std::vector<SkinBone>& bones,
                                              const std::vector<std::string>& boneNames, const InfluenceMapOptions& options)
{
    if (bones.empty() || boneNames.size() != bones.size())
        return {};
    InfluenceMapOptions stop = options;
    stop.missing = MissingInfluences::Stop; // rule 4 lists them instead of re-homing
    Lookup lookup = lookupOf(bones, boneNames, stop);
    InfluenceResolution placed;
    std::vector<InfluenceMatch> missing;
    Diagnostics notes;
    for (const SkinChunk& c : chunks)
        resolveChunk(c, lookup, boneNames, placed, missing, notes);
    return missing;
}

namespace {

bool alreadyOnBones(const SkinChunk& c, const std::vector<std::int32_t>& target, const std::vector<SkinBone>& bones)
{
    if (c.weights.joints.size() != bones.size() || c.weights.parents.size() != bones.size())
        return false;
    for (std::size_t b = 0; b < bones.size(); ++b)
        if (c.weights.joints[b] != bones[b].key || c.weights.parents[b] != bones[b].parent || target[b] != std::int32_t(b))
            return false;
    return true;
}

model::MeshWeights moved(const model::MeshWeights& weights, const std::vector<std::int32_t>& target, const std::vector<SkinBone>& bones)
{
    model::MeshWeights out;
    for (const SkinBone& bone : bones) {
        out.joints.push_back(bone.key);
        out.parents.push_back(bone.parent);
    }
    out.offsets.push_back(0);
    for (std::size_t v = 0; v < weights.vertexCount(); ++v) {
        const std::size_t first = out.influences.size();
        for (const model::Influence* i = weights.begin(v); i != weights.end(v); ++i) {
            const std::int32_t to = i->joint < target.size() ? target[i->joint] : -1;
            if (to < 0 || !(i->weight > 0.0f))
                continue;
            auto same = std::find_if(out.influences.begin() + std::ptrdiff_t(first), out.influences.end(),
                                     [&](const model::Influence& m) { return m.joint == std::uint32_t(to); });
            if (same != out.influences.end())
                same->weight += i->weight;
            else
                out.influences.push_back({std::uint32_t(to), i->weight});
        }
        out.offsets.push_back(std::uint32_t(out.influences.size()));
    }
    return out;
}

} // namespace

std::vector<SkinChunk> applyInfluences(std::vector<SkinChunk> chunks, const InfluenceResolution& resolution,
                                       const std::vector<SkinBone>& bones, const std::vector<std::string>& boneNames)
{
    for (std::size_t k = 0; k < chunks.size() && k < resolution.target.size(); ++k) {
        SkinChunk& c = chunks[k];
        const std::vector<std::int32_t>& target = resolution.target[k];
        if (alreadyOnBones(c, target, bones))
            continue;
        std::vector<ChunkJoint> joints(bones.size());
        for (std::size_t b = 0; b < bones.size(); ++b) {
            joints[b].key = bones[b].key;
            joints[b].name = boneNames[b];
        }
        for (std::size_t j = c.joints.size(); j-- > 0;) // matrices: the chunk's joint of that key, else one landing there
            if (j < target.size() && target[j] >= 0 && (c.joints[j].key == bones[std::size_t(target[j])].key ||
                                                         joints[std::size_t(target[j])].world == Mat4(1.0)))
                joints[std::size_t(target[j])] = ChunkJoint{bones[std::size_t(target[j])].key, boneNames[std::size_t(target[j])],
                                                            c.joints[j].world, c.joints[j].local, c.joints[j].bind};
        c.weights = moved(c.weights, target, bones);
        c.joints = std::move(joints);
    }
    return chunks;
}

} // namespace rs::skin
