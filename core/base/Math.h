#pragma once
// Core maths types. Core works in double precision, metres, Y-up, right-handed;
// angles in the document are degrees (rigger-facing), radians everywhere else.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace rs {

using Vec3 = glm::dvec3;
using Vec4 = glm::dvec4;
using Mat3 = glm::dmat3;
using Mat4 = glm::dmat4;
using Quat = glm::dquat;

// Local transform as a rigger edits it: translate, then rotate (Euler XYZ order,
// degrees: X applied first), then scale. Matrix = T * Rz * Ry * Rx * S.
struct Transform {
    Vec3 translate{0.0};
    Vec3 rotateDegrees{0.0};
    Vec3 scale{1.0};

    Mat4 matrix() const;
    bool operator==(const Transform&) const = default;
};

Mat4 translationMatrix(const Vec3& t);
Vec3 translationOf(const Mat4& m);
// Rotation about the given unit axis by angleRadians.
Mat4 rotationMatrix(const Vec3& axis, double angleRadians);
// Splits an affine matrix into translation, rotation and (positive) scale.
void decompose(const Mat4& m, Vec3& translate, Quat& rotate, Vec3& scale);
// Largest absolute difference between two matrices' elements.
double maxAbsDifference(const Mat4& a, const Mat4& b);

// Units. Rigsmith works in metres; FBX's UnitScaleFactor is the number of
// centimetres in one file unit (1 for centimetre files, 100 for metre files).
constexpr double kCentimetresPerMetre = 100.0;
constexpr double metresPerFbxUnit(double unitScaleFactor) { return unitScaleFactor / kCentimetresPerMetre; }
constexpr double fbxUnitScaleFactor(double unitsPerMetre) { return kCentimetresPerMetre / unitsPerMetre; }

} // namespace rs
