#include "io/ExportMotion.h"

#include "io/ExportSampling.h"
#include "io/RangeOfMotion.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace rs::io {

namespace {

// The largest turn of any node from `a` to `b`, as the smallest |cos(angle / 2)|.
double leastRotationDot(const Sample& a, const Sample& b)
{
    double least = 1.0;
    for (std::size_t n = 0; n < a.rotations.size(); ++n)
        least = std::min(least, std::abs(glm::dot(a.rotations[n], b.rotations[n])));
    return least;
}

// The pose a fraction of the way from key `a` to key `b`: continuous channels
// linearly, rotate orders and enums held at `a`'s value.
eval::Pose poseBetween(const eval::ChannelLayout& layout, const eval::Pose& a, const eval::Pose& b, double fraction)
{
    eval::Pose out = a;
    for (std::size_t c = 0; c < out.size(); ++c)
        if (layout[c].transform != eval::kRotateOrderChannel && !layout[c].isEnum())
            out[c] = a[c] + (b[c] - a[c]) * fraction;
    return out;
}

// What every player plays half way between two samples (translations and
// scales linearly, rotations by slerp on the shorter arc).
Sample halfWay(const Sample& a, const Sample& b)
{
    Sample out;
    out.frame = 0.5 * (a.frame + b.frame);
    for (std::size_t n = 0; n < a.rotations.size(); ++n) {
        out.translations.push_back(0.5 * (a.translations[n] + b.translations[n]));
        out.scales.push_back(0.5 * (a.scales[n] + b.scales[n]));
        const Quat end = glm::dot(a.rotations[n], b.rotations[n]) < 0.0 ? -b.rotations[n] : b.rotations[n];
        out.rotations.push_back(glm::normalize(glm::slerp(a.rotations[n], end, 0.5)));
    }
    for (std::size_t c = 0; c < a.focalLengths.size(); ++c)
        out.focalLengths.push_back(0.5 * (a.focalLengths[c] + b.focalLengths[c]));
    return out;
}

// A node turning more than this between two samples (cos of half of 120
// degrees) is sampled again in between: interpolators disagree on a half turn
// (slerp, nlerp and Euler curves each pick their own way round) and Euler
// curves near it step by 180 degrees, which three.js's FBXLoader mishandles.
constexpr double kMostTurnDot = 0.5;

// Appends the samples strictly after `a` up to and including `b` (frames of
// plan keys `keyA` and `keyA + 1`, `fractionA`/`fractionB` of the way between
// them, `b` the evaluation of `poseB`): where a node turns too far, the rig is
// evaluated again at the whole frame half way; within one frame (a flip of
// the rig) the players' own half-way transform is written, so every consumer
// turns the same way.
//
// The rig is evaluated in time order: a rolling wheel (eval::RollMemory)
// turns by the path between consecutive evaluations, so `state` holds the
// rolls as `b` left them and `rollsA` as `a` left them. A frame evaluated
// half way starts from `rollsA`, and `b` is evaluated again after it (only
// for rigs with rolls: for the others it gives the same sample). On return
// `state` holds the rolls of the last sample appended.
void refineInto(std::vector<Sample>& out, Sample a, Sample b, double fractionA, double fractionB,
                const eval::Pose& keyA, const eval::Pose& keyB, const eval::Pose& poseB,
                const std::vector<eval::RollMemory>& rollsA, const eval::RigProgram& program,
                const Sampler& sampler, eval::EvalState& state, int depth)
{
    if (depth < 8 && leastRotationDot(a, b) < kMostTurnDot) {
        // An even frame when there is one (keys stay on the grid at half the
        // rate, where Godot resamples: io/RangeOfMotion.h's framesPerKey), else any.
        double midFrame = 2.0 * std::floor(0.25 * (a.frame + b.frame));
        if (!(midFrame > a.frame && midFrame < b.frame))
            midFrame = std::floor(0.5 * (a.frame + b.frame));
        if (midFrame > a.frame && midFrame < b.frame) {
            const double fraction = fractionA + (fractionB - fractionA) * (midFrame - a.frame) / (b.frame - a.frame);
            const eval::Pose midPose = poseBetween(program.channels(), keyA, keyB, fraction);
            const bool rolls = program.hasPaths();
            if (rolls)
                state.rolls = rollsA;
            Sample mid = sampleAt(midFrame, midPose, program, sampler, state);
            refineInto(out, std::move(a), mid, fractionA, fraction, keyA, keyB, midPose, rollsA, program, sampler, state,
                       depth + 1);
            const std::vector<eval::RollMemory> rollsMid = state.rolls;
            if (rolls)
                b = sampleAt(b.frame, poseB, program, sampler, state);
            refineInto(out, out.back(), std::move(b), fraction, fractionB, keyA, keyB, poseB, rollsMid, program, sampler,
                       state, depth + 1);
            return;
        }
        // Nothing is evaluated within one frame: `state` stays as `b` left it.
        Sample mid = halfWay(a, b);
        refineInto(out, std::move(a), mid, fractionA, fractionA, keyA, keyB, poseB, rollsA, program, sampler, state, depth + 1);
        refineInto(out, out.back(), std::move(b), fractionA, fractionB, keyA, keyB, poseB, rollsA, program, sampler, state,
                   depth + 1);
        return;
    }
    out.push_back(std::move(b));
}

// A clip of `keys` [first, last] of the plan, times from 0 on the frame grid
// (and half way between two frames where the rig flips within one).
ExportClip sampleClip(const std::string& name, const RangeOfMotionPlan& plan, std::size_t first, std::size_t last,
                      const eval::RigProgram& program, const Sampler& sampler, double framesPerSecond)
{
    ExportClip clip;
    clip.name = name;
    clip.framesPerSecond = framesPerSecond;
    const ExportScene& scene = sampler.scene;
    clip.tracks = emptyTracks(scene);
    const int step = framesPerKey(framesPerSecond);
    eval::EvalState state = program.makeState();
    std::vector<Sample> samples;
    samples.push_back(sampleAt(0.0, plan.keys[first], program, sampler, state));
    for (std::size_t k = first; k < last; ++k) {
        const std::vector<eval::RollMemory> rolls = state.rolls; // as the key before left them
        Sample next = sampleAt(double((k + 1 - first) * std::size_t(step)), plan.keys[k + 1], program, sampler, state);
        refineInto(samples, samples.back(), std::move(next), 0.0, 1.0, plan.keys[k], plan.keys[k + 1], plan.keys[k + 1],
                   rolls, program, sampler, state, 0);
    }
    for (const Sample& sample : samples) {
        clip.times.push_back(sample.frame / framesPerSecond);
        appendSample(clip, sample);
    }
    std::vector<ExportTrack> kept;
    for (auto& track : clip.tracks) {
        markTrack(track, scene);
        if (track.animated | track.held)
            kept.push_back(std::move(track));
    }
    clip.tracks = std::move(kept);
    return clip;
}

// The longest range-of-motion clip in the default layout. Engines keep clip
// time in 32-bit floats: Godot 3 bakes a glTF clip at 15 fps by adding
// float(1/15) to a float time, which drifts 0.3 ms by 64 s, 1.9 ms by 170 s
// and 23 ms by 380 s; each key of a limb turning at 4.7 rad/s (90 degrees in
// framesPerKey) is then played drift x velocity change off, 1.6 cm at a toe
// 170 s into the biped's 380 s clip. Longer ranges are split at controller
// boundaries into consecutive clips (range_of_motion_1, _2...).
constexpr double kLongestClipSeconds = 60.0;

// Consecutive runs of `parts` (first and last part index), each at least one
// part and at most kLongestClipSeconds long where its parts allow, of about
// equal lengths (no short last clip of one finger).
std::vector<std::pair<std::size_t, std::size_t>> clipRuns(const std::vector<RangeOfMotionPart>& parts, double secondsPerKey)
{
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    if (parts.empty())
        return runs;
    const double total = double(parts.back().lastKey - parts.front().firstKey) * secondsPerKey;
    const double count = std::ceil(total / (kLongestClipSeconds - 10.0)); // room for a part across a cut
    const double target = total / std::max(1.0, count);
    auto seconds = [&](std::size_t from, std::size_t to) { // from part `from`'s first key to part `to`'s last
        return double(parts[to].lastKey - parts[from].firstKey) * secondsPerKey;
    };
    for (std::size_t p = 0; p < parts.size(); ++p) {
        // A run ends once the range so far has reached its share (runs x target).
        const bool full = !runs.empty() && seconds(0, runs.back().second) >= target * double(runs.size()) - 1e-9;
        if (!runs.empty() && !full && seconds(runs.back().first, p) <= kLongestClipSeconds)
            runs.back().second = p;
        else
            runs.emplace_back(p, p);
    }
    return runs;
}

void addRangeOfMotion(const model::Rig& rig, const ExportOptions& options, const eval::RigProgram& program,
                      const Sampler& sampler, ExportScene& scene, const RangeOfMotionPlan& plan)
{
    const double fps = options.framesPerSecond > 0.0 ? options.framesPerSecond : 30.0;
    const int step = framesPerKey(fps);
    if (!options.clipPerControl) {
        const auto runs = clipRuns(plan.parts, double(step) / fps);
        if (runs.size() <= 1) {
            ExportClip clip = sampleClip("range_of_motion", plan, 0, plan.keys.size() - 1, program, sampler, fps);
            for (const auto& part : plan.parts)
                clip.markers.push_back({rig.nodes[part.control].name, rig.nodes[part.control].path,
                                        double(part.firstKey * std::size_t(step)) / fps,
                                        double(part.lastKey * std::size_t(step)) / fps});
            scene.clips.push_back(std::move(clip));
            return;
        }
        for (std::size_t r = 0; r < runs.size(); ++r) {
            const std::size_t firstKey = plan.parts[runs[r].first].firstKey;
            const std::size_t lastKey = plan.parts[runs[r].second].lastKey;
            ExportClip clip = sampleClip("range_of_motion_" + std::to_string(r + 1), plan, firstKey, lastKey, program, sampler, fps);
            for (std::size_t p = runs[r].first; p <= runs[r].second; ++p) {
                const auto& part = plan.parts[p];
                clip.markers.push_back({rig.nodes[part.control].name, rig.nodes[part.control].path,
                                        double((part.firstKey - firstKey) * std::size_t(step)) / fps,
                                        double((part.lastKey - firstKey) * std::size_t(step)) / fps});
            }
            scene.clips.push_back(std::move(clip));
        }
        return;
    }
    for (const auto& part : plan.parts) {
        ExportClip clip = sampleClip("rom_" + rig.nodes[part.control].name, plan, part.firstKey, part.lastKey, program, sampler, fps);
        clip.markers.push_back({rig.nodes[part.control].name, rig.nodes[part.control].path, 0.0, clip.times.back()});
        scene.clips.push_back(std::move(clip));
    }
}

// A keyed clip: the rig evaluated at each key, every changing channel cubic
// with spline slopes (io::KeyedClip).
// For a rig whose evaluation depends on the ones before (a wheel's roll:
// path accumulates what it travels): evaluates `state` on every whole frame
// strictly between keys `k` and `k + 1`, the channels played as spline keys
// (Catmull-Rom, flat at the ends, as the authored keys are), so that the key
// after them rolls as far as the path between the keys, not as one straight
// (and, past roll_jump, skipped) step.
void travelBetweenKeys(const std::vector<double>& keys, const std::vector<eval::Pose>& poses, std::size_t k,
                       double framesPerSecond, const eval::RigProgram& program, eval::EvalState& state)
{
    auto slope = [&](std::size_t at, std::size_t c) {
        return at == 0 || at + 1 >= poses.size() ? 0.0 : (poses[at + 1][c] - poses[at - 1][c]) / (keys[at + 1] - keys[at - 1]);
    };
    eval::Pose pose = poses[k];
    for (long long f = (long long)std::floor(keys[k] * framesPerSecond + 1e-9) + 1; double(f) / framesPerSecond < keys[k + 1] - 1e-9; ++f) {
        const double time = double(f) / framesPerSecond;
        for (std::size_t c = 0; c < pose.size(); ++c)
            pose[c] = hermite(poses[k][c], slope(k, c), poses[k + 1][c], slope(k + 1, c), keys[k], keys[k + 1], time);
        program.evaluate(pose, state);
    }
}

ExportClip keyedClip(const model::Rig& rig, const KeyedClip& keyed, const eval::RigProgram& program,
                     const Sampler& sampler, double framesPerSecond)
{
    ExportClip clip;
    clip.name = keyed.name;
    clip.framesPerSecond = framesPerSecond; // where the FBX keys its cubic curves
    clip.times = keyed.times;
    const ExportScene& scene = sampler.scene;
    clip.tracks = emptyTracks(scene);
    eval::EvalState state = program.makeState();
    std::vector<eval::Pose> poses;
    for (const auto& values : keyed.poses)
        poses.push_back(eval::poseFromValues(rig, program.channels(), values));
    for (std::size_t k = 0; k < poses.size(); ++k) {
        if (k > 0 && program.hasPaths()) // wheels roll along the path between the keys
            travelBetweenKeys(keyed.times, poses, k - 1, framesPerSecond, program, state);
        appendSample(clip, sampleAt(keyed.times[k], poses[k], program, sampler, state));
    }
    std::vector<ExportTrack> kept;
    for (auto& track : clip.tracks) {
        markTrack(track, scene);
        if (!(track.animated | track.held))
            continue;
        track.cubic = track.animated & kAllChannels; // a lens is keyed linearly
        track.translationSlopes = splineSlopes(track.translations, clip.times);
        track.rotationSlopes = splineSlopes(track.rotations, clip.times);
        track.scaleSlopes = splineSlopes(track.scales, clip.times);
        kept.push_back(std::move(track));
    }
    clip.tracks = std::move(kept);
    return clip;
}

// The key interval of `times` holding `time` (clamped to the clip) and how far in it is.
std::size_t intervalOf(const std::vector<double>& times, double time)
{
    const auto after = std::upper_bound(times.begin(), times.end(), time);
    const std::size_t k = after == times.begin() ? 0 : std::size_t(after - times.begin()) - 1;
    return std::min(k, times.size() < 2 ? 0 : times.size() - 2);
}

template <typename T, typename Linear>
T valueAt(const std::vector<T>& values, const std::vector<T>& slopes, bool cubic, const std::vector<double>& times,
          double time, Linear linear)
{
    if (values.size() < 2 || times.size() < 2)
        return values.front();
    const std::size_t k = intervalOf(times, time);
    const double t = std::clamp(time, times[k], times[k + 1]);
    if (cubic)
        return hermite(values[k], slopes[k], values[k + 1], slopes[k + 1], times[k], times[k + 1], t);
    return linear(values[k], values[k + 1], (t - times[k]) / (times[k + 1] - times[k]));
}

// The cameras where `pose` (evaluated in `state`) puts them, with its lens.
void placeCameras(const eval::RigProgram& program, const eval::Pose& pose, const Sampler& sampler,
                  const eval::EvalState& state, ExportScene& scene)
{
    for (std::size_t c = 0; c < scene.cameras.size(); ++c) {
        scene.cameras[c].poseWorld = sampler.cameraWorld(c, state);
        applyLens(scene.cameras[c], program, pose, sampler.nodes.cameras.lenses[c]);
    }
}

} // namespace

Quat trackRotationAt(const ExportTrack& track, const std::vector<double>& times, double time)
{
    return glm::normalize(valueAt(track.rotations, track.rotationSlopes, (track.cubic & kRotationChannel) != 0, times,
                                  time, [](const Quat& a, const Quat& b, double f) { return glm::slerp(a, b, f); }));
}
Vec3 trackTranslationAt(const ExportTrack& track, const std::vector<double>& times, double time)
{
    return valueAt(track.translations, track.translationSlopes, (track.cubic & kTranslationChannel) != 0, times, time,
                   [](const Vec3& a, const Vec3& b, double f) { return a + (b - a) * f; });
}
Vec3 trackScaleAt(const ExportTrack& track, const std::vector<double>& times, double time)
{
    return valueAt(track.scales, track.scaleSlopes, (track.cubic & kScaleChannel) != 0, times, time,
                   [](const Vec3& a, const Vec3& b, double f) { return a + (b - a) * f; });
}

bool addMotion(const model::Rig& rig, const ExportOptions& options, const eval::RigProgram& program, const SceneNodes& nodes,
               ExportScene& scene)
{
    const Sampler sampler{scene, nodes};
    if (!options.pose) {
        // The rig's default values (what reset returns to, the rigger's "set as
        // default" overrides included) are the pose the file's nodes rest in.
        // The bind stays the build's rest; nodes the defaults leave in place
        // keep their bind transform exactly.
        eval::EvalState state = program.makeState();
        program.evaluate(program.channels().defaults(), state);
        for (std::size_t j = 0; j < scene.joints.size(); ++j)
            if (const Mat4 local = sampler.jointLocal(j, state); maxAbsDifference(local, scene.joints[j].poseLocal) > 1e-9)
                scene.joints[j].poseLocal = local;
        for (std::size_t c = 0; c < scene.controllers.size(); ++c)
            if (const Mat4 local = sampler.controllerLocal(c, state); maxAbsDifference(local, scene.controllers[c].poseLocal) > 1e-9)
                scene.controllers[c].poseLocal = local;
        placeCameras(program, program.channels().defaults(), sampler, state, scene);
    } else {
        eval::EvalState state = program.makeState();
        program.evaluate(eval::poseFromValues(rig, program.channels(), *options.pose), state);
        for (std::size_t j = 0; j < scene.joints.size(); ++j)
            scene.joints[j].poseLocal = sampler.jointLocal(j, state);
        for (std::size_t c = 0; c < scene.controllers.size(); ++c)
            scene.controllers[c].poseLocal = sampler.controllerLocal(c, state);
        placeCameras(program, eval::poseFromValues(rig, program.channels(), *options.pose), sampler, state, scene);
    }
    auto addKeyed = [&] {
        if (options.keyedClips)
            for (const KeyedClip& keyed : *options.keyedClips)
                scene.clips.push_back(keyedClip(rig, keyed, program, sampler,
                                                options.framesPerSecond > 0.0 ? options.framesPerSecond : 30.0));
    };
    if (!options.rangeOfMotion) {
        addKeyed();
        return true;
    }
    const eval::Pose start = options.testPose ? eval::poseFromValues(rig, program.channels(), *options.testPose)
                                              : program.channels().defaults();
    const RangeOfMotionPlan plan = planRangeOfMotion(rig, program, start, options.progress);
    if (plan.keys.empty())
        return false; // cancelled
    addRangeOfMotion(rig, options, program, sampler, scene, plan);
    addKeyed();
    return !options.progress || options.progress(0.6);
}

} // namespace rs::io
