// Sampling the rig for an export's clips (io/ExportSampling.h).
#include "io/ExportSampling.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace rs::io {

namespace {

constexpr double kSameTranslation = 1e-6; // metres
constexpr double kSameRotation = 1e-6;    // quaternion component
constexpr double kSameScale = 1e-6;

// The transform a track's node is written with (what constant channels equal).
const Mat4& writtenTransform(const ExportScene& scene, const ExportTrack& track)
{
    const std::size_t n = std::size_t(track.node);
    return track.camera ? scene.cameras[n].poseWorld
                        : track.controller ? scene.controllers[n].poseLocal : scene.joints[n].poseLocal;
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

// A camera track's lens: animated when its focal length changes, held when it
// differs from the camera's own.
void markLens(ExportTrack& track, const ExportCamera& camera)
{
    constexpr double kSameFocalLength = 1e-6; // millimetres
    const auto& f = track.focalLengths;
    if (f.empty())
        return;
    const auto [low, high] = std::minmax_element(f.begin(), f.end());
    if (*high - *low > kSameFocalLength)
        track.animated |= kLensChannel;
    else if (std::abs(f.front() - camera.focalLength) > kSameFocalLength)
        track.held |= kLensChannel;
}

} // namespace

// The tracks of a clip before sampling: joints, controllers, then cameras (a Sample's order).
std::vector<ExportTrack> emptyTracks(const ExportScene& scene)
{
    std::vector<ExportTrack> tracks;
    auto add = [&](std::size_t count, bool controller, bool camera) {
        for (std::size_t n = 0; n < count; ++n) {
            ExportTrack& track = tracks.emplace_back();
            track.node = int(n);
            track.controller = controller;
            track.camera = camera;
        }
    };
    add(scene.joints.size(), false, false);
    add(scene.controllers.size(), true, false);
    add(scene.cameras.size(), false, true);
    return tracks;
}

void markTrack(ExportTrack& track, const ExportScene& scene)
{
    markChannels(track, writtenTransform(scene, track));
    if (track.camera)
        markLens(track, scene.cameras[std::size_t(track.node)]);
}

// One key on every track of `clip`, each rotation on the hemisphere of the
// track's previous key (no half-turn flip between keys).
void appendSample(ExportClip& clip, const Sample& sample)
{
    for (std::size_t n = 0; n < clip.tracks.size(); ++n) {
        ExportTrack& track = clip.tracks[n];
        Quat r = sample.rotations[n];
        if (!track.rotations.empty() && glm::dot(track.rotations.back(), r) < 0.0)
            r = -r;
        track.translations.push_back(sample.translations[n]);
        track.rotations.push_back(r);
        track.scales.push_back(sample.scales[n]);
        if (track.camera)
            track.focalLengths.push_back(sample.focalLengths[std::size_t(track.node)]);
    }
}

Sample sampleAt(double frame, const eval::Pose& pose, const eval::RigProgram& program, const Sampler& sampler,
                eval::EvalState& state)
{
    program.evaluate(pose, state);
    Sample out;
    out.frame = frame;
    const std::size_t joints = sampler.scene.joints.size(), controllers = sampler.scene.controllers.size();
    const std::size_t cameras = sampler.scene.cameras.size();
    for (std::size_t n = 0; n < joints + controllers + cameras; ++n) {
        Vec3 t, s;
        Quat r;
        decompose(n < joints                 ? sampler.jointLocal(n, state)
                  : n < joints + controllers ? sampler.controllerLocal(n - joints, state)
                                             : sampler.cameraWorld(n - joints - controllers, state),
                  t, r, s);
        out.translations.push_back(t);
        out.rotations.push_back(r);
        out.scales.push_back(s);
    }
    for (std::size_t c = 0; c < cameras; ++c)
        out.focalLengths.push_back(focalLengthIn(program, pose, sampler.nodes.cameras.lenses[c],
                                                 sampler.scene.cameras[c].focalLength));
    return out;
}

} // namespace rs::io
