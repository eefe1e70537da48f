#include "rigging/builders/ChainOrient.h"

#include "rigging/builders/BuilderKit.h"
#include "rigging/builders/Builders.h"
#include "templates/Manifest.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace rs::rigging {

namespace {

bool declares(const BuildContext& ctx, const char* name) { return ctx.manifest().findOpt(name) != nullptr; }

// An axis option ("x", "-z"); an error naming it otherwise.
std::optional<Vec3> axisOption(const BuildContext& ctx, const char* name, const Vec3& fallback)
{
    if (!declares(ctx, name))
        return fallback;
    const std::string text = ctx.optionString(name);
    if (auto axis = templates::parseAxis(text))
        return axis;
    ctx.error("'" + text + "' is not an axis (x, y, z, -x, -y, -z)", name);
    return std::nullopt;
}

// The rotation of a guide joint's world matrix, without scale (rigidFrame).
Mat3 rotationOf(const Mat4& guideWorld) { return Mat3(rigidFrame(guideWorld)); }

Mat4 frameAt(const Mat3& rotation, const Vec3& position)
{
    Mat4 m(rotation);
    m[3] = Vec4(position, 1.0);
    return m;
}

// Any unit vector perpendicular to unit `v` (as kit::aimFrame picks it).
Vec3 anyPerpendicular(const Vec3& v)
{
    return glm::normalize(std::abs(v.y) < 0.9 ? glm::cross(v, Vec3(0.0, 1.0, 0.0)) : glm::cross(v, Vec3(1.0, 0.0, 0.0)));
}

// The smallest turn of `rotation`'s local aimAxis onto unit `aim`; a half
// turn about its upAxis where they are opposite.
Mat3 turnOnto(const Mat3& rotation, const Vec3& aim, const ChainOrient& o)
{
    const Vec3 from = glm::normalize(rotation * o.aimAxis);
    if (glm::dot(from, aim) < -1.0 + 1e-12)
        return glm::mat3_cast(glm::angleAxis(glm::pi<double>(), glm::normalize(rotation * o.upAxis))) * rotation;
    return glm::mat3_cast(Quat(from, aim)) * rotation;
}

} // namespace

std::optional<Mat3> aimRotation(const Vec3& aim, const Vec3& up, const Vec3& aimAxis, const Vec3& upAxis)
{
    Vec3 side = up - aim * glm::dot(up, aim);
    if (glm::length(side) < 1e-9)
        return std::nullopt;
    side = glm::normalize(side);
    // Columns are signed unit axes, so the products below are exact.
    const Mat3 local(aimAxis, upAxis, glm::cross(aimAxis, upAxis));
    const Mat3 world(aim, side, glm::cross(aim, side));
    return world * glm::transpose(local);
}

std::optional<ChainOrient> readChainOrient(const BuildContext& ctx, bool report)
{
    ChainOrient o;
    bool ok = true;
    if (declares(ctx, "orient")) {
        const std::string mode = ctx.optionString("orient");
        if (mode == "copy") o.mode = ChainOrient::Mode::Copy;
        else if (mode == "auto") o.mode = ChainOrient::Mode::Auto;
        else if (mode == "world") o.mode = ChainOrient::Mode::World;
        else if (report) // a template of its own with other labels (its enum let them through): the guides' frames
            ctx.warning("'" + mode + "' is no orientation this builder knows (copy, auto, world); the guide joints' own frames are used", "orient");
    }
    const auto aim = axisOption(ctx, "aim_axis", o.aimAxis);
    const auto up = axisOption(ctx, "up_axis", o.upAxis);
    if (aim && up && std::abs(glm::dot(*aim, *up)) > 0.5) {
        ctx.error("up_axis " + ctx.optionString("up_axis") + " lies along aim_axis " + ctx.optionString("aim_axis") +
                      " (equal or opposite); pick another axis", "up_axis");
        ok = false;
    }
    if (aim) o.aimAxis = *aim;
    if (up) o.upAxis = *up;
    ok = ok && aim && up;
    if (declares(ctx, "up_dir")) {
        const Value& v = ctx.option("up_dir");
        const Vec3 dir = std::holds_alternative<Vec3>(v) ? std::get<Vec3>(v) : Vec3(0.0);
        if (!(glm::length(dir) > 1e-9) || !std::isfinite(glm::length(dir))) {
            ctx.error("up_dir " + formatValue(v) + " is no direction (it needs a length)", "up_dir");
            ok = false;
        } else {
            o.upDir = glm::normalize(dir);
        }
    }
    if (declares(ctx, "up_auto"))
        o.upAuto = ctx.optionBool("up_auto");
    if (!ok)
        return std::nullopt;
    return o;
}

std::vector<Mat4> orientChain(const ChainOrient& o, const std::vector<Mat4>& guideWorld, bool aimAlways)
{
    const std::size_t n = guideWorld.size();
    std::vector<Vec3> points;
    for (const Mat4& m : guideWorld)
        points.push_back(translationOf(m));
    std::vector<Mat4> frames;
    if (o.mode != ChainOrient::Mode::Auto && !aimAlways) {
        for (std::size_t i = 0; i < n; ++i)
            frames.push_back(o.mode == ChainOrient::Mode::Copy ? rigidFrame(guideWorld[i]) : translationMatrix(points[i]));
        return frames;
    }
    if (n == 1)
        return {rigidFrame(guideWorld[0])};
    Vec3 upDir = o.upDir;
    if (o.upDirFromRootGuide) {
        const Vec3 rootUp = Mat3(rigidFrame(guideWorld[0])) * o.upAxis, first = points[1] - points[0];
        if (glm::length(first) > 1e-9 && glm::length(glm::cross(glm::normalize(first), rootUp)) > 1e-6)
            upDir = rootUp;
    }
    Vec3 normal = upDir; // the bend normal carried along (upAuto)
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 segment = i + 1 < n ? points[i + 1] - points[i] : Vec3(0.0);
        if (i + 1 == n || (glm::length(segment) < 1e-9 && !frames.empty())) { // the last joint, or on top of the next
            frames.push_back(frameAt(Mat3(frames.back()), points[i]));
            continue;
        }
        const Vec3 aim = glm::length(segment) < 1e-9 ? Mat3(rigidFrame(guideWorld[i])) * o.aimAxis : glm::normalize(segment);
        if (o.mode != ChainOrient::Mode::Auto) { // bones: copy or world, turned onto the segment
            const Mat3 base = o.mode == ChainOrient::Mode::Copy ? rotationOf(guideWorld[i]) : Mat3(1.0);
            frames.push_back(frameAt(turnOnto(base, aim, o), points[i]));
            continue;
        }
        if (o.upAuto && i + 2 < n)
            if (auto bend = kit::planeNormal(points[i], points[i + 1], points[i + 2]))
                normal = *bend;
        std::optional<Mat3> rotation = aimRotation(aim, o.upAuto ? normal : upDir, o.aimAxis, o.upAxis);
        if (!rotation && !frames.empty())
            rotation = aimRotation(aim, Mat3(frames.back()) * o.upAxis, o.aimAxis, o.upAxis);
        if (!rotation)
            rotation = aimRotation(aim, anyPerpendicular(aim), o.aimAxis, o.upAxis);
        frames.push_back(frameAt(*rotation, points[i]));
    }
    return frames;
}

std::vector<Mat4> orientFrames(const BuildContext& ctx, const std::vector<model::JointId>& chain, bool aimAlways,
                               bool rootGuideUp)
{
    std::vector<Mat4> guideWorld;
    for (model::JointId joint : chain)
        guideWorld.push_back(ctx.guideWorldMatrix(joint));
    return orientFrames(ctx, guideWorld, aimAlways, rootGuideUp);
}

std::vector<Mat4> orientFrames(const BuildContext& ctx, const std::vector<Mat4>& guideWorld, bool aimAlways, bool rootGuideUp)
{
    ChainOrient orient = readChainOrient(ctx, false).value_or(ChainOrient{}); // gather reported its problems
    orient.upDirFromRootGuide = rootGuideUp && !ctx.instance().options.count("up_dir");
    return orientChain(orient, guideWorld, aimAlways);
}

} // namespace rs::rigging
