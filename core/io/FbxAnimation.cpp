// Clips as FBX animation: per clip an AnimationStack with one AnimationLayer;
// per animated node and transform property (Lcl Translation / Lcl Rotation /
// Lcl Scaling) an AnimationCurveNode "T" / "R" / "S" whose channels d|X, d|Y,
// d|Z each get an AnimationCurve. Keys are the clip's samples (baked), so
// they are declared linear. The clip's flags (ExportTrack::animated / held)
// say which properties get a curve node, as they say which channels glTF
// gets; within one, a component whose keys all equal the node's own value is
// omitted (importers fall back to that value). One Take per clip.
#include "io/FbxAnimation.h"
#include "io/FbxDocument.h"

#include <bit>
#include <cmath>

namespace rs::io::fbx {

namespace {

// KeyAttrFlags: eInterpolationLinear (bit 2). KeyAttrDataFloat: right slope,
// next left slope, tangent weights/velocities packed as bits (the default
// 1/3 weights), unused here since the keys are linear.
constexpr std::int32_t kLinearKeys = 1 << 2;
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
    const std::int32_t flags = kLinearKeys, refCount = std::int32_t(values.size());
    const float data[4] = {0.f, 0.f, std::bit_cast<float>(kDefaultTangentWeights), 0.f};
    curve.child("KeyAttrFlags").addInt32s({&flags, 1});
    curve.child("KeyAttrDataFloat").addFloats(data);
    curve.child("KeyAttrRefCount").addInt32s({&refCount, 1});
    static const char* const kChannels[3] = {"d|X", "d|Y", "d|Z"};
    doc.connect(id, curveNode, kChannels[channel]);
}

// `property` as the clip's flags say (ExportTrack::animated / held, the same
// channels glTF writes): an animated property gets a curve node whose
// components carry every key (a component that never moves gets one key, or
// none when it keeps the node's own value); a held one gets one key per
// component that differs from the node's value; any other property nothing.
void addProperty(Document& doc, std::int64_t layer, std::int64_t model, const std::vector<std::int64_t>& times,
                 Property property, unsigned bit, const ExportTrack& track)
{
    const bool animated = (track.animated & bit) != 0, held = (track.held & bit) != 0;
    if (!animated && !held)
        return;
    std::vector<std::int64_t> keyTimes = times;
    if (!animated) { // held: the first key is the value
        property.keys.resize(1);
        keyTimes.resize(1);
    }
    bool writes[3] = {false, false, false};
    for (int c = 0; c < 3; ++c)
        for (const Vec3& key : property.keys)
            writes[c] = writes[c] || std::abs(key[c] - property.nodeValue[c]) > kConstantTolerance;
    if (!writes[0] && !writes[1] && !writes[2]) // held within float resolution of the node's value
        return;
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
        if (writes[c])
            addCurve(doc, id, c, keyTimes, property);
}

void addTrack(Document& doc, std::int64_t layer, std::int64_t model, const Mat4& nodeLocal,
              const ExportTrack& track, const std::vector<std::int64_t>& times)
{
    Vec3 t, s;
    Quat r;
    decompose(nodeLocal, t, r, s);
    const Vec3 euler = eulerXyzDegrees(r);
    addProperty(doc, layer, model, times, {"Lcl Translation", "T", t, track.translations}, kTranslationChannel, track);
    addProperty(doc, layer, model, times, {"Lcl Rotation", "R", euler, continuousEulerDegrees(track.rotations, euler)},
                kRotationChannel, track);
    addProperty(doc, layer, model, times, {"Lcl Scaling", "S", s, track.scales}, kScaleChannel, track);
}

} // namespace

void addClips(Document& doc, const ExportScene& scene, const ModelIds& ids, Node& takes)
{
    takes.child("Current").addString(scene.clips.empty() ? "" : scene.clips.front().name);
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
            if (track.controller)
                addTrack(doc, layer, ids.controllers[node], scene.controllers[node].poseLocal, track, times);
            else
                addTrack(doc, layer, ids.joints[node], scene.joints[node].poseLocal, track, times);
        }

        Node& take = takes.child("Take");
        take.addString(clip.name);
        take.child("FileName").addString(clip.name + ".tak");
        take.child("LocalTime").addInt64(start).addInt64(stop);
        take.child("ReferenceTime").addInt64(start).addInt64(stop);
    }
}

} // namespace rs::io::fbx
