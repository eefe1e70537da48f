#pragma once
// An affine transform as the evaluator stores it: a 3x3 linear part (rotation
// times scale, column vectors) and a translation. Composing two costs 36
// multiplications instead of a 4x4 product's 64; the evaluation of a whole rig
// is a few hundred of them.
#include "base/Math.h"

namespace rs::eval {

struct Affine {
    Mat3 linear{1.0};
    Vec3 translation{0.0};

    static Affine fromMatrix(const Mat4& m) { return {Mat3(m), Vec3(m[3])}; }
    Mat4 matrix() const
    {
        Mat4 m(linear);
        m[3] = Vec4(translation, 1.0);
        return m;
    }
    Vec3 apply(const Vec3& p) const { return linear * p + translation; }
    Affine operator*(const Affine& b) const { return {linear * b.linear, linear * b.translation + translation}; }
    Affine inverse() const
    {
        const Mat3 inv = glm::inverse(linear);
        return {inv, -(inv * translation)};
    }
    // Column lengths: the scale along each local axis (shear-free transforms).
    Vec3 scale() const { return {glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])}; }
    // The rotation with the scale divided out of the columns.
    Mat3 rotation() const
    {
        const Vec3 s = scale();
        return Mat3(linear[0] / s.x, linear[1] / s.y, linear[2] / s.z);
    }
};

inline Affine compose(const Mat3& rotation, const Vec3& scale, const Vec3& translation)
{
    return {Mat3(rotation[0] * scale.x, rotation[1] * scale.y, rotation[2] * scale.z), translation};
}

} // namespace rs::eval
