#pragma once
// Click selection in screen space: the nearest guide joint within a pixel radius
// wins; otherwise the nearest controller curve within a (smaller) radius.
// Pure maths over a Scene, so it is tested without a GL context.
#include "Camera.h"
#include "Scene.h"

namespace rs::viewport {

struct PickResult {
    enum class Kind { Nothing, GuideJoint, Controller } kind = Kind::Nothing;
    model::JointId joint = model::kNoId;
    model::InstanceId owner = model::kNoId;
    model::RigNodeIndex node = model::kNoNode;
    double distancePixels = 0.0;
};

PickResult pick(const Scene& scene, const Camera& camera, double width, double height, glm::dvec2 cursorPixels,
                double jointRadiusPixels = 10.0, double curveRadiusPixels = 6.0);

} // namespace rs::viewport
