#include "eval/SplineCurve.h"

#include "eval/RigProgram.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rs::eval {

namespace {

constexpr std::size_t kMaxControls = 16;

struct Controls {
    std::array<Vec3, kMaxControls> position;
    std::array<Quat, kMaxControls> rotation;
    std::array<Vec3, kMaxControls> tangent; // world, unit
    int count = 0;
};

Controls gather(const CompiledConstraint& c, const std::vector<Affine>& world)
{
    Controls k;
    k.count = int(c.targets.size());
    for (int i = 0; i < k.count; ++i) {
        const Affine& t = world[c.targets[i]];
        k.position[i] = t.translation;
        k.rotation[i] = rotationOf(t);
        k.tangent[i] = k.rotation[i] * c.localTangents[i];
    }
    return k;
}

// Loosens the tangent at an end control (`end`, with `neighbour` the control
// next to it) by its rigidity: 1 keeps the control's own tangent, 0 aims it
// along the chord to the neighbour (the same direction at rest).
void loosenEnd(Controls& k, int end, int neighbour, double rigidity)
{
    const Vec3 chord = end < neighbour ? k.position[neighbour] - k.position[end] : k.position[end] - k.position[neighbour];
    const double length = glm::length(chord);
    if (rigidity >= 1.0 || length < 1e-12)
        return;
    const Vec3 blended = glm::mix(chord / length, k.tangent[end], std::max(rigidity, 0.0));
    if (const double b = glm::length(blended); b > 1e-9) // opposite directions half way: keep the control's
        k.tangent[end] = blended / b;
}

int segmentOf(const Controls& k, double u, double& s)
{
    const int segment = std::clamp(int(std::floor(u)), 0, k.count - 2);
    s = u - segment;
    return segment;
}

// Hermite position and derivative at parameter u in [0, count - 1].
void curveAt(const Controls& k, double u, Vec3& position, Vec3& derivative)
{
    double s;
    const int i = segmentOf(k, u, s);
    const Vec3 &p0 = k.position[i], &p1 = k.position[i + 1];
    const double chord = glm::length(p1 - p0);
    const Vec3 m0 = k.tangent[i] * chord, m1 = k.tangent[i + 1] * chord;
    const double s2 = s * s, s3 = s2 * s;
    position = (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
    derivative = (6 * s2 - 6 * s) * p0 + (3 * s2 - 4 * s + 1) * m0 + (-6 * s2 + 6 * s) * p1 + (3 * s2 - 2 * s) * m1;
}

Quat between(const Vec3& from, const Vec3& to)
{
    const double d = glm::dot(from, to);
    if (d < -1.0 + 1e-12) {
        Vec3 axis = glm::cross(Vec3(1, 0, 0), from);
        if (glm::length(axis) < 1e-6) axis = glm::cross(Vec3(0, 1, 0), from);
        return glm::angleAxis(glm::pi<double>(), glm::normalize(axis));
    }
    const Vec3 c = glm::cross(from, to);
    return glm::normalize(Quat(1.0 + d, c.x, c.y, c.z));
}

// The curve frame: the controls' rotations blended, turned so the chain axis
// follows the curve's tangent.
Mat3 frameAt(const CompiledConstraint& c, const Controls& k, double u, const Vec3& derivative)
{
    double s;
    const int i = segmentOf(k, u, s);
    const Quat q = glm::slerp(k.rotation[i], k.rotation[i + 1], std::clamp(s, 0.0, 1.0));
    const Vec3 axis = q * glm::normalize(glm::mix(c.localTangents[i], c.localTangents[i + 1], std::clamp(s, 0.0, 1.0)));
    const double length = glm::length(derivative);
    if (length < 1e-12)
        return glm::mat3_cast(q);
    return glm::mat3_cast(between(axis, derivative / length) * q);
}

// Cumulative chord lengths at `perSegment` samples per segment.
void arcTable(const Controls& k, int perSegment, std::vector<double>& arc)
{
    const int count = perSegment * (k.count - 1) + 1;
    Vec3 previous, derivative;
    curveAt(k, 0.0, previous, derivative);
    arc[0] = 0.0;
    for (int i = 1; i < count; ++i) {
        Vec3 p;
        curveAt(k, double(i) / perSegment, p, derivative);
        arc[i] = arc[i - 1] + glm::length(p - previous);
        previous = p;
    }
}

double arcAt(const std::vector<double>& arc, int perSegment, int count, double u)
{
    const double x = u * perSegment;
    const int i = std::clamp(int(std::floor(x)), 0, count - 2);
    return arc[i] + (arc[i + 1] - arc[i]) * (x - i);
}

// The parameter where the arc length reaches `length`; `beyond` gets what is
// left past the curve's end (negative: before its start).
double parameterAt(const std::vector<double>& arc, int perSegment, int count, double length, double& beyond)
{
    beyond = 0.0;
    if (length < 0.0) {
        beyond = length;
        return 0.0;
    }
    if (length >= arc[count - 1]) {
        beyond = length - arc[count - 1];
        return double(count - 1) / perSegment;
    }
    const auto it = std::upper_bound(arc.begin(), arc.begin() + count, std::max(length, 0.0));
    const int i = std::clamp(int(it - arc.begin()) - 1, 0, count - 2);
    const double span = arc[i + 1] - arc[i];
    return (i + (span > 0.0 ? (length - arc[i]) / span : 0.0)) / perSegment;
}

} // namespace

std::string prepareSpline(CompiledConstraint& c, const std::vector<Affine>& rest)
{
    const std::size_t n = c.targets.size();
    if (n < 2 || n > kMaxControls)
        return "a spline needs 2 to 16 control targets; it has " + std::to_string(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 before = rest[c.targets[i > 0 ? i - 1 : i]].translation;
        const Vec3 after = rest[c.targets[i + 1 < n ? i + 1 : i]].translation;
        if (glm::length(after - before) < 1e-9)
            return "two spline controls are at the same place";
        const Vec3 tangent = glm::normalize(after - before);
        c.localTangents.push_back(glm::transpose(rest[c.targets[i]].rotation()) * tangent);
    }
    const Controls k = gather(c, rest);
    const int count = c.samplesPerSegment * int(n - 1) + 1;
    std::vector<double> arc(count);
    arcTable(k, c.samplesPerSegment, arc);
    c.restLength = arc.back();
    for (model::RigNodeIndex d : c.driven) {
        const Vec3 target = rest[d].translation;
        auto distance = [&](double u) {
            Vec3 p, derivative;
            curveAt(k, u, p, derivative);
            return glm::length(p - target);
        };
        // Closest point: a coarse scan, then a golden-section search around it.
        const int coarse = 32 * int(n - 1);
        double best = 0.0, bestDistance = distance(0.0);
        for (int i = 1; i <= coarse; ++i)
            if (const double u = double(i) * double(n - 1) / coarse, dd = distance(u); dd < bestDistance)
                best = u, bestDistance = dd;
        double lo = std::max(0.0, best - double(n - 1) / coarse), hi = std::min(double(n - 1), best + double(n - 1) / coarse);
        const double g = (std::sqrt(5.0) - 1.0) / 2.0;
        for (int it = 0; it < 48; ++it) { // the bracket shrinks to 1e-10 of a segment
            const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
            if (distance(a) < distance(b)) hi = b; else lo = a;
        }
        const double u = 0.5 * (lo + hi);
        Vec3 p, derivative;
        curveAt(k, u, p, derivative);
        c.parameters.push_back(u);
        c.restArc.push_back(arcAt(arc, c.samplesPerSegment, count, u));
        c.curveOffsets.push_back(Affine{frameAt(c, k, u, derivative), p}.inverse() * rest[d]);
    }
    return {};
}

std::vector<Vec3> restCurvePoints(const std::vector<Affine>& targets, int count, bool byLength)
{
    const std::size_t n = targets.size();
    if (n < 2 || n > kMaxControls || count < 2)
        return {};
    Controls k;
    k.count = int(n);
    for (std::size_t i = 0; i < n; ++i) { // at rest each tangent runs from the target before to the one after
        const Vec3 along = targets[i + 1 < n ? i + 1 : i].translation - targets[i > 0 ? i - 1 : i].translation;
        if (glm::length(along) < 1e-9)
            return {};
        k.position[i] = targets[i].translation;
        k.rotation[i] = rotationOf(targets[i]);
        k.tangent[i] = glm::normalize(along);
    }
    constexpr int kPerSegment = 256;
    const int samples = kPerSegment * (k.count - 1) + 1;
    std::vector<double> arc(byLength ? samples : 0);
    if (byLength)
        arcTable(k, kPerSegment, arc);
    std::vector<Vec3> points;
    for (int j = 0; j < count; ++j) {
        double u = double(k.count - 1) * j / (count - 1), beyond = 0.0;
        if (byLength)
            u = parameterAt(arc, kPerSegment, samples, arc.back() * j / (count - 1), beyond);
        Vec3 position, derivative;
        curveAt(k, u, position, derivative);
        points.push_back(position);
    }
    return points;
}

void solveSpline(const CompiledConstraint& c, const Pose& pose, EvalState& state)
{
    std::vector<Affine>& world = state.world;
    Controls k = gather(c, world);
    if (c.rigidityStartChannel >= 0)
        loosenEnd(k, 0, 1, pose[c.rigidityStartChannel]);
    if (c.rigidityEndChannel >= 0)
        loosenEnd(k, k.count - 1, k.count - 2, pose[c.rigidityEndChannel]);
    const double scale = c.chainParent != model::kNoNode ? world[c.chainParent].scale().x / c.restParentScale : 1.0;
    const double stretch = c.stretchChannel >= 0 ? std::clamp(pose[c.stretchChannel], 0.0, 1.0) : 1.0;
    const int count = c.samplesPerSegment * (k.count - 1) + 1;
    const double volume = c.volumeChannel >= 0 ? std::clamp(pose[c.volumeChannel], 0.0, 1.0) : 0.0;
    const double slide = c.slideChannel >= 0 ? pose[c.slideChannel] : 0.0;
    if (stretch < 1.0 || volume > 0.0 || slide != 0.0 || c.scaleStretch)
        arcTable(k, c.samplesPerSegment, state.arcLengths);
    // Slid with the stretch, the shift grows with the curve as the joints' spacing does.
    const double stretchedSlide = slide != 0.0 && c.restLength > 0.0 ? slide * state.arcLengths[count - 1] / c.restLength : 0.0;
    // Volume: the chain's stretch (by the stretch share) thins it across, a squash thickens it.
    // Stretch by scale: the joints also grow along their bones by it.
    double across = 1.0, along = 1.0;
    if ((volume > 0.0 || c.scaleStretch) && c.restLength > 0.0) {
        const double s = std::max(1.0 + stretch * (state.arcLengths[count - 1] / (c.restLength * scale) - 1.0), 1e-3);
        across = std::pow(s, -0.5 * volume);
        along = c.scaleStretch ? s : 1.0;
    }
    for (std::size_t j = 0; j < c.driven.size(); ++j) {
        double u = c.parameters[j], beyond = 0.0, stretchedBeyond = 0.0;
        if (slide != 0.0 && stretch > 0.0) {
            const double at = arcAt(state.arcLengths, c.samplesPerSegment, count, u) + stretchedSlide;
            u = parameterAt(state.arcLengths, c.samplesPerSegment, count, at, stretchedBeyond);
        }
        if (stretch < 1.0) {
            const double kept = parameterAt(state.arcLengths, c.samplesPerSegment, count, (c.restArc[j] + slide) * scale, beyond);
            u = kept + (u - kept) * stretch;
            beyond *= 1.0 - stretch;
        }
        beyond += stretchedBeyond * stretch;
        Vec3 position, derivative;
        curveAt(k, u, position, derivative);
        if (beyond != 0.0 && glm::length(derivative) > 1e-12)
            position += glm::normalize(derivative) * beyond;
        Affine& driven = world[c.driven[j]];
        driven = compose(frameAt(c, k, u, derivative), Vec3(scale), position) * c.curveOffsets[j];
        if ((across != 1.0 || along != 1.0) && j + 1 < c.driven.size()) {
            driven.linear[0] *= along;
            driven.linear[1] *= across;
            driven.linear[2] *= across;
        }
    }
}

} // namespace rs::eval
