#include "io/ExportScene.h"

#include "eval/RigProgram.h"
#include "io/ExportCheck.h"
#include "model/Value.h"
#include "model/Skeleton.h"

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

namespace rs::io {

namespace {

constexpr double kRomDegrees = 30.0;
constexpr double kRomStep = 0.25; // seconds between range-of-motion keys

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

// Local transforms of the scene's nodes for one evaluated state.
struct Sampler {
    const ExportScene& scene;
    std::vector<model::RigNodeIndex> jointNodes, controllerNodes;

    Mat4 world(model::RigNodeIndex node, const eval::EvalState& state) const
    {
        return node == model::kNoNode ? Mat4(1.0) : state.worldMatrix(node);
    }
    Mat4 jointLocal(std::size_t j, const eval::EvalState& state) const
    {
        const int parent = scene.joints[j].parent;
        const Mat4 w = world(jointNodes[j], state);
        return parent < 0 ? w : glm::inverse(world(jointNodes[std::size_t(parent)], state)) * w;
    }
    Mat4 controllerLocal(std::size_t c, const eval::EvalState& state) const
    {
        const int parent = scene.controllers[c].parent;
        const Mat4 w = state.worldMatrix(controllerNodes[c]);
        return parent < 0 ? w : glm::inverse(state.worldMatrix(controllerNodes[std::size_t(parent)])) * w;
    }
};

void addControllers(const model::Rig& rig, ExportScene& scene, std::vector<model::RigNodeIndex>& nodes)
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

void appendSample(ExportTrack& track, const Mat4& local)
{
    Vec3 t, s;
    Quat r;
    decompose(local, t, r, s);
    if (!track.rotations.empty() && glm::dot(track.rotations.back(), r) < 0.0)
        r = -r;
    track.translations.push_back(t);
    track.rotations.push_back(r);
    track.scales.push_back(s);
}

// The keyed poses of the range-of-motion clip: rest, then each controller's free
// rotate axes in turn, +30 and -30 degrees (within limits), back to rest.
std::vector<eval::Pose> rangeOfMotionPoses(const model::Rig& rig, const eval::ChannelLayout& layout)
{
    const eval::Pose rest = layout.defaults();
    std::vector<eval::Pose> poses{rest};
    for (model::RigNodeIndex i = 0; i < rig.nodes.size(); ++i) {
        const int tx = layout.transformOf(i);
        if (tx < 0 || rig.nodes[i].kind != model::RigNodeKind::Controller)
            continue;
        bool moved = false;
        for (int axis = 0; axis < 3; ++axis) {
            if (rig.nodes[i].channels.isLocked(3 + axis))
                continue;
            const int channel = tx + 3 + axis;
            for (double sign : {1.0, -1.0}) {
                eval::Pose pose = rest;
                pose[std::size_t(channel)] = layout.clamp(channel, rest[std::size_t(channel)] + sign * kRomDegrees);
                poses.push_back(std::move(pose));
                moved = true;
            }
        }
        if (moved)
            poses.push_back(rest);
    }
    return poses;
}

// Evaluates the pose and the range-of-motion clip; false when cancelled.
bool addMotion(const model::Rig& rig, const ExportOptions& options, const eval::RigProgram& program, Sampler& sampler,
               ExportScene& scene)
{
    eval::EvalState state = program.makeState();
    if (options.pose) {
        program.evaluate(eval::poseFromValues(rig, program.channels(), *options.pose), state);
        for (std::size_t j = 0; j < scene.joints.size(); ++j)
            scene.joints[j].poseLocal = sampler.jointLocal(j, state);
        for (std::size_t c = 0; c < scene.controllers.size(); ++c)
            scene.controllers[c].poseLocal = sampler.controllerLocal(c, state);
    }
    if (!options.rangeOfMotion)
        return true;
    ExportClip clip;
    clip.name = "range_of_motion";
    for (std::size_t j = 0; j < scene.joints.size(); ++j)
        clip.tracks.push_back({int(j), false, {}, {}, {}});
    for (std::size_t c = 0; c < scene.controllers.size(); ++c)
        clip.tracks.push_back({int(c), true, {}, {}, {}});
    const auto poses = rangeOfMotionPoses(rig, program.channels());
    for (std::size_t k = 0; k < poses.size(); ++k) {
        if (options.progress && k % 32 == 0 && !options.progress(0.1 + 0.5 * double(k) / double(poses.size())))
            return false;
        program.evaluate(poses[k], state);
        clip.times.push_back(double(k) * kRomStep);
        for (auto& track : clip.tracks)
            appendSample(track, track.controller ? sampler.controllerLocal(std::size_t(track.node), state)
                                                 : sampler.jointLocal(std::size_t(track.node), state));
    }
    scene.clips.push_back(std::move(clip));
    return true;
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

Mat4 conjugate(const Mat4& m, const Mat4& basis, double scale)
{
    Mat4 out = basis * m * glm::transpose(basis);
    out[3] = Vec4(Vec3(out[3]) * scale, 1.0);
    return out;
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
    const NameMap unity = options.preset == ExportPreset::Unity && !options.names ? unityHumanoidMap() : NameMap{};
    if (const NameMap* names = options.names ? options.names : &unity; !names->names.empty())
        skeleton = applyNameMap(rig, std::move(skeleton), *names);
    if (options.preset == ExportPreset::Unreal)
        addUnrealRoot(skeleton, meshes);

    out.report = validate(rig, skeleton, meshes, options);
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
    Sampler sampler{scene, {}, {}};
    for (const auto& joint : skeleton.joints)
        sampler.jointNodes.push_back(joint.node);
    if (options.controllers)
        addControllers(rig, scene, sampler.controllerNodes);
    if (options.pose || options.rangeOfMotion) {
        auto program = eval::RigProgram::compile(rig);
        if (!program) {
            Diagnostics d = program.takeDiagnostics();
            out.report.insert(out.report.end(), d.begin(), d.end());
            return out;
        }
        if (!addMotion(rig, options, *program, sampler, scene)) {
            out.cancelled = true;
            return out;
        }
    }
    out.scene = std::move(scene);
    return out;
}

Convention conventionFor(ExportPreset preset, bool fbx)
{
    // glTF fixes metres and Y-up; Unreal's glTF importer converts on its side.
    if (preset == ExportPreset::Unreal && fbx)
        return {kCentimetresPerMetre, true}; // Z-up centimetres
    return {};
}

ExportScene converted(ExportScene scene, const Convention& convention)
{
    if (convention.unitsPerMetre == 1.0 && !convention.zUp)
        return scene;
    const double s = convention.unitsPerMetre;
    // Y-up to Z-up: +90 degrees about X (y -> z, z -> -y).
    const Mat4 basis = convention.zUp ? rotationMatrix(Vec3(1, 0, 0), glm::radians(90.0)) : Mat4(1.0);
    const Quat q = glm::quat_cast(Mat3(basis));
    for (auto& j : scene.joints) {
        j.bindWorld = conjugate(j.bindWorld, basis, s);
        j.bindLocal = conjugate(j.bindLocal, basis, s);
        j.poseLocal = conjugate(j.poseLocal, basis, s);
    }
    for (auto& c : scene.controllers)
        c.poseLocal = conjugate(c.poseLocal, basis, s);
    const glm::mat3 rotation = glm::mat3(Mat3(basis));
    for (auto& mesh : scene.meshes) {
        for (auto& p : mesh.positions)
            p = rotation * p * float(s);
        for (auto& n : mesh.normals)
            n = rotation * n;
    }
    for (auto& clip : scene.clips)
        for (auto& track : clip.tracks) {
            for (auto& t : track.translations)
                t = Mat3(basis) * t * s;
            for (auto& r : track.rotations)
                r = q * r * glm::conjugate(q);
            for (auto& sc : track.scales)
                sc = glm::abs(Mat3(basis) * sc);
        }
    return scene;
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
            if (changes && !track.controller)
                scaled.push_back(scene.joints[std::size_t(track.node)].name);
        }
        clips.push_back({{"name", clip.name}, {"seconds", clip.times.empty() ? 0.0 : clip.times.back()}, {"scaled", std::move(scaled)}});
    }
    // A forced export may carry names that are not UTF-8: replaced, never thrown.
    return json{{"joints", std::move(joints)}, {"meshes", std::move(meshes)}, {"clips", std::move(clips)}}.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

} // namespace rs::io
