#include "base/Math.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace rs {

Mat4 translationMatrix(const Vec3& t)
{
    return glm::translate(Mat4(1.0), t);
}

Vec3 translationOf(const Mat4& m)
{
    return Vec3(m[3]);
}

Mat4 rotationMatrix(const Vec3& axis, double angleRadians)
{
    return glm::rotate(Mat4(1.0), angleRadians, axis);
}

Mat4 Transform::matrix() const
{
    const Vec3 r = glm::radians(rotateDegrees);
    Mat4 m = translationMatrix(translate);
    m = glm::rotate(m, r.z, Vec3(0, 0, 1));
    m = glm::rotate(m, r.y, Vec3(0, 1, 0));
    m = glm::rotate(m, r.x, Vec3(1, 0, 0));
    return glm::scale(m, scale);
}

void decompose(const Mat4& m, Vec3& translate, Quat& rotate, Vec3& scale)
{
    translate = Vec3(m[3]);
    glm::dmat3 basis(m);
    scale = Vec3(glm::length(basis[0]), glm::length(basis[1]), glm::length(basis[2]));
    if (glm::determinant(basis) < 0.0)
        scale.x = -scale.x;
    for (int i = 0; i < 3; ++i)
        basis[i] /= (scale[i] == 0.0 ? 1.0 : scale[i]);
    rotate = glm::normalize(glm::quat_cast(basis));
}

double maxAbsDifference(const Mat4& a, const Mat4& b)
{
    double worst = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            worst = std::max(worst, std::abs(a[c][r] - b[c][r]));
    return worst;
}

} // namespace rs
