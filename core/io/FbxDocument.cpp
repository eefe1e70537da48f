#include "io/FbxDocument.h"

#include "io/FbxAnimation.h"

#include <algorithm>
#include <cmath>

namespace rs::io::fbx {

Node& Document::addObject(const std::string& kind, std::int64_t id, const std::string& name,
                          const std::string& className, const std::string& type)
{
    ++counts[kind];
    Node& node = objects.child(kind);
    node.addInt64(id).addString(objectName(name, className)).addString(type);
    return node;
}

void Document::connect(std::int64_t child, std::int64_t parent)
{
    connections.child("C").addString("OO").addInt64(child).addInt64(parent);
}

void Document::connect(std::int64_t child, std::int64_t parent, const std::string& property)
{
    connections.child("C").addString("OP").addInt64(child).addInt64(parent).addString(property);
}

void propertyInt(Node& p70, const std::string& name, const std::string& type, std::int32_t value)
{
    p70.child("P").addString(name).addString(type).addString(type == "int" ? "Integer" : "").addString("").addInt32(value);
}

void propertyDouble(Node& p70, const std::string& name, double value, const std::string& flags)
{
    p70.child("P").addString(name).addString("double").addString("Number").addString(flags).addDouble(value);
}

void propertyVector(Node& p70, const std::string& name, const std::string& type, const Vec3& value,
                    const std::string& flags)
{
    p70.child("P").addString(name).addString(type).addString("").addString(flags)
        .addDouble(value.x).addDouble(value.y).addDouble(value.z);
}

void propertyTime(Node& p70, const std::string& name, std::int64_t ticks)
{
    p70.child("P").addString(name).addString("KTime").addString("Time").addString("").addInt64(ticks);
}

void propertyString(Node& p70, const std::string& name, const std::string& value, const std::string& flags)
{
    p70.child("P").addString(name).addString("KString").addString("").addString(flags).addString(value);
}

std::vector<double> matrixArray(const Mat4& m)
{
    std::vector<double> out;
    out.reserve(16);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            out.push_back(m[c][r]);
    return out;
}

} // namespace rs::io::fbx

namespace rs::io {

Vec3 eulerXyzDegrees(const Quat& rotation)
{
    // R = Rz(z) Ry(y) Rx(x); with glm's m[column][row]: r20 = -sin y,
    // r21 = cos y sin x, r22 = cos y cos x, r10 = sin z cos y, r00 = cos z cos y.
    const Mat3 m = glm::mat3_cast(glm::normalize(rotation));
    const double sy = std::clamp(-m[0][2], -1.0, 1.0);
    const double y = std::asin(sy);
    double x = 0.0, z = 0.0;
    if (std::abs(sy) < 1.0 - 1e-12) {
        x = std::atan2(m[1][2], m[2][2]);
        z = std::atan2(m[0][1], m[0][0]);
    } else { // gimbal lock: only x + z (or x - z) is defined; put it all in x
        x = std::atan2(-m[2][1], m[1][1]);
    }
    return glm::degrees(Vec3(x, y, z));
}

namespace {

// `e` moved by whole turns per channel to lie within 180 degrees of `previous`.
Vec3 nearestTurns(Vec3 e, const Vec3& previous)
{
    for (int i = 0; i < 3; ++i)
        e[i] += 360.0 * std::round((previous[i] - e[i]) / 360.0);
    return e;
}

double distance1(const Vec3& a, const Vec3& b) { return std::abs(a.x - b.x) + std::abs(a.y - b.y) + std::abs(a.z - b.z); }

} // namespace

std::vector<Vec3> continuousEulerDegrees(const std::vector<Quat>& rotations, const Vec3& startDegrees)
{
    std::vector<Vec3> out;
    out.reserve(rotations.size());
    Vec3 previous = startDegrees;
    for (const Quat& q : rotations) {
        const Vec3 e = eulerXyzDegrees(q);
        // The same rotation as (x + 180, 180 - y, z + 180): take whichever is nearer.
        const Vec3 a = nearestTurns(e, previous);
        const Vec3 b = nearestTurns(Vec3(e.x + 180.0, 180.0 - e.y, e.z + 180.0), previous);
        previous = distance1(b, previous) < distance1(a, previous) - 1e-9 ? b : a;
        out.push_back(previous);
    }
    return out;
}

} // namespace rs::io
