#pragma once
// What an export writes, made once from the rig and then written by the glTF
// and FBX writers (io/RigExport.h is the entry point):
//  1. the deform skeleton (model::extractSkeleton: skin virtual hierarchy, one
//     root, no controllers or helpers), named by the name map;
//  2. the preset (Unreal: a `root` joint at the origin, Unity: the humanoid map);
//  3. the validator (io/ExportCheck.h, io/SkinnedMesh.h): errors refuse unless
//     forced, the safe fixes (renames, weight limiting) only when asked;
//  4. options: controllers as tagged non-joint nodes, the current pose on the
//     nodes (the bind pose stays in the inverse bind matrices), a range-of-motion
//     clip exercising each controller in turn from the guide's test pose
//     (io/RangeOfMotion.h plans it; joint tracks are sampled from the
//     evaluator, eval::RigProgram, at its keys);
//  5. the rig's cameras (util.camera: io/ExportCamera.h) at the scene root,
//     sampled in every clip like joints, never part of the skeleton.
// The scene is in the rig's convention (metres, Y-up); writers convert it to
// the file's with converted().
#include "base/Diagnostic.h"
#include "io/NameMap.h"
#include "io/SkinnedMesh.h"
#include "model/GuideDocument.h"
#include "model/Rig.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rs::io {

enum class ExportPreset {
    Gltf,   // Y-up, metres
    Unreal, // Z-up, centimetres (FBX; glTF keeps its Y-up metres), a `root` joint at the origin
    Unity,  // Y-up, metres, humanoid names (io/HumanoidMap.h, resolved on `guide`) unless a map is given
};
std::optional<ExportPreset> presetNamed(const std::string& name); // "gltf", "unreal", "unity"
const char* presetName(ExportPreset preset);

// A material of the exported meshes: a base colour and, when the model has
// one, the base colour texture's image, read once by io/CharacterExport.h (a
// file beside the model, or an image embedded in the model file).
struct ExportMaterial {
    std::string name;
    glm::vec3 baseColor{0.8f};  // linear RGB, 0..1
    std::string imageName;      // the image's file name ("brown_eye.png"); empty: no texture
    std::string imagePath;      // the image file, absolute; empty when the image came from inside the model
    std::string image;          // the image's bytes; empty: no texture
    std::string mimeType;       // "image/png" or "image/jpeg" (what glTF takes); empty for other formats
};

struct ExportOptions {
    ExportPreset preset = ExportPreset::Gltf;
    const NameMap* names = nullptr;               // export names; replaces the preset's map
    // The guide the rig was built from: the Unity preset finds its humanoid
    // bones through the guide's instances (template, side, tag), never by name.
    const model::GuideDocument* guide = nullptr;
    bool fixNames = false;                        // apply the validator's safe renames
    bool fixWeights = false;                      // limit to 4 influences and normalise
    bool force = false;                           // write despite validator errors (reported as warnings)
    bool controllers = false;                     // controllers as non-joint nodes tagged in extras
    const model::PoseValues* pose = nullptr;      // the current pose on the nodes; bind pose unchanged
    bool rangeOfMotion = false;                   // a clip rotating each controller in turn
    const std::vector<SkinnedMesh>* meshes = nullptr; // bound meshes (bind pose, world space)
    const std::vector<ExportMaterial>* materials = nullptr; // what the meshes' `material` indexes
    std::string generator = "Rigsmith";
    bool stampTime = false;                       // FBX: the real time in the header (else fixed: byte-identical files)
    bool embedTextures = true;                    // FBX: images inside the file; false: beside it, named relatively
    // Called with the fraction done (0..1); returning false cancels the export.
    std::function<bool(double)> progress;
    // Where the range of motion starts: the guide's test pose, relative to this
    // rig's rest (so none for a rig already rebuilt in that pose, eval::posedRig).
    // None: the rig's defaults.
    const model::PoseValues* testPose = nullptr;
    // The range of motion's frame grid: keys on whole frames at this rate
    // (> 0; io/RangeOfMotion.h says how many frames apart).
    double framesPerSecond = 30.0;
    // One clip per exercised controller ("rom_<controller name>", each from
    // time 0) instead of one clip with a marker per controller
    // ("range_of_motion"; a range longer than a minute is split at controller
    // boundaries into range_of_motion_1, _2..., each from time 0, because
    // engines keep clip time in 32-bit floats: io/ExportMotion.cpp).
    bool clipPerControl = false;
    // Authored clips: keyed poses played with cubic (spline) keys
    // (ExportTrack::cubic), written after the range of motion.
    const std::vector<struct KeyedClip>* keyedClips = nullptr;
};

// A clip a rigger keys: poses (channel values relative to the rig's rest, as
// the test pose) at increasing times. Each node the poses move gets one key
// per pose with spline tangents (Catmull-Rom: the slope from the previous key
// to the next; flat at the first and last key), like a DCC's spline keys;
// the writers keep them cubic (glTF CUBICSPLINE, FBX cubic keys). The rig is
// evaluated at the keys only, so between keys the export plays the joints'
// cubic curves, not the rig's own evaluation of interpolated channels.
struct KeyedClip {
    std::string name;
    std::vector<double> times;               // seconds, increasing, at least two
    std::vector<model::PoseValues> poses;    // one per time
};

struct ExportJoint {
    std::string name;
    std::string id;                  // rig node id, empty for a joint the preset added
    int parent = -1;
    Mat4 bindWorld{1.0};
    Mat4 bindLocal{1.0};
    Mat4 poseLocal{1.0};             // the node transform written (bindLocal unless posed)
};

struct ExportController {
    std::string name;
    std::string id;
    std::string shape;
    int parent = -1;                 // index into ExportScene::controllers, -1: at the scene root
    Mat4 poseLocal{1.0};
    // The default value of each animatable channel, recorded by cleanup
    // (model::RigNode::defaultValues; empty without it): "tx".."sz" in metres,
    // degrees and factors along the controller's own rest axes as Rigsmith's
    // channel box shows them (distances in the file's unit), then custom
    // attributes in their own units. glTF writes them
    // in the node's extras as rig.defaults ({"rig": {"defaults": {"rx": 0, ...}}}),
    // FBX as user properties rig_default_<channel> (double, flag "U").
    std::vector<std::pair<std::string, double>> defaults;
    // The controller's custom attributes (ik_blend, space, fist...: what the
    // channel box shows below its transform), with every export of
    // controllers, cleaned up or not: the value in the written pose (the
    // current pose when it is exported, else the attribute's default), its
    // range and, for an enum (a space switch), its labels. glTF writes them in
    // the node's extras as rig.attributes ({"ik_blend": {"value": 1, "min": 0,
    // "max": 1}, "space": {..., "labels": ["world", ...]}}), FBX as animatable
    // user properties named like the attribute (flags "A+U": a double
    // "Number", or an "enum" with its labels joined by '~', as Maya writes
    // them; Blender reads both as custom properties). Values are in the
    // attribute's own unit as the channel box shows it (a distance in metres,
    // also in a centimetre FBX: an attribute carries no unit to convert by).
    struct Attribute {
        std::string name;
        double value = 0.0, min = 0.0, max = 1.0;
        std::vector<std::string> labels;
    };
    std::vector<Attribute> attributes;
};

// A camera of the rig (the rig set "cameras": each util.camera instance's
// view node, io/ExportCamera.h), written at the scene root as a glTF camera
// node or an FBX Camera model, never as a joint. Its frame looks down its -Z
// with +Y up (glTF's and the rig's camera convention; the FBX writer turns it
// to FBX's +X look), unit scale. Lens values are the camera controller's
// attributes at the pose the file rests in.
struct ExportCamera {
    std::string name;
    std::string id;                  // rig node id (RigNode::path)
    Mat4 poseWorld{1.0};             // rotation and translation only
    double focalLength = 50.0;       // millimetres
    double filmWidth = 1.28;         // film back (horizontal aperture), inches
    double filmHeight = 0.72;        // inches
    double nearClip = 0.01;          // file units once converted()
    double farClip = 1000.0;
    bool orthographic = false;
    double orthoWidth = 2.0;         // orthographic: the width it sees, metres (not converted: see io/README.md)
};
// The camera's field of view in radians at `focalLength` millimetres: across
// the film's height (glTF's yfov) or width (FBX FieldOfView).
double verticalFieldOfView(const ExportCamera& camera, double focalLength);
double horizontalFieldOfView(const ExportCamera& camera, double focalLength);

// Bits of ExportTrack::animated / held.
enum ExportChannel : unsigned {
    kTranslationChannel = 1u,
    kRotationChannel = 2u,
    kScaleChannel = 4u,
    kAllChannels = 7u,
    kLensChannel = 8u, // a camera track's focal length (ExportTrack::focalLengths)
};

// Sampled local transforms of one node per clip time.
struct ExportTrack {
    int node = 0;                    // joint or controller index
    bool controller = false;
    std::vector<Vec3> translations;  // one per clip time, whichever channels are animated
    std::vector<Quat> rotations;     // sign-continuous, for linear interpolation
    std::vector<Vec3> scales;
    // Added for issue 21 (writers read these; the vectors above stay full):
    // ExportChannel bits of the channels whose value changes during the clip:
    // write them with every key. A channel in neither mask is constant and
    // equal to the node's written transform (poseLocal): write nothing.
    unsigned animated = kAllChannels;
    // ExportChannel bits of channels constant during the clip but different
    // from the node's written transform: write them with one key (the first).
    unsigned held = 0;
    // Added for issue 21 item 1: ExportChannel bits of the animated channels
    // whose keys are authored cubic keys (io::KeyedClip), not baked samples:
    // between keys k and k+1 the value is the cubic Hermite through both
    // values with these slopes (value per second, one per key, the same on
    // both sides of a key) - glTF CUBICSPLINE's definition, in which a player
    // scales the slopes by the key interval. Rotation slopes are derivatives
    // of the quaternion components (glTF normalises the result); scale and
    // translation slopes of their components. Other channels are linear.
    unsigned cubic = 0;
    std::vector<Vec3> translationSlopes;
    std::vector<Quat> rotationSlopes;
    std::vector<Vec3> scaleSlopes;
    // Added for cameras: the track moves ExportScene::cameras[node] (its world
    // transform: cameras sit at the scene root; `controller` is false), with
    // its focal length (millimetres) at each time, animated (kLensChannel)
    // when the lens attribute changes. glTF core cannot animate a camera's
    // yfov; FBX writes a FocalLength curve.
    bool camera = false;
    std::vector<double> focalLengths;

    bool isJoint() const { return !controller && !camera; }
};

// The value of a cubic channel at `time` between keys `k` and `k + 1` (glTF's
// cubic spline: Hermite basis, slopes scaled by the interval).
template <typename T>
T hermite(const T& v0, const T& slope0, const T& v1, const T& slope1, double t0, double t1, double time)
{
    const double span = t1 - t0, s = (time - t0) / span, s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * v0 + (s3 - 2 * s2 + s) * span * slope0 + (-2 * s3 + 3 * s2) * v1 +
           (s3 - s2) * span * slope1;
}
// Spline (Catmull-Rom) slopes of `values` at `times`: (next - previous) /
// (their time apart), zero at the ends (the key eases in and out).
template <typename T>
std::vector<T> splineSlopes(const std::vector<T>& values, const std::vector<double>& times)
{
    std::vector<T> slopes(values.size(), values.empty() ? T() : values.front() * 0.0);
    for (std::size_t k = 1; k + 1 < values.size(); ++k)
        slopes[k] = (values[k + 1] + values[k - 1] * -1.0) * (1.0 / (times[k + 1] - times[k - 1]));
    return slopes;
}
// The track's rotation at `time` of clip `times` (normalised; cubic or slerp).
Quat trackRotationAt(const ExportTrack& track, const std::vector<double>& times, double time);
Vec3 trackTranslationAt(const ExportTrack& track, const std::vector<double>& times, double time);
Vec3 trackScaleAt(const ExportTrack& track, const std::vector<double>& times, double time);

// A named frame range of a clip: the part that exercises one controller.
struct ExportMarker {
    std::string name;                // the controller's name
    std::string control;             // its rig node id (RigNode::path)
    double start = 0.0, end = 0.0;   // seconds, on the clip's times
};

struct ExportClip {
    std::string name;
    std::vector<double> times;       // seconds, increasing
    std::vector<ExportTrack> tracks;
    // Added for issue 21: the frame rate whose whole frames the times sit on
    // (0: no grid) and the clip's named ranges, in time order.
    double framesPerSecond = 0.0;
    std::vector<ExportMarker> markers;
};

struct ExportScene {
    std::string name;
    std::vector<ExportJoint> joints; // parents first
    std::vector<ExportController> controllers; // parents first
    std::vector<ExportCamera> cameras;
    std::vector<SkinnedMesh> meshes; // joint indices into `joints`
    std::vector<ExportMaterial> materials; // indexed by SkinnedMesh::material
    std::vector<ExportClip> clips;
};

struct PreparedExport {
    std::optional<ExportScene> scene; // none when refused or failed
    Diagnostics report;               // the validator's findings and any failure
    bool cancelled = false;
};
// Refuses (an error in the report, unless forced) when the export is invalid
// or when the preset cannot map the rig: the Unity preset names humanoid
// bones the rig has no joint for (each is listed with the joint it wanted;
// without options.guide no bone can be found).
PreparedExport prepareExport(const model::Rig& rig, const ExportOptions& options);

// The axes and units a file is written in.
struct Convention {
    double unitsPerMetre = 1.0;
    bool zUp = false;
};
Convention conventionFor(ExportPreset preset, bool fbx);
// The scene in `convention`: every transform conjugated by the change of basis
// (joints keep unit scale), vertices and translations scaled. In a Y-up
// convention the root joints are turned into a Z-up frame (-90 degrees about
// X: Z up, Y back; their children's local transforms compensate, world
// transforms are unchanged), so that no importer infers a root bone pointing
// at the hips (Blender's FBX importer would connect them and drop the hips'
// location curves); a Z-up file's roots keep their frame.
ExportScene converted(ExportScene scene, const Convention& convention);

// What the export holds, in the rig's convention, as JSON for the consumer
// checks (tests/tools): joints with name, parent and head, and each mesh's
// vertices with their weights by joint name, and each clip's name, length in
// seconds and the joints whose scale changes in it; each camera's name, lens
// and world position and look direction (-Z) at rest and at a few of each
// clip's key times (ExportCamera.cpp).
std::string exportReferenceJson(const ExportScene& scene);

} // namespace rs::io
