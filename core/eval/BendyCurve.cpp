#include "eval/BendyCurve.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rs::eval {

namespace {

constexpr int kSamples = 24;

// Cubic Hermite position and derivative on one piece, s in [0, 1].
void hermite(const Vec3& p0, const Vec3& m0, const Vec3& p1, const Vec3& m1, double s, Vec3& position, Vec3& derivative)
{
    const double s2 = s * s, s3 = s2 * s;
    position = (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
    derivative = (6 * s2 - 6 * s) * p0 + (3 * s2 - 4 * s + 1) * m0 + (-6 * s2 + 6 * s) * p1 + (3 * s2 - 2 * s) * m1;
}

} // namespace

void BendyCurve::setChords()
{
    first = glm::length(mid - start);
    second = glm::length(end - mid);
}

void BendyCurve::at(double u, Vec3& position, Vec3& derivative) const
{
    u = std::clamp(u, 0.0, 1.0);
    const Vec3 midTangentScaled = midTangent * (0.5 * (first + second));
    if (u <= 0.5) {
        hermite(start, startTangent * first, mid, midTangentScaled, 2.0 * u, position, derivative);
    } else {
        hermite(mid, midTangentScaled, end, endTangent * second, 2.0 * u - 1.0, position, derivative);
    }
    derivative *= 2.0; // per unit of u, which spans each piece in half
}

double BendyCurve::parameterAtLength(double share) const
{
    std::array<double, kSamples + 1> arc{};
    Vec3 previous, d;
    at(0.0, previous, d);
    for (int i = 1; i <= kSamples; ++i) {
        Vec3 p;
        at(double(i) / kSamples, p, d);
        arc[i] = arc[i - 1] + glm::length(p - previous);
        previous = p;
    }
    if (arc[kSamples] < 1e-12)
        return share;
    const double wanted = std::clamp(share, 0.0, 1.0) * arc[kSamples];
    const auto it = std::lower_bound(arc.begin() + 1, arc.end(), wanted);
    const int i = std::min(int(it - arc.begin()), kSamples);
    const double span = arc[i] - arc[i - 1];
    const double t = span > 1e-15 ? (wanted - arc[i - 1]) / span : 0.0;
    return (double(i - 1) + t) / kSamples;
}

namespace {

// The target positions, world.
Vec3 at(const CompiledConstraint& c, const std::vector<Affine>& world, std::size_t k)
{
    return world[c.targets[bendTargetsBegin(c) + k]].translation;
}

Vec3 unit(const Vec3& v, const Vec3& fallback)
{
    const double length = glm::length(v);
    return length > 1e-12 ? v / length : fallback;
}

// `from` turned towards `to` by `angle` radians in their plane (`between` the
// angle between them, > angle).
Vec3 turnedTowards(const Vec3& from, const Vec3& to, double between, double angle)
{
    return (std::sin(between - angle) * from + std::sin(angle) * to) / std::sin(between);
}

} // namespace

BendyCurve bendyCurveOf(const CompiledConstraint& c, const std::vector<Affine>& world)
{
    const std::size_t b = bendTargetsBegin(c);
    const Vec3 start = at(c, world, 0), middle = at(c, world, 1), end = at(c, world, 2);
    const Vec3 upper = unit(middle - start, Vec3(1, 0, 0)), lower = unit(end - middle, upper);
    // The tangents at the middle joint: each bone turned towards the other
    // until they are no more than the rest angle apart.
    Vec3 in = upper, out = lower;
    const double between = std::acos(std::clamp(glm::dot(upper, lower), -1.0, 1.0));
    if (between > c.restKink + 1e-12 && std::sin(between) > 1e-9) {
        const double turn = 0.5 * (between - c.restKink);
        in = turnedTowards(upper, lower, between, turn);
        out = turnedTowards(lower, upper, between, turn);
    }
    // The tweak's own turn, world: its rotation relative to its space.
    const Mat3 tweak = world[c.targets[b + 3]].rotation() * glm::transpose(world[c.targets[b + 4]].rotation());
    BendyCurve curve;
    curve.mid = at(c, world, 5);
    curve.midTangent = world[c.targets[b + 5]].rotation() * c.localTangents[0];
    if (c.bendyLower) {
        curve.start = at(c, world, 3);
        curve.startTangent = tweak * out;
        curve.end = end;
        curve.endTangent = lower;
    } else {
        curve.start = start;
        curve.startTangent = upper;
        curve.end = at(c, world, 3);
        curve.endTangent = tweak * in;
    }
    curve.setChords();
    return curve;
}

std::string prepareBendy(CompiledConstraint& c, const std::vector<Affine>& rest)
{
    const std::size_t b = bendTargetsBegin(c);
    if (c.targets.size() != b + 6)
        return "needs six targets after the twist's own to be bendy (limb start, middle joint, limb end, tweak, tweak space, "
               "bend control)";
    const Vec3 start = at(c, rest, 0), middle = at(c, rest, 1), end = at(c, rest, 2);
    if (glm::length(middle - start) < 1e-9 || glm::length(end - middle) < 1e-9)
        return "its limb joints are at the same place";
    const Vec3 upper = glm::normalize(middle - start), lower = glm::normalize(end - middle);
    c.restKink = std::acos(std::clamp(glm::dot(upper, lower), -1.0, 1.0));
    c.localTangents = {glm::transpose(rest[c.targets[b + 5]].rotation()) * (c.bendyLower ? lower : upper)};
    return {};
}

void bendJoint(const CompiledConstraint& c, const std::vector<Affine>& world, const Vec3& boneAxis, Mat3& twisted,
               Vec3& position)
{
    const BendyCurve curve = bendyCurveOf(c, world);
    const double u = c.byLength ? curve.parameterAtLength(c.fraction) : c.fraction;
    Vec3 derivative;
    curve.at(u, position, derivative);
    if (glm::length(derivative) < 1e-12 || glm::length(boneAxis) < 1e-12)
        return;
    const Vec3 from = glm::normalize(boneAxis), to = glm::normalize(derivative);
    const double d = glm::dot(from, to);
    if (d < -1.0 + 1e-9)
        return; // the curve doubles back on the bone: no defined swing, keep the twist's own aim
    const Vec3 axis = glm::cross(from, to);
    twisted = glm::mat3_cast(glm::normalize(Quat(1.0 + d, axis.x, axis.y, axis.z))) * twisted;
}

} // namespace rs::eval
