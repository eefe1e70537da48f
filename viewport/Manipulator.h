#pragma once
// The transform gizmo (W translate, E rotate, R scale) as pure maths: its
// handles for drawing and picking, and a drag tracker that turns mouse rays
// into the dragged node's new world matrix. No Qt, no GL; tested headless.
//
// Handles live in the gizmo frame (local: the node's axes; world: world axes),
// sized in world units so they keep a constant size on screen. A drag keeps
// the matrix the node had when it started, so the result never drifts.
#include "Camera.h"
#include "Scene.h"

#include <glm/glm.hpp>
#include <vector>

namespace rs::viewport {

enum class GizmoMode { Translate, Rotate, Scale };

struct Ray {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0}; // unit
};

// The ray from the camera through a pixel (origin top-left).
Ray rayThroughPixel(const Camera& camera, double width, double height, glm::dvec2 pixel);

struct Gizmo {
    GizmoMode mode = GizmoMode::Translate;
    bool worldSpace = false;
    glm::dmat4 target{1.0};       // the node's world matrix
    double size = 0.2;            // handle length, world units

    glm::dvec3 origin() const { return glm::dvec3(target[3]); }
    // Unit axis k of the gizmo frame (world axes, or the node's own).
    glm::dvec3 axis(int k) const;
    // A gizmo about `sizePixels` tall on screen.
    static double sizeFor(const Camera& camera, const glm::dvec3& origin, double heightPixels, double sizePixels = 90.0);
};

// The handles as polylines, axis k coloured red/green/blue, the hovered or
// dragged one highlighted (`active`, -1 none).
std::vector<SceneCurve> gizmoCurves(const Gizmo& gizmo, int active);
// The handle under the cursor within `radiusPixels`, or -1.
int pickGizmoHandle(const Gizmo& gizmo, const Camera& camera, double width, double height, glm::dvec2 pixel,
                    double radiusPixels = 8.0);

class GizmoDrag {
public:
    GizmoDrag(const Gizmo& gizmo, int handle, const Ray& start);
    // The node's world matrix for the cursor ray `now`.
    glm::dmat4 worldFor(const Ray& now) const;

private:
    double alongAxis(const Ray& ray) const;            // parameter on the axis line nearest the ray
    bool onPlane(const Ray& ray, glm::dvec3& point) const;

    Gizmo m_gizmo;
    int m_handle;
    glm::dvec3 m_axis;
    double m_startAlong = 0.0;
    glm::dvec3 m_startPoint{0.0};
};

} // namespace rs::viewport
