#pragma once
// What the viewport draws, in world space, derived from the guide and the built
// rig: guide joints with their bones, controller curves, skin joints. Pure data;
// the Renderer turns it into GL buffers and Picking hit-tests it.
#include "eval/RigProgram.h"
#include "model/GuideDocument.h"
#include "model/Mesh.h"
#include "model/Rig.h"
#include "session/MirroredGuides.h"

#include <glm/glm.hpp>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rs::viewport {

struct SceneJoint {
    model::JointId id = model::kNoId;
    model::InstanceId owner = model::kNoId;
    glm::dvec3 position{0.0};
    glm::dvec3 parentPosition{0.0};
    bool hasParent = false;
    bool selected = false;
};

struct SceneCurve {
    model::RigNodeIndex node = model::kNoNode;
    model::InstanceId owner = model::kNoId; // the instance it is drawn for (kNoId: none, the rig root)
    std::vector<glm::dvec3> points; // world-space polyline
    glm::dvec3 color{1.0, 1.0, 0.0};
    bool selected = false;
};

// CV mode: a control point of a selected controller's shape.
struct SceneCv {
    model::CurveCv cv;
    model::InstanceId owner = model::kNoId; // the controller's instance
    glm::dvec3 position{0.0}; // world
    bool selected = false;
};

// A name drawn next to what it names (an instance at its first guide joint,
// a controller at its origin), world space.
struct SceneLabel {
    glm::dvec3 position{0.0};
    std::string text;
};

// How skinned meshes are shaded (View > Display > Weights): their materials;
// the weights of one skin bone (Scene::weightBone) as a heat ramp, blue 0 to
// red 1; or each vertex in its dominant bone's colour (a colour per bone).
// Both weight views show the 4 largest influences per vertex, renormalised:
// what the renderer skins with.
enum class WeightDisplay { Off, SelectedJoint, DominantJoint };
// Linear blend skinning, or dual quaternions (no candy-wrapper collapse under
// twist; scale in the palette is ignored: dual quaternions are rigid).
enum class Skinning { Linear, DualQuaternion };

// One mesh of the character. The model is shared, so the renderer sends a
// mesh's vertices to the GPU once per (model, mesh) and its weights once per
// weights object, not once per scene.
struct SceneMesh {
    std::shared_ptr<const model::Model> model;           // owns the mesh; never null
    std::size_t mesh = 0;                                // into model->meshes
    std::shared_ptr<const model::MeshWeights> weights;   // joint i = Scene::palette[i]; null: unbound
    // Drawn opaque and posed by the palette (Rig mode, bound). Otherwise
    // see-through in the bind pose, so guides and joints stay visible.
    bool skinned = false;
    glm::vec3 baseColor{0.8f};                           // linear RGB, [0, 1]
    std::string texturePath;                             // absolute (or "<model>#<name>" when embedded); "" none
    std::shared_ptr<const std::string> textureImage;     // an embedded texture's encoded bytes; null: read texturePath
    std::size_t characterMesh = 0;                       // into session::Session::characterMeshes()
    std::vector<std::uint32_t> selectedVertices;         // weight painting's vertex selection, sorted
    // A colour per vertex drawn instead of the material and the weight display
    // (linear RGB, lit like the material; the skin chunk routes overlay); null
    // or the wrong size: none.
    std::shared_ptr<const std::vector<glm::vec3>> vertexColors;
    const model::Mesh& data() const { return model->meshes[mesh]; }
};

// What the View > Display menu shows. Controller curves are the "shapes" in
// Guide mode (authored there) and the "controllers" in Rig mode.
struct DisplayOptions {
    bool guides = true;
    bool shapes = true;
    bool controllers = true;
    bool skinJoints = true;
    bool labels = false;
    bool axes = false;
    bool meshes = true;
    WeightDisplay weights = WeightDisplay::Off;
    Skinning skinning = Skinning::Linear;
    bool operator==(const DisplayOptions&) const = default;
};

struct SceneSelection {
    model::InstanceId instance = model::kNoId;
    model::JointId joint = model::kNoId;
    std::vector<model::JointId> joints;     // every selected guide joint (guide mode), `joint` among them
    model::RigNodeIndex node = model::kNoNode;
    std::vector<model::RigNodeIndex> nodes; // every selected controller (rig mode)
    bool cvMode = false;                    // guide mode: show the selected controllers' CVs
    std::vector<model::CurveCv> cvs;        // the selected CVs
};

struct Scene {
    std::vector<SceneJoint> guideJoints;
    std::vector<SceneCurve> curves;
    std::vector<SceneJoint> skinJoints;   // id unused; owner = instance
    // The other side of mirrored branches (`branches: [L, R]`): derived from the
    // authored guide, drawn dimmer, not pickable; they follow every edit.
    std::vector<SceneJoint> mirrorJoints;
    std::vector<SceneCv> cvs;             // CV mode: pickable control points
    std::vector<SceneCurve> hulls;        // CV mode: the hulls joining them
    std::vector<SceneCurve> overlay;      // drawn last, on top (the gizmo, the paint brush)
    std::vector<glm::dvec3> overlayPoints; // drawn last, on top (weight painting's selected vertices)
    // Each guide joint's (Guide mode) or skin joint's (Rig mode) local axes:
    // X red, Y green, Z blue, kAxisLength long. Not pickable.
    std::vector<SceneCurve> axes;
    std::vector<SceneLabel> labels;
    static constexpr double kAxisLength = 0.06; // metres
    // The character: its meshes, and per skin bone (session::Session::skinBones()
    // order) its posed world matrix times the inverse of its bind matrix,
    // sent to the GPU every frame. Skinning happens in the vertex shader.
    std::vector<SceneMesh> meshes;
    std::vector<glm::mat4> palette;
    Skinning skinning = Skinning::Linear;
    WeightDisplay weightDisplay = WeightDisplay::Off;
    // The skin bone (into palette) WeightDisplay::SelectedJoint shows, -1 none:
    // set by the caller (the selection's bone, see skinBoneFor) or chosen
    // explicitly (a paint tool's joint).
    int weightBone = -1;
    bool showGuides = true;
    // Set by the viewport each time it is given a new scene: the renderer sends
    // the scene's vertices again only when it changed (0: always).
    std::uint64_t revision = 0;
    // What changed since revision `since` (set by the viewport from what its
    // caller says a change touched): with `all` false, only what these instances
    // own (joints, curves, CVs, axes by their `owner`) may differ from the scene
    // of revision `since`, and the renderer sends only their vertices again.
    struct Delta {
        bool all = true;
        std::uint64_t since = 0;
        std::vector<model::InstanceId> instances; // sorted, unique
    };
    Delta delta;

    // Bounds of everything drawn; false when the scene is empty.
    bool bounds(glm::dvec3& lo, glm::dvec3& hi) const;
    // Every point drawn (joints, curve points, mesh vertices), for framing.
    std::vector<glm::dvec3> drawnPoints() const;
};

// `rig` may be null (not built yet). With `pose` (an evaluation of the rig) the
// controllers and skin joints are drawn posed and the guides hidden: Rig mode.
// `mirrored` (session::Session::mirroredGuideJoints()) are the mirrored branches'
// guides, drawn with the guides.
Scene makeScene(const model::GuideDocument& guide, const model::Rig* rig, const SceneSelection& selection,
                const eval::EvalState* pose = nullptr, const std::vector<session::MirroredGuideJoint>& mirrored = {});
// Removes what `display` hides (hidden things are neither drawn nor picked).
void applyDisplay(Scene& scene, const DisplayOptions& display, bool rigMode);
// Bounds of the selected guide joints or controllers; false when nothing is selected.
bool selectionBounds(const Scene& scene, glm::dvec3& lo, glm::dvec3& hi);

} // namespace rs::viewport
