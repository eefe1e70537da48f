#include "io/ExportMotion.h"

#include "io/RangeOfMotion.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace rs::io {

namespace {

constexpr double kSameTranslation = 1e-6; // metres
constexpr double kSameRotation = 1e-6;    // quaternion component
constexpr double kSameScale = 1e-6;

// Local transforms of the scene's nodes for one evaluated state.
struct Sampler {
    const ExportScene& scene;
    const SceneNodes& nodes;

    Mat4 world(model::RigNodeIndex node, const eval::EvalState& state) const
    {
        return node == model::kNoNode ? Mat4(1.0) : state.worldMatrix(node);
    }
    Mat4 jointLocal(std::size_t j, const eval::EvalState& state) const
    {
        const int parent = scene.joints[j].parent;
        const Mat4 w = world(nodes.joints[j], state);
        return parent < 0 ? w : glm::inverse(world(nodes.joints[std::size_t(parent)], state)) * w;
    }
    Mat4 controllerLocal(std::size_t c, const eval::EvalState& state) const
    {
        const int parent = scene.controllers[c].parent;
        const Mat4 w = state.worldMatrix(nodes.controllers[c]);
        return parent < 0 ? w : glm::inverse(state.worldMatrix(nodes.controllers[std::size_t(parent)])) * w;
    }
};

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

bool sameVec(const Vec3& a, const Vec3& b, double tolerance)
{
    return std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance && std::abs(a.z - b.z) <= tolerance;
}
bool sameRotation(const Quat& a, const Quat& b) { return std::abs(glm::dot(a, b)) >= 1.0 - kSameRotation * kSameRotation; }

// Which channels of `track` change, and which constant ones differ from `written` (the node's transform).
void markChannels(ExportTrack& track, const Mat4& written)
{
    Vec3 t, s;
    Quat r;
    decompose(written, t, r, s);
    track.animated = 0;
    track.held = 0;
    auto mark = [&](unsigned bit, auto& values, auto same, const auto& rest) {
        bool changes = false;
        for (const auto& v : values)
            changes = changes || !same(v, values.front());
        if (changes)
            track.animated |= bit;
        else if (!values.empty() && !same(values.front(), rest))
            track.held |= bit;
    };
    mark(kTranslationChannel, track.translations, [](const Vec3& a, const Vec3& b) { return sameVec(a, b, kSameTranslation); }, t);
    mark(kRotationChannel, track.rotations, sameRotation, r);
    mark(kScaleChannel, track.scales, [](const Vec3& a, const Vec3& b) { return sameVec(a, b, kSameScale); }, s);
}

// A clip of `keys` [first, last] of the plan, times from 0 on the frame grid.
ExportClip sampleClip(const std::string& name, const RangeOfMotionPlan& plan, std::size_t first, std::size_t last,
                      const eval::RigProgram& program, const Sampler& sampler, double framesPerSecond)
{
    ExportClip clip;
    clip.name = name;
    clip.framesPerSecond = framesPerSecond;
    const ExportScene& scene = sampler.scene;
    for (std::size_t j = 0; j < scene.joints.size(); ++j)
        clip.tracks.push_back({int(j), false, {}, {}, {}});
    for (std::size_t c = 0; c < scene.controllers.size(); ++c)
        clip.tracks.push_back({int(c), true, {}, {}, {}});
    const int step = framesPerKey(framesPerSecond);
    eval::EvalState state = program.makeState();
    for (std::size_t k = first; k <= last; ++k) {
        program.evaluate(plan.keys[k], state);
        clip.times.push_back(double((k - first) * std::size_t(step)) / framesPerSecond);
        for (auto& track : clip.tracks)
            appendSample(track, track.controller ? sampler.controllerLocal(std::size_t(track.node), state)
                                                 : sampler.jointLocal(std::size_t(track.node), state));
    }
    std::vector<ExportTrack> kept;
    for (auto& track : clip.tracks) {
        markChannels(track, track.controller ? scene.controllers[std::size_t(track.node)].poseLocal
                                             : scene.joints[std::size_t(track.node)].poseLocal);
        if (track.animated | track.held)
            kept.push_back(std::move(track));
    }
    clip.tracks = std::move(kept);
    return clip;
}

void addRangeOfMotion(const model::Rig& rig, const ExportOptions& options, const eval::RigProgram& program,
                      const Sampler& sampler, ExportScene& scene, const RangeOfMotionPlan& plan)
{
    const double fps = options.framesPerSecond > 0.0 ? options.framesPerSecond : 30.0;
    const int step = framesPerKey(fps);
    if (!options.clipPerControl) {
        ExportClip clip = sampleClip("range_of_motion", plan, 0, plan.keys.size() - 1, program, sampler, fps);
        for (const auto& part : plan.parts)
            clip.markers.push_back({rig.nodes[part.control].name, rig.nodes[part.control].path,
                                    double(part.firstKey * std::size_t(step)) / fps, double(part.lastKey * std::size_t(step)) / fps});
        scene.clips.push_back(std::move(clip));
        return;
    }
    for (const auto& part : plan.parts) {
        ExportClip clip = sampleClip("rom_" + rig.nodes[part.control].name, plan, part.firstKey, part.lastKey, program, sampler, fps);
        clip.markers.push_back({rig.nodes[part.control].name, rig.nodes[part.control].path, 0.0, clip.times.back()});
        scene.clips.push_back(std::move(clip));
    }
}

} // namespace

bool addMotion(const model::Rig& rig, const ExportOptions& options, const eval::RigProgram& program, const SceneNodes& nodes,
               ExportScene& scene)
{
    const Sampler sampler{scene, nodes};
    if (options.pose) {
        eval::EvalState state = program.makeState();
        program.evaluate(eval::poseFromValues(rig, program.channels(), *options.pose), state);
        for (std::size_t j = 0; j < scene.joints.size(); ++j)
            scene.joints[j].poseLocal = sampler.jointLocal(j, state);
        for (std::size_t c = 0; c < scene.controllers.size(); ++c)
            scene.controllers[c].poseLocal = sampler.controllerLocal(c, state);
    }
    if (!options.rangeOfMotion)
        return true;
    const eval::Pose start = options.testPose ? eval::poseFromValues(rig, program.channels(), *options.testPose)
                                              : program.channels().defaults();
    const RangeOfMotionPlan plan = planRangeOfMotion(rig, program, start, options.progress);
    if (plan.keys.empty())
        return false; // cancelled
    addRangeOfMotion(rig, options, program, sampler, scene, plan);
    return !options.progress || options.progress(0.6);
}

} // namespace rs::io
