#include "io/ExportScene.h"

#include "eval/RigProgram.h"
#include "io/ExportCamera.h"
#include "io/ExportCheck.h"
#include "io/ExportMotion.h"
#include "io/HumanoidMap.h"
#include "model/Value.h"
#include "model/Skeleton.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rs::io {

namespace {

bool isIdentity(const Mat4& m) { return maxAbsDifference(m, Mat4(1.0)) < 1e-9; }

// Unreal wants a joint called `root` at the origin above everything: the
// skeleton's own root when it already sits there unrotated, otherwise a new one.
void addUnrealRoot(model::Skeleton& skeleton, std::vector<SkinnedMesh>& meshes)
{
    auto& joints = skeleton.joints;
    if (isIdentity(joints.front().bindWorld)) {
        joints.front().name = "root";
        return;
    }
    model::SkeletonJoint root;
    root.name = "root";
    root.node = model::kNoNode;
    for (auto& joint : joints)
        ++joint.parent;
    joints.front().parent = 0;
    joints.insert(joints.begin(), root);
    for (auto& mesh : meshes)
        for (auto& influence : mesh.influences)
            ++influence.joint;
}

// The Unity preset's humanoid bones (resolved through the guide's instances):
// each one this rig has no deform joint for is a bone Unity's avatar leaves unmapped.
Diagnostics checkUnityMap(const model::Rig& rig, const model::Skeleton& skeleton, const std::vector<HumanoidBone>& bones,
                          bool hasGuide)
{
    std::vector<std::pair<std::string, std::string>> missing; // bone, what it wanted
    for (const HumanoidBone& bone : bones) {
        const auto node = bone.node ? rig.find(*bone.node) : std::nullopt;
        const bool inSkeleton = node && std::any_of(skeleton.joints.begin(), skeleton.joints.end(),
                                                    [&](const model::SkeletonJoint& j) { return j.node == *node; });
        if (!inSkeleton)
            missing.push_back({bone.bone, bone.node ? "no joint '" + bone.wanted + "'" : "no " + bone.wanted});
    }
    if (!hasGuide)
        return {makeError({}, "preset unity: the humanoid map is found through the rig's guide, and none was given")};
    if (missing.empty())
        return {};
    std::string list;
    for (std::size_t i = 0; i < missing.size(); ++i)
        list += (i ? ", " : "") + missing[i].first + " (" + missing[i].second + ")";
    return {makeError({}, "preset unity: " + std::to_string(missing.size()) + " of " + std::to_string(bones.size()) +
                              " Unity humanoid bones have no joint in this rig, so a humanoid avatar would map only part of "
                              "it and play its animation on the wrong joints: " + list +
                              "; forcing the export writes it anyway (rigsmith-cli --force, or \"Export despite errors\" in the editor), "
                              "or give a name map for this rig (--names MAP.yml)")};
}

Diagnostics validate(const model::Rig& rig, model::Skeleton& skeleton, std::vector<SkinnedMesh>& meshes,
                     const ExportOptions& options)
{
    ExportCheck check = checkSkeleton(rig, skeleton);
    if (options.fixNames && !check.renames.empty()) {
        skeleton = applyRenames(std::move(skeleton), check);
        check = checkSkeleton(rig, skeleton);
    }
    Diagnostics report = check.problems;
    for (auto& mesh : meshes) {
        Diagnostics problems = checkInfluences(mesh, skeleton);
        if (options.fixWeights && hasErrors(problems)) {
            mesh = limitInfluences(std::move(mesh));
            problems = checkInfluences(mesh, skeleton);
        }
        report.insert(report.end(), problems.begin(), problems.end());
    }
    return report;
}

void addControllers(const model::Rig& rig, const model::PoseValues* pose, ExportScene& scene,
                    std::vector<model::RigNodeIndex>& nodes)
{
    std::vector<int> index(rig.nodes.size(), -1);
    for (model::RigNodeIndex i = 0; i < rig.nodes.size(); ++i) {
        const auto& node = rig.nodes[i];
        if (node.kind != model::RigNodeKind::Controller)
            continue;
        ExportController c;
        c.name = node.name;
        c.id = node.path;
        c.shape = node.shape;
        c.defaults = node.defaultValues;
        const std::map<std::string, double>* posed = nullptr;
        if (pose)
            if (auto it = pose->find(node.key); it != pose->end())
                posed = &it->second;
        for (const model::RigAttribute& attribute : node.attributes) {
            ExportController::Attribute a{attribute.name, attribute.value, attribute.min, attribute.max, attribute.labels};
            if (posed && !attribute.locked)
                if (auto it = posed->find(attribute.name); it != posed->end())
                    a.value = std::clamp(it->second, attribute.min, attribute.max);
            c.attributes.push_back(std::move(a));
        }
        // The nearest controller above it in the controllers' virtual hierarchy.
        for (auto p = node.virtualParent; p != model::kNoNode && c.parent < 0; p = rig.nodes[p].virtualParent)
            c.parent = index[p];
        c.poseLocal = c.parent < 0 ? node.worldMatrix
                                   : glm::inverse(rig.nodes[nodes[std::size_t(c.parent)]].worldMatrix) * node.worldMatrix;
        index[i] = int(scene.controllers.size());
        scene.controllers.push_back(c);
        nodes.push_back(i);
    }
}

ExportScene sceneFrom(const model::Rig& rig, const model::Skeleton& skeleton, std::vector<SkinnedMesh> meshes)
{
    ExportScene scene;
    scene.name = rig.nodes.empty() ? "rig" : rig.nodes.front().name;
    for (const auto& joint : skeleton.joints) {
        ExportJoint out;
        out.name = joint.name;
        out.id = joint.node == model::kNoNode ? std::string() : rig.nodes[joint.node].path;
        out.parent = joint.parent;
        out.bindWorld = joint.bindWorld;
        out.bindLocal = out.poseLocal = joint.bindLocal;
        scene.joints.push_back(out);
    }
    scene.meshes = std::move(meshes);
    return scene;
}

} // namespace

std::optional<ExportPreset> presetNamed(const std::string& name)
{
    for (ExportPreset p : {ExportPreset::Gltf, ExportPreset::Unreal, ExportPreset::Unity})
        if (name == presetName(p))
            return p;
    return std::nullopt;
}

const char* presetName(ExportPreset preset)
{
    switch (preset) {
    case ExportPreset::Gltf: return "gltf";
    case ExportPreset::Unreal: return "unreal";
    case ExportPreset::Unity: return "unity";
    }
    return "gltf";
}

PreparedExport prepareExport(const model::Rig& rig, const ExportOptions& options)
{
    PreparedExport out;
    auto extracted = model::extractSkeleton(rig);
    if (!extracted) {
        out.report = extracted.takeDiagnostics();
        return out;
    }
    model::Skeleton skeleton = extracted.take();
    std::vector<SkinnedMesh> meshes = options.meshes ? *options.meshes : std::vector<SkinnedMesh>{};
    const bool unityPreset = options.preset == ExportPreset::Unity && !options.names;
    const std::vector<HumanoidBone> humanoid =
        unityPreset && options.guide ? unityHumanoidBones(*options.guide, rig) : std::vector<HumanoidBone>{};
    NameMap unity;
    for (const HumanoidBone& bone : humanoid)
        if (bone.node)
            unity.byKey[*bone.node] = bone.bone;
    if (const NameMap* names = options.names ? options.names : &unity; !names->empty())
        skeleton = applyNameMap(rig, std::move(skeleton), *names);
    if (options.preset == ExportPreset::Unreal)
        addUnrealRoot(skeleton, meshes);

    out.report = validate(rig, skeleton, meshes, options);
    if (options.keyedClips)
        for (const KeyedClip& keyed : *options.keyedClips) {
            bool increasing = keyed.times.size() >= 2 && keyed.times.size() == keyed.poses.size();
            for (std::size_t k = 1; increasing && k < keyed.times.size(); ++k)
                increasing = keyed.times[k] > keyed.times[k - 1];
            if (!increasing || !(keyed.times.front() >= 0.0)) {
                out.report.push_back(makeError({}, "clip '" + keyed.name +
                                                   "' needs at least two keys, one pose per key, at increasing times from 0 s"));
                return out; // not forceable: there is no clip to write
            }
        }
    if (unityPreset) {
        Diagnostics unmapped = checkUnityMap(rig, skeleton, humanoid, options.guide != nullptr);
        out.report.insert(out.report.end(), unmapped.begin(), unmapped.end());
    }
    if (hasErrors(out.report)) {
        if (!options.force)
            return out;
        for (auto& item : out.report)
            if (item.severity == Severity::Error) {
                item.severity = Severity::Warning;
                item.message = "exported anyway (forced): " + item.message;
            }
    }
    ExportScene scene = sceneFrom(rig, skeleton, std::move(meshes));
    if (options.materials)
        scene.materials = *options.materials;
    SceneNodes nodes;
    for (const auto& joint : skeleton.joints)
        nodes.joints.push_back(joint.node);
    if (options.controllers)
        addControllers(rig, options.pose, scene, nodes.controllers);
    addCameras(rig, scene, nodes.cameras);
    // Compiled for the pose, the clips and the default values the nodes rest
    // in; a rig that does not evaluate exports its build rest unless a pose or
    // a clip was asked for.
    auto program = eval::RigProgram::compile(rig);
    const bool motion = options.pose || options.rangeOfMotion || (options.keyedClips && !options.keyedClips->empty());
    if (!program && motion) {
        Diagnostics d = program.takeDiagnostics();
        out.report.insert(out.report.end(), d.begin(), d.end());
        return out;
    }
    if (program) {
        if (!addMotion(rig, options, *program, nodes, scene)) {
            out.cancelled = true;
            return out;
        }
    }
    out.scene = std::move(scene);
    return out;
}

std::string exportReferenceJson(const ExportScene& scene)
{
    using nlohmann::json;
    json joints = json::array();
    for (const auto& j : scene.joints) {
        const Vec3 head = translationOf(j.bindWorld);
        joints.push_back({{"name", j.name},
                          {"parent", j.parent < 0 ? json(nullptr) : json(scene.joints[std::size_t(j.parent)].name)},
                          {"head", {head.x, head.y, head.z}}});
    }
    json meshes = json::array();
    for (const auto& mesh : scene.meshes) {
        json vertices = json::array();
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            const auto& p = mesh.positions[v];
            json weights = json::object();
            for (std::size_t k = 0; k < mesh.influenceCount(v); ++k) {
                const Influence& in = mesh.influencesOf(v)[k];
                weights[scene.joints[std::size_t(in.joint)].name] = double(in.weight);
            }
            vertices.push_back({p.x, p.y, p.z, std::move(weights)});
        }
        meshes.push_back({{"name", mesh.name}, {"vertices", std::move(vertices)}});
    }
    // Per clip, the joints whose scale changes during it (consumers check scale curves against it).
    json clips = json::array();
    for (const auto& clip : scene.clips) {
        json scaled = json::array();
        for (const auto& track : clip.tracks) {
            bool changes = false;
            for (const auto& s : track.scales)
                changes = changes || glm::length(s - track.scales.front()) > 1e-5;
            if (changes && !track.controller && !track.camera)
                scaled.push_back(scene.joints[std::size_t(track.node)].name);
        }
        clips.push_back({{"name", clip.name}, {"seconds", clip.times.empty() ? 0.0 : clip.times.back()}, {"scaled", std::move(scaled)}});
    }
    // A forced export may carry names that are not UTF-8: replaced, never thrown.
    return json{{"joints", std::move(joints)}, {"meshes", std::move(meshes)}, {"clips", std::move(clips)},
                {"cameras", camerasJson(scene)}}.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

} // namespace rs::io
