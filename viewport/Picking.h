#pragma once
// Click selection in screen space: in CV mode the nearest shown CV within a
// pixel radius wins; then the nearest guide joint; otherwise the nearest
// controller curve within a (smaller) radius.
// Pure maths over a Scene, so it is tested without a GL context.
#include "Camera.h"
#include "Scene.h"

namespace rs::viewport {

struct PickResult {
    enum class Kind { Nothing, GuideJoint, Controller, Cv } kind = Kind::Nothing;
    model::JointId joint = model::kNoId;
    model::InstanceId owner = model::kNoId;
    model::RigNodeIndex node = model::kNoNode;
    double distancePixels = 0.0;
    model::CurveCv cv;                 // Kind::Cv
};

PickResult pick(const Scene& scene, const Camera& camera, double width, double height, glm::dvec2 cursorPixels,
                double jointRadiusPixels = 10.0, double curveRadiusPixels = 6.0);

// Distance in pixels from p to the segment a-b.
double distanceToSegment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b);
// Controllers with any curve point inside the pixel rectangle (box select), in node order.
std::vector<model::RigNodeIndex> boxPick(const Scene& scene, const Camera& camera, double width, double height,
                                         glm::dvec2 cornerA, glm::dvec2 cornerB);

// CVs (CV mode) inside the pixel rectangle, in scene order.
std::vector<model::CurveCv> boxPickCvs(const Scene& scene, const Camera& camera, double width, double height,
                                       glm::dvec2 cornerA, glm::dvec2 cornerB);

// The CV and every shown CV of the same controller at its place (a cube's
// corner is several CVs of one polyline): a click picks them together.
std::vector<model::CurveCv> coincidentCvs(const Scene& scene, const model::CurveCv& cv);

// Guide joints inside the pixel rectangle, in scene order.
std::vector<model::JointId> boxPickJoints(const Scene& scene, const Camera& camera, double width, double height,
                                          glm::dvec2 cornerA, glm::dvec2 cornerB);

} // namespace rs::viewport
