// Clips as FBX animation: per clip an AnimationStack with one AnimationLayer;
// per animated node and transform property (Lcl Translation / Lcl Rotation /
// Lcl Scaling) an AnimationCurveNode "T" / "R" / "S" whose channels d|X, d|Y,
// d|Z each get an AnimationCurve. Baked keys (the range of motion's samples)
// are declared linear. Authored cubic channels (ExportTrack::cubic) are cubic
// keys with user slopes (value per second): one at each authored key and at
// every half frame of the clip's rate between them, each key's value and
// slope the clip's own curve there (exact for translation and scale: a cubic
// cut at a frame is still that cubic; for rotation the Euler curve through
// glTF's normalised quaternion spline). Importers that ignore the flags
// (Blender, three.js, Assimp interpolate linearly) so play the curve within
// a half frame's chord instead of cutting straight between authored keys.
// The clip's flags (ExportTrack::animated / held) say which properties get a curve node, as they say which channels glTF
// gets; within one, every component gets a curve (one key when it stays still:
// Blender's importer would play a missing component at the previous take's
// last value). A camera's track plays its
// model (the frame turned to FBX's +X look) and, when its lens changes or
// differs, a FocalLength curve node on its Camera attribute. One Take per clip.
#include "io/FbxAnimation.h"
#include "io/FbxDocument.h"

#include <algorithm>
#include <bit>
#include <map>
#include <tuple>
#include <cmath>

namespace rs::io::fbx {

namespace {

// KeyAttrFlags: eInterpolationLinear (bit 2). KeyAttrDataFloat: right slope,
// next left slope, tangent weights/velocities packed as bits (the default
// 1/3 weights), unused here since the keys are linear.
constexpr std::int32_t kLinearKeys = 1 << 2;
// eInterpolationCubic (0x08) | eTangentUser (0x400): the slopes in KeyAttrDataFloat.
constexpr std::int32_t kCubicUserKeys = 0x08 | 0x400;
constexpr std::uint32_t kDefaultTangentWeights = 0x0d050505;
// A channel closer than this to the node's value at every key is constant
// (degrees for rotations, file units for translations, factors for scales).
constexpr double kConstantTolerance = 1e-5;

std::int64_t ticksOf(double seconds) { return std::llround(seconds * double(kTicksPerSecond)); }

struct Property {
    const char* name;      // "Lcl Translation"...
    const char* curveNode; // "T"...
    Vec3 nodeValue;        // the model's own value
    std::vector<Vec3> keys;
    std::vector<Vec3> slopes;           // cubic keys: one per key (per second); empty: linear
    std::vector<std::int64_t> times;    // cubic keys' own times (else the clip's)
};

void addCurve(Document& doc, std::int64_t curveNode, int channel, const std::vector<std::int64_t>& times,
              const Property& property)
{
    std::vector<float> values;
    std::vector<std::int64_t> keyTimes = times;
    for (const Vec3& key : property.keys)
        values.push_back(float(key[channel]));
    bool constant = true;
    for (float v : values)
        constant = constant && std::abs(double(v) - double(values.front())) <= kConstantTolerance;
    const bool cubic = !constant && property.slopes.size() == values.size();
    if (constant) { // differs from the node's value but never moves: one key
        values.resize(1);
        keyTimes.resize(1);
    }
    const std::int64_t id = doc.newId();
    Node& curve = doc.addObject("AnimationCurve", id, "", "AnimCurve", "");
    curve.child("Default").addDouble(property.nodeValue[channel]);
    curve.child("KeyVer").addInt32(4008);
    curve.child("KeyTime").addInt64s(keyTimes);
    curve.child("KeyValueFloat").addFloats(values);
    if (cubic) { // one attribute per key: its right slope and the next key's left one
        std::vector<std::int32_t> flags(values.size(), kCubicUserKeys), refCounts(values.size(), 1);
        std::vector<float> data;
        for (std::size_t k = 0; k < values.size(); ++k) {
            const double right = property.slopes[k][channel];
            const double nextLeft = property.slopes[std::min(k + 1, values.size() - 1)][channel];
            data.insert(data.end(), {float(right), float(nextLeft), std::bit_cast<float>(kDefaultTangentWeights), 0.f});
        }
        curve.child("KeyAttrFlags").addInt32s(flags);
        curve.child("KeyAttrDataFloat").addFloats(data);
        curve.child("KeyAttrRefCount").addInt32s(refCounts);
    } else {
        const std::int32_t flags = kLinearKeys, refCount = std::int32_t(values.size());
        const float data[4] = {0.f, 0.f, std::bit_cast<float>(kDefaultTangentWeights), 0.f};
        curve.child("KeyAttrFlags").addInt32s({&flags, 1});
        curve.child("KeyAttrDataFloat").addFloats(data);
        curve.child("KeyAttrRefCount").addInt32s({&refCount, 1});
    }
    static const char* const kChannels[3] = {"d|X", "d|Y", "d|Z"};
    doc.connect(id, curveNode, kChannels[channel]);
}

// `property` as the clip's flags say (ExportTrack::animated / held, the same
// channels glTF writes): an animated property gets a curve node whose
// components carry every key (a component that never moves gets one key); a
// held one gets one key per component; none when every key stays within float
// resolution of the node's own value; any other property nothing. A written
// property always carries all three components: Blender 3.4's importer keeps
// one transform per model across the takes it reads, so a component missing
// from a take would play the previous take's last value, not the node's
// (core/io/README.md, "Blender's FBX importer and missing components").
// With `restore`, the property is written as the node's own value, one key
// (another take moves it on this model). Returns whether it was written.
bool addProperty(Document& doc, std::int64_t layer, std::int64_t model, const std::vector<std::int64_t>& times,
                 Property property, unsigned bit, const ExportTrack& track, bool restore = false)
{
    const bool animated = (track.animated & bit) != 0, held = (track.held & bit) != 0;
    if (!animated && !held && !restore)
        return false;
    std::vector<std::int64_t> keyTimes = property.slopes.empty() ? times : property.times;
    if (!animated || restore) { // held: the first key is the value; restored: the node's
        property.keys.resize(1);
        property.slopes.clear();
        keyTimes.resize(1);
    }
    if (restore)
        property.keys = {property.nodeValue};
    bool differs = restore;
    for (const Vec3& key : property.keys)
        for (int c = 0; c < 3; ++c)
            differs = differs || std::abs(key[c] - property.nodeValue[c]) > kConstantTolerance;
    if (!differs) // within float resolution of the node's value
        return false;
    const std::int64_t id = doc.newId();
    Node& node = doc.addObject("AnimationCurveNode", id, property.curveNode, "AnimCurveNode", "");
    Node& p70 = node.child("Properties70");
    static const char* const kChannels[3] = {"d|X", "d|Y", "d|Z"};
    for (int c = 0; c < 3; ++c)
        p70.child("P").addString(kChannels[c]).addString("Number").addString("").addString("A")
            .addDouble(property.nodeValue[c]);
    doc.connect(id, layer);
    doc.connect(id, model, property.name);
    for (int c = 0; c < 3; ++c)
        addCurve(doc, id, c, keyTimes, property);
    return true;
}

// Cubic curves are keyed at every half frame: importers that ignore the
// cubic flags cut straight between keys, and a frame's chord of a brisk arm
// swing already strays 2 mm at a fingertip (a half frame's a quarter of it).
constexpr double kCubicKeysPerFrame = 2.0;

// The times a cubic channel of `clip` is keyed at in the FBX: its keys and
// every half frame of the clip's rate (30 when it has none) between them.
std::vector<double> cubicKeyTimes(const ExportClip& clip)
{
    const double fps = kCubicKeysPerFrame * (clip.framesPerSecond > 0.0 ? clip.framesPerSecond : 30.0);
    std::vector<double> out;
    for (std::size_t k = 0; k < clip.times.size(); ++k) {
        out.push_back(clip.times[k]);
        if (k + 1 == clip.times.size())
            break;
        for (double frame = std::floor(clip.times[k] * fps + 1e-6) + 1.0; frame / fps < clip.times[k + 1] - 1e-6; frame += 1.0)
            out.push_back(frame / fps);
    }
    return out;
}

// Values and slopes (central differences of the clip's curve; one-sided at
// the clip's ends) of `at` at `dense` times.
template <typename At>
void sampleCubic(const std::vector<double>& dense, const std::vector<double>& clipTimes, At at, std::vector<Vec3>& values,
                 std::vector<Vec3>& slopes)
{
    constexpr double h = 1e-4; // seconds
    for (double t : dense) {
        const double before = std::max(t - h, clipTimes.front()), after = std::min(t + h, clipTimes.back());
        const auto [a, v, b] = at(before, t, after);
        values.push_back(v);
        slopes.push_back((b - a) / (after - before));
    }
}

// `elsewhere`: the channels some take of the file writes on this model; a
// model this take animates gets those back at its own value (Blender 3.4
// would play what the previous take left there).
void addTrack(Document& doc, std::int64_t layer, std::int64_t model, const Mat4& nodeLocal,
              const ExportTrack& track, const ExportClip& clip, const std::vector<std::int64_t>& times,
              unsigned elsewhere)
{
    Vec3 t, s;
    Quat r;
    decompose(nodeLocal, t, r, s);
    const Vec3 euler = eulerXyzDegrees(r);
    Property translation{"Lcl Translation", "T", t, track.translations, {}, {}};
    Property rotation{"Lcl Rotation", "R", euler, continuousEulerDegrees(track.rotations, euler), {}, {}};
    Property scaling{"Lcl Scaling", "S", s, track.scales, {}, {}};
    if (track.cubic & track.animated) {
        const std::vector<double> dense = cubicKeyTimes(clip);
        std::vector<std::int64_t> denseTicks;
        for (double time : dense)
            denseTicks.push_back(ticksOf(time - clip.times.front()) + times.front());
        using Triple = std::tuple<Vec3, Vec3, Vec3>;
        if (track.cubic & kTranslationChannel) {
            translation.keys.clear();
            sampleCubic(dense, clip.times, [&](double a, double v, double b) {
                return Triple{trackTranslationAt(track, clip.times, a), trackTranslationAt(track, clip.times, v),
                              trackTranslationAt(track, clip.times, b)};
            }, translation.keys, translation.slopes);
            translation.times = denseTicks;
        }
        if (track.cubic & kScaleChannel) {
            scaling.keys.clear();
            sampleCubic(dense, clip.times, [&](double a, double v, double b) {
                return Triple{trackScaleAt(track, clip.times, a), trackScaleAt(track, clip.times, v),
                              trackScaleAt(track, clip.times, b)};
            }, scaling.keys, scaling.slopes);
            scaling.times = denseTicks;
        }
        if (track.cubic & kRotationChannel) {
            std::vector<Quat> quats;
            for (double time : dense)
                quats.push_back(trackRotationAt(track, clip.times, time));
            const std::vector<Vec3> eulers = continuousEulerDegrees(quats, euler);
            std::size_t i = 0;
            rotation.keys.clear();
            sampleCubic(dense, clip.times, [&](double a, double, double b) {
                // The neighbours' Euler triples nearest this key's (no wrap inside a difference).
                const std::vector<Vec3> near = continuousEulerDegrees(
                    {trackRotationAt(track, clip.times, a), trackRotationAt(track, clip.times, b)}, eulers[i]);
                return Triple{near[0], eulers[i++], near[1]};
            }, rotation.keys, rotation.slopes);
            rotation.times = denseTicks;
        }
    }
    const Property* properties[3] = {&translation, &rotation, &scaling};
    const unsigned bits[3] = {kTranslationChannel, kRotationChannel, kScaleChannel};
    bool written[3] = {false, false, false};
    for (int p = 0; p < 3; ++p)
        written[p] = addProperty(doc, layer, model, times, *properties[p], bits[p], track);
    if (written[0] || written[1] || written[2])
        for (int p = 0; p < 3; ++p)
            if (!written[p] && (elsewhere & bits[p]))
                addProperty(doc, layer, model, times, *properties[p], bits[p], track, true);
}

// A camera's track as its FBX model plays it: each key's frame turned to
// FBX's +X look (right-multiplied: key to key continuity is kept).
ExportTrack fbxCameraTrack(ExportTrack track)
{
    const Quat turn = fbxCameraTurn();
    for (auto& r : track.rotations)
        r = r * turn;
    for (auto& r : track.rotationSlopes)
        r = r * turn;
    return track;
}

// The camera's focal length (millimetres) as a FocalLength curve on its
// NodeAttribute (what Blender's importer animates the lens from; Assimp
// reads no camera animation), linear keys.
void addLensCurve(Document& doc, std::int64_t layer, std::int64_t attribute, const ExportCamera& camera,
                  const ExportTrack& track, const std::vector<std::int64_t>& times)
{
    const bool animated = (track.animated & kLensChannel) != 0;
    if ((!animated && !(track.held & kLensChannel)) || track.focalLengths.empty())
        return;
    const std::int64_t node = doc.newId(), curve = doc.newId();
    Node& curveNode = doc.addObject("AnimationCurveNode", node, "FocalLength", "AnimCurveNode", "");
    curveNode.child("Properties70").child("P").addString("d|FocalLength").addString("Number").addString("")
        .addString("A").addDouble(camera.focalLength);
    doc.connect(node, layer);
    doc.connect(node, attribute, "FocalLength");
    std::vector<float> values;
    for (double f : track.focalLengths)
        values.push_back(float(f));
    std::vector<std::int64_t> keyTimes = times;
    if (!animated) {
        values.resize(1);
        keyTimes.resize(1);
    }
    Node& c = doc.addObject("AnimationCurve", curve, "", "AnimCurve", "");
    c.child("Default").addDouble(camera.focalLength);
    c.child("KeyVer").addInt32(4008);
    c.child("KeyTime").addInt64s(keyTimes);
    c.child("KeyValueFloat").addFloats(values);
    const std::int32_t flags = kLinearKeys, refCount = std::int32_t(values.size());
    const float data[4] = {0.f, 0.f, std::bit_cast<float>(kDefaultTangentWeights), 0.f};
    c.child("KeyAttrFlags").addInt32s({&flags, 1});
    c.child("KeyAttrDataFloat").addFloats(data);
    c.child("KeyAttrRefCount").addInt32s({&refCount, 1});
    doc.connect(curve, node, "d|FocalLength");
}

} // namespace

void addClips(Document& doc, const ExportScene& scene, const ModelIds& ids, Node& takes)
{
    takes.child("Current").addString(scene.clips.empty() ? "" : scene.clips.front().name);
    auto modelOf = [&](const ExportTrack& track) {
        const std::size_t node = std::size_t(track.node);
        return track.camera ? ids.cameras[node] : track.controller ? ids.controllers[node] : ids.joints[node];
    };
    std::map<std::int64_t, unsigned> writtenSomewhere; // model -> channels some take animates or holds
    for (const ExportClip& clip : scene.clips)
        for (const ExportTrack& track : clip.tracks)
            writtenSomewhere[modelOf(track)] |= track.animated | track.held;
    for (const ExportClip& clip : scene.clips) {
        std::vector<std::int64_t> times;
        for (double t : clip.times)
            times.push_back(ticksOf(t));
        const std::int64_t start = times.empty() ? 0 : times.front(), stop = times.empty() ? 0 : times.back();

        const std::int64_t stack = doc.newId(), layer = doc.newId();
        Node& p70 = doc.addObject("AnimationStack", stack, clip.name, "AnimStack", "").child("Properties70");
        propertyTime(p70, "LocalStart", start);
        propertyTime(p70, "LocalStop", stop);
        propertyTime(p70, "ReferenceStart", start);
        propertyTime(p70, "ReferenceStop", stop);
        // An (empty) nested list: Assimp drops a layer without one, and with it the clip.
        doc.addObject("AnimationLayer", layer, "BaseLayer", "AnimLayer", "").child("Properties70");
        doc.connect(layer, stack);
        for (const ExportTrack& track : clip.tracks) {
            const std::size_t node = std::size_t(track.node);
            if (track.camera) {
                const ExportCamera& camera = scene.cameras[node];
                addTrack(doc, layer, ids.cameras[node], camera.poseWorld * glm::mat4_cast(fbxCameraTurn()),
                         fbxCameraTrack(track), clip, times, writtenSomewhere[modelOf(track)]);
                addLensCurve(doc, layer, ids.cameraAttributes[node], camera, track, times);
            } else if (track.controller)
                addTrack(doc, layer, ids.controllers[node], scene.controllers[node].poseLocal, track, clip, times,
                         writtenSomewhere[modelOf(track)]);
            else
                addTrack(doc, layer, ids.joints[node], scene.joints[node].poseLocal, track, clip, times,
                         writtenSomewhere[modelOf(track)]);
        }

        Node& take = takes.child("Take");
        take.addString(clip.name);
        take.child("FileName").addString(clip.name + ".tak");
        take.child("LocalTime").addInt64(start).addInt64(stop);
        take.child("ReferenceTime").addInt64(start).addInt64(stop);
    }
}

} // namespace rs::io::fbx
