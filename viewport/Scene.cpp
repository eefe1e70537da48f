#include "Scene.h"

#include <algorithm>

namespace rs::viewport {

std::vector<glm::dvec3> Scene::drawnPoints() const
{
    std::vector<glm::dvec3> points;
    for (const auto& j : guideJoints) points.push_back(j.position);
    for (const auto& c : curves) points.insert(points.end(), c.points.begin(), c.points.end());
    for (const auto& j : skinJoints) points.push_back(j.position);
    for (const auto& m : meshes) for (const auto& p : m.data().positions) points.emplace_back(p);
    return points;
}

namespace {
bool boundsOf(const std::vector<glm::dvec3>& points, glm::dvec3& lo, glm::dvec3& hi)
{
    lo = glm::dvec3(1e300);
    hi = glm::dvec3(-1e300);
    for (const glm::dvec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return !points.empty();
}
} // namespace

bool Scene::bounds(glm::dvec3& lo, glm::dvec3& hi) const { return boundsOf(drawnPoints(), lo, hi); }

namespace {
std::vector<glm::dvec3> selectionPoints(const Scene& scene)
{
    std::vector<glm::dvec3> points;
    for (const auto& cv : scene.cvs)
        if (cv.selected) points.push_back(cv.position);
    if (!points.empty()) // CV mode frames the selected CVs
        return points;
    if (scene.showGuides)
        for (const auto& j : scene.guideJoints) if (j.selected) points.push_back(j.position);
    for (const auto& c : scene.curves)
        if (c.selected) points.insert(points.end(), c.points.begin(), c.points.end());
    return points;
}

} // namespace

bool selectionBounds(const Scene& scene, glm::dvec3& lo, glm::dvec3& hi) { return boundsOf(selectionPoints(scene), lo, hi); }

void applyDisplay(Scene& scene, const DisplayOptions& display, bool rigMode)
{
    if (!display.guides) {
        scene.guideJoints.clear();
        scene.mirrorJoints.clear();
        if (!rigMode)
            scene.axes.clear();
    }
    if (!(rigMode ? display.controllers : display.shapes)) {
        scene.curves.clear();
        scene.cvs.clear();
        scene.hulls.clear();
    }
    if (!display.skinJoints) {
        scene.skinJoints.clear();
        if (rigMode)
            scene.axes.clear();
    }
    if (!display.labels)
        scene.labels.clear();
    if (!display.axes)
        scene.axes.clear();
    if (!display.meshes)
        scene.meshes.clear();
    scene.weightDisplay = display.weights;
    scene.skinning = display.skinning;
}

namespace {

const glm::dvec3 kHullColor{0.55, 0.3, 0.6}; // Maya draws hulls and CVs in violet

bool showsCvs(const SceneSelection& selection, model::RigNodeIndex node)
{
    return selection.cvMode &&
           (node == selection.node || std::find(selection.nodes.begin(), selection.nodes.end(), node) != selection.nodes.end());
}

// A controller's CVs and hulls (CV mode), in world space.
void addCvs(Scene& scene, const model::RigNode& node, model::RigNodeIndex index, const std::vector<model::CurveCv>& selected)
{
    for (std::size_t k = 0; k < node.curves.size(); ++k) {
        const model::ControllerCurve& curve = node.curves[k];
        SceneCurve hull;
        hull.node = index;
        hull.owner = node.owner;
        hull.color = kHullColor;
        for (std::size_t i = 0; i < curve.cvs.size(); ++i) {
            SceneCv cv{{index, int(k), int(i)}, node.owner, glm::dvec3(node.worldMatrix * glm::dvec4(curve.cvs[i], 1.0)), false};
            cv.selected = std::find(selected.begin(), selected.end(), cv.cv) != selected.end();
            hull.points.push_back(cv.position);
            scene.cvs.push_back(cv);
        }
        if (curve.periodic && !hull.points.empty())
            hull.points.push_back(hull.points.front());
        scene.hulls.push_back(std::move(hull));
    }
}

void addAxes(Scene& scene, const glm::dmat4& world, model::InstanceId owner)
{
    const glm::dvec3 origin(world[3]);
    const glm::dvec3 colors[] = {{0.95, 0.25, 0.25}, {0.3, 0.9, 0.3}, {0.3, 0.5, 1.0}};
    for (int axis = 0; axis < 3; ++axis) {
        const glm::dvec3 direction(world[axis]);
        const double length = glm::length(direction);
        if (length < 1e-12)
            continue;
        SceneCurve c;
        c.owner = owner;
        c.color = colors[axis];
        c.points = {origin, origin + direction / length * Scene::kAxisLength};
        scene.axes.push_back(std::move(c));
    }
}

} // namespace

Scene makeScene(const model::GuideDocument& guide, const model::Rig* rig, const SceneSelection& selection,
                const eval::EvalState* pose, const std::vector<session::MirroredGuideJoint>& mirrored)
{
    Scene scene;
    scene.showGuides = pose == nullptr;
    for (const auto& instance : guide.instances())
        for (const auto& joint : instance.joints) {
            SceneJoint j;
            j.id = joint.id;
            j.owner = instance.id;
            const glm::dmat4 jointWorld = guide.jointWorldMatrix(joint.id);
            j.position = translationOf(jointWorld);
            if (scene.showGuides) {
                addAxes(scene, jointWorld, instance.id);
                if (&joint == &instance.joints.front())
                    scene.labels.push_back({j.position, instance.name});
            }
            const model::JointId parent = joint.parent != model::kNoId ? joint.parent : instance.parentJoint;
            if (parent != model::kNoId && guide.joint(parent)) {
                j.hasParent = true;
                j.parentPosition = translationOf(guide.jointWorldMatrix(parent));
            }
            j.selected = joint.id == selection.joint ||
                         std::find(selection.joints.begin(), selection.joints.end(), joint.id) != selection.joints.end() ||
                         (selection.joint == model::kNoId && instance.id == selection.instance);
            scene.guideJoints.push_back(j);
        }
    if (scene.showGuides)
        for (const session::MirroredGuideJoint& m : mirrored) {
            SceneJoint j;
            j.owner = m.owner;
            j.position = m.position;
            j.hasParent = m.hasParent;
            j.parentPosition = m.parentPosition;
            scene.mirrorJoints.push_back(j);
        }
    if (!rig)
        return scene;
    const bool posed = pose && pose->world.size() == rig->nodes.size();
    auto world = [&](model::RigNodeIndex i) { return posed ? pose->worldMatrix(i) : rig->nodes[i].worldMatrix; };
    for (model::RigNodeIndex i = 0; i < rig->nodes.size(); ++i) {
        const model::RigNode& node = rig->nodes[i];
        const glm::dmat4 nodeWorld = world(i);
        // Rig mode draws (and so picks) only what the pose shows: a limb's FK
        // controls hide at full IK and its IK controls at full FK.
        const bool shown = !posed || pose->isVisible(i);
        if (node.kind == model::RigNodeKind::Controller && shown)
            for (const auto& curve : node.curves) {
                if (!curve.visible)
                    continue; // a shape override hides it
                SceneCurve c;
                c.node = i;
                c.owner = node.owner;
                c.color = curve.color;
                c.selected = i == selection.node ||
                             std::find(selection.nodes.begin(), selection.nodes.end(), i) != selection.nodes.end() ||
                             (!posed && selection.node == model::kNoNode && node.owner == selection.instance &&
                              selection.instance != model::kNoId);
                for (const auto& p : curve.points)
                    c.points.push_back(glm::dvec3(nodeWorld * glm::dvec4(p, 1.0)));
                if (c.selected && posed && &curve == &node.curves.front())
                    scene.labels.push_back({translationOf(nodeWorld), node.name}); // Rig mode: the selected controllers
                scene.curves.push_back(std::move(c));
            }
        if (showsCvs(selection, i) && !posed)
            addCvs(scene, node, i, selection.cvs);
        if (node.kind == model::RigNodeKind::Joint && !node.hidden && node.domain() == "skin") {
            SceneJoint j;
            j.owner = node.owner;
            j.position = translationOf(nodeWorld);
            if (node.virtualParent != model::kNoNode) {
                j.hasParent = true;
                j.parentPosition = translationOf(world(node.virtualParent));
            }
            if (posed)
                addAxes(scene, nodeWorld, node.owner);
            scene.skinJoints.push_back(j);
        }
    }
    return scene;
}

} // namespace rs::viewport
