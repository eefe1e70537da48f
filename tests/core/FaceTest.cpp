// The face templates as an animator checks them on the built and evaluated
// face sample (issue 22 item 6): eyes that aim at a shared look target with
// lids that follow the gaze and close on blink, a jaw that carries the lips
// and the mouth corners by their shares, and the parts mirrored on L/R.
#include "EvalTestSupport.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <map>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

Vec3 axisAt(const PosedRig& r, const std::string& id, int column)
{
    return glm::normalize(r.state().world[r.index(id)].rotation()[column]);
}

// The face sample's value of a number option of one of its instances (the template's default when unset).
double sampleOption(const std::string& instance, const std::string& option)
{
    const model::GuideDocument guide = test::loadSample("face");
    const model::TemplateInstance* owner = guide.instanceNamed(instance);
    const auto it = owner->options.find(option);
    const Value value = it != owner->options.end() ? it->second : test::builtinTemplates().find(owner->templateId)->findOpt(option)->value;
    return std::holds_alternative<double>(value) ? std::get<double>(value) : double(std::get<long long>(value));
}

// Pitch of a frame's X axis above the horizontal, degrees.
double pitch(const Vec3& x) { return glm::degrees(std::asin(std::clamp(x.y, -1.0, 1.0))); }

TEST(Face, SampleBuildsEveryPartOnBothSides)
{
    PosedRig r("face");
    ASSERT_TRUE(r.ok());
    for (const char* id : {"jaw::ctrls.jaw", "jaw::ctrls.chin", "eye.L::ctrls.eye", "eye.R::ctrls.eye", "eye.L::ctrls.look",
                           "eye.L::ctrls.lid_up", "eye.R::ctrls.lid_low", "brow.L::ctrls.brow", "brow.R::ctrls.fk.2",
                           "mouth::ctrls.lip_up", "mouth::ctrls.lip_low", "mouth::ctrls.corner_L", "mouth::ctrls.corner_R"})
        EXPECT_TRUE(r.rig.findPath(id)) << id;
    for (const char* id : {"eye", "lid_up", "lid_low"}) {
        const Vec3 left = r.restPosition(std::string("eye.L::skin.") + id), right = r.restPosition(std::string("eye.R::skin.") + id);
        EXPECT_NEAR(left.x, -right.x, 1e-9) << id;
        EXPECT_NEAR(left.y, right.y, 1e-9) << id;
    }
    const Vec3 cornerL = r.restPosition("mouth::skin.corner_L"), cornerR = r.restPosition("mouth::skin.corner_R");
    EXPECT_GT(cornerL.x, 0.01);
    EXPECT_NEAR(cornerL.x, -cornerR.x, 1e-9);
    // The look control sits between the eyes, in front of them.
    const Vec3 look = r.restPosition("eye.L::ctrls.look");
    EXPECT_NEAR(look.x, 0.0, 1e-9);
    EXPECT_GT(look.z, r.restPosition("eye.L::skin.eye").z + 0.2);
}

TEST(Face, EyesFollowTheLookTargetAndTheLidsFollowTheGaze)
{
    PosedRig r("face");
    ASSERT_TRUE(r.ok());
    // A mirrored branch's frames are reflections (W' = M W M): its X axes point
    // the other way, so its forward is -X.
    auto forward = [&](const std::string& side, const std::string& id) {
        return axisAt(r, side + "::" + id, 0) * (side == "eye.R" ? -1.0 : 1.0);
    };
    Pose pose = r.defaults();
    r.evaluate(pose);
    const double follow = sampleOption("eye", "lid_follow");
    ASSERT_GT(follow, 0.0);
    std::map<std::string, double> rest;
    for (const std::string side : {"eye.L", "eye.R"})
        for (const std::string id : {"skin.eye", "skin.lid_up", "skin.lid_low"})
            rest[side + id] = pitch(forward(side, id));
    pose[r.channel("eye.L::ctrls.look", "ty")] = 0.25; // look up (the target is 0.6 m ahead): both eyes turn up
    r.evaluate(pose);
    for (const std::string side : {"eye.L", "eye.R"}) {
        const double eye = pitch(forward(side, "skin.eye")) - rest[side + "skin.eye"];
        EXPECT_GT(eye, 15.0) << side;
        // Each lid turns by lid_follow (0.5 in the sample) of the eye's turn.
        const double up = pitch(forward(side, "skin.lid_up")) - rest[side + "skin.lid_up"];
        const double low = pitch(forward(side, "skin.lid_low")) - rest[side + "skin.lid_low"];
        EXPECT_NEAR(up, follow * eye, 0.05 * eye) << side;
        EXPECT_NEAR(low, follow * eye, 0.05 * eye) << side;
        // The eye aims at its own target exactly.
        const Vec3 at = r.position(side + "::skin.eye"), target = r.position(side + "::ctrls.target");
        EXPECT_GT(glm::dot(forward(side, "skin.eye"), glm::normalize(target - at)), 1.0 - 1e-9) << side;
    }
}

TEST(Face, BlinkClosesTheLidsWhereTheyMeet)
{
    PosedRig r("face");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    for (const char* side : {"eye.L", "eye.R"}) {
        pose[r.channel(std::string(side) + "::ctrls.eye", "blink")] = 1.0;
        r.evaluate(pose);
        const Vec3 up = axisAt(r, std::string(side) + "::skin.lid_up", 0), low = axisAt(r, std::string(side) + "::skin.lid_low", 0);
        EXPECT_GT(glm::dot(up, low), 1.0 - 1e-9) << side << ": the lids meet";
        pose[r.channel(std::string(side) + "::ctrls.eye", "blink")] = 0.0;
    }
    r.evaluate(pose);
    EXPECT_LT(glm::dot(axisAt(r, "eye.L::skin.lid_up", 0), axisAt(r, "eye.L::skin.lid_low", 0)), 0.9) << "open at rest";
}

TEST(Face, TheJawCarriesTheLowerLipMostOfTheWayTheCornersLessAndTheUpperLipALittle)
{
    PosedRig r("face");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    r.evaluate(pose);
    auto rest = [&](const std::string& id) { return r.position(id); };
    const Vec3 lipUp = rest("mouth::skin.lip_up"), lipLow = rest("mouth::skin.lip_low"), corner = rest("mouth::skin.corner_L"),
               chin = rest("jaw::skin.chin"), cornerR = rest("mouth::skin.corner_R");
    const int open = r.channel("jaw::ctrls.jaw", "rz");
    pose[open] = -20.0; // the jaw opens (about its side axis)
    r.evaluate(pose);
    const Vec3 chinMove = r.position("jaw::skin.chin") - chin;
    ASSERT_GT(glm::length(chinMove), 0.01);
    const double upMove = glm::length(r.position("mouth::skin.lip_up") - lipUp);
    const double lowMove = glm::length(r.position("mouth::skin.lip_low") - lipLow);
    const double cornerMove = glm::length(r.position("mouth::skin.corner_L") - corner);
    EXPECT_GT(lowMove, 0.005);
    // Where the jaw would carry each point alone (rigidly), each part goes its share of the way: in the sample the
    // lower lip 0.9 (it lags the chin a little), the corners 0.4 (they stretch toward the cheeks) and the upper lip
    // 0.1 (it does not look pinned to the skull).
    pose[open] = 0.0;
    r.evaluate(pose);
    const auto jawRest = r.state().world[r.index("jaw::ctrls.jaw")];
    pose[open] = -20.0;
    r.evaluate(pose);
    const auto jawOpen = r.state().world[r.index("jaw::ctrls.jaw")];
    auto carried = [&](const Vec3& p) { return Vec3(jawOpen.matrix() * glm::inverse(jawRest.matrix()) * Vec4(p, 1.0)); };
    const double lowShare = sampleOption("mouth", "lip_low_jaw"), cornerShare = sampleOption("mouth", "corner_jaw"),
                 upShare = sampleOption("mouth", "lip_up_jaw");
    ASSERT_GT(upShare, 0.0);
    ASSERT_GT(lowShare, cornerShare) << "the sample's lower lip follows the jaw more than its corners";
    ASSERT_GT(cornerShare, upShare);
    EXPECT_NEAR(lowMove, lowShare * glm::length(carried(lipLow) - lipLow), 0.02 * lowMove);
    EXPECT_NEAR(cornerMove, cornerShare * glm::length(carried(corner) - corner), 0.1 * cornerMove);
    EXPECT_GT(upMove, 1e-4);
    EXPECT_NEAR(upMove, upShare * glm::length(carried(lipUp) - lipUp), 0.1 * upMove);
    EXPECT_NEAR(glm::length(r.position("mouth::skin.corner_R") - cornerR), cornerMove, 1e-9) << "both corners";
}

} // namespace
} // namespace rs
