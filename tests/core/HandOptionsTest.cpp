// digit.finger's controller-hierarchy and orientation options on the biped's
// hands, as an animator checks them: the hand's drives land in the pose group
// (do_pose) and the finger controls stay at zero; parent_scale decides whether
// the phalanges take the base's scale; flip_orient poses both hands as mirror
// images with the same values; a fist still curls every finger however the
// phalanges are oriented; incremental = full.
#include "EvalTestSupport.h"
#include "IncrementalCheck.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

const std::vector<std::string> kFingers = {"thumb", "index", "middle", "ring", "pinky"};

// The biped with `options` set on every digit.finger.
model::GuideDocument bipedWith(const std::map<std::string, Value>& options)
{
    model::GuideDocument guide = test::loadSample("biped");
    for (const auto& instance : guide.instances())
        if (instance.templateId == "digit.finger")
            for (const auto& [name, value] : options)
                guide.instance(instance.id)->options[name] = value;
    return guide;
}

double angleDegrees(const Vec3& a, const Vec3& b)
{
    return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)));
}

// The bend at each knuckle (between one bone and the next, by skin joint
// positions), in degrees, for the last evaluation.
std::vector<double> knuckleBends(const PosedRig& r, const std::string& finger)
{
    const int joints = finger.rfind("thumb", 0) == 0 ? 3 : 4;
    std::vector<double> out;
    for (int i = 1; i + 1 < joints; ++i) {
        auto at = [&](int k) { return r.position(finger + "::skin." + std::to_string(k)); };
        out.push_back(angleDegrees(at(i) - at(i - 1), at(i + 1) - at(i)));
    }
    return out;
}

TEST(HandRig, PoseGroupsCarryTheHandsDrivesAndTheFingerControlsStayAtZero)
{
    PosedRig plain("biped"), posed(bipedWith({{"do_pose", Value(true)}}));
    ASSERT_TRUE(plain.ok() && posed.ok());
    for (PosedRig* r : {&plain, &posed}) {
        Pose pose = r->defaults();
        pose[r->channel("hand.L::ctrls.hand", "fist")] = 0.7;
        pose[r->channel("hand.L::ctrls.hand", "spread")] = 15.0;
        pose[r->channel("index.L::ctrls.fk.0", "curl")] = 20.0;
        r->evaluate(pose);
    }
    for (const std::string& name : kFingers) {
        const std::string finger = name + ".L";
        for (int i = 0; i < (name == "thumb" ? 2 : 3); ++i) {
            const std::string k = std::to_string(i);
            // The skin bends exactly as it did with the drives on the offsets.
            EXPECT_LT(glm::length(posed.position(finger + "::skin." + k) - plain.position(finger + "::skin." + k)), 1e-9) << finger << k;
            const Mat4 offset = posed.state().world[posed.index(finger + "::roots.fk." + k)].matrix();
            const Mat4 group = posed.state().world[posed.index(finger + "::nodes.pose.fk." + k)].matrix();
            const Mat4 ctrl = posed.state().world[posed.index(finger + "::ctrls.fk." + k)].matrix();
            EXPECT_LT(maxAbsDifference(ctrl, group), 1e-12) << finger << k << ": the controller sits at zero in its pose group";
            const model::RigNode& offsetNode = test::node(posed.rig, finger + "::roots.fk." + k);
            const Mat4 parentNow = posed.state().world[offsetNode.parent].matrix();
            const Mat4 parentRest = posed.rig.nodes[offsetNode.parent].worldMatrix;
            EXPECT_LT(maxAbsDifference(glm::inverse(parentNow) * offset, glm::inverse(parentRest) * offsetNode.worldMatrix), 1e-9)
                << finger << k << ": the offset keeps its rest place under its parent";
            if (i > 0) // the bases (metacarpals) turn only with cup
                EXPECT_GT(maxAbsDifference(glm::inverse(offset) * group, Mat4(1.0)), 0.1) << finger << k << ": the pose group is turned";
        }
    }
    // Every drive of the fingers lands in a pose group.
    std::size_t drives = 0;
    for (const model::RigConstraint& c : posed.rig.constraints)
        for (const std::string& name : kFingers)
            if (c.kind() == model::ConstraintKind::Drive && c.path.rfind(name + ".", 0) == 0)
                for (model::RigNodeIndex d : c.driven) {
                    EXPECT_EQ(posed.rig.nodes[d].key.tag.rfind("nodes.pose.", 0), 0u) << c.path;
                    ++drives;
                }
    EXPECT_GT(drives, 40u);
}

TEST(HandRig, ParentScaleDecidesWhetherThePhalangesTakeTheBasesScale)
{
    for (const bool parentScale : {false, true}) {
        PosedRig r(bipedWith({{"parent_scale", Value(parentScale)}}));
        ASSERT_TRUE(r.ok());
        Pose pose = r.defaults();
        for (const char* s : {"sx", "sy", "sz"})
            pose[r.channel("index.L::ctrls.fk.0", s)] = 1.5; // the base (metacarpal) control
        r.evaluate(pose);
        for (int i = 1; i < 4; ++i) {
            const Mat3 m = r.state().world[r.index("index.L::skin." + std::to_string(i))].linear;
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(glm::length(m[k]), parentScale ? 1.5 : 1.0, 1e-9) << "parent_scale " << parentScale << " phalanx " << i;
        }
        // The first phalanx still sits at the end of the scaled base.
        const double base = glm::length(r.restPosition("index.L::skin.1") - r.restPosition("index.L::skin.0"));
        EXPECT_NEAR(glm::length(r.position("index.L::skin.1") - r.position("index.L::skin.0")), 1.5 * base, 1e-9);
    }
}

TEST(HandRig, FlipOrientPosesBothHandsAsMirrorImagesWithTheSameValues)
{
    PosedRig r(bipedWith({{"flip_orient", Value(true)}}));
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    for (const std::string side : {"L", "R"}) {
        pose[r.channel("hand." + side + "::ctrls.hand", "fist")] = 0.5;
        pose[r.channel("hand." + side + "::ctrls.hand", "spread")] = 10.0;
        pose[r.channel("index." + side + "::ctrls.fk.1", "rz")] = 20.0;
        pose[r.channel("index." + side + "::ctrls.fk.1", "ry")] = -15.0;
        pose[r.channel("thumb." + side + "::ctrls.fk.0", "rx")] = 12.0;
    }
    r.evaluate(pose);
    for (const std::string& name : kFingers)
        for (int i = 0; i < (name == "thumb" ? 3 : 4); ++i) {
            const std::string k = "::skin." + std::to_string(i);
            const Vec3 left = r.position(name + ".L" + k), right = r.position(name + ".R" + k);
            EXPECT_LT(glm::length(right - Vec3(-left.x, left.y, left.z)), 1e-9) << name << k;
        }
    // A fist still curls every finger on both sides.
    for (const std::string side : {"L", "R"})
        for (double bend : knuckleBends(r, "middle." + side))
            EXPECT_GT(bend, 30.0) << side;
}

TEST(HandRig, FistCurlsEveryFingerWhateverThePhalangesOrientation)
{
    // Phalanges aimed down +Y with Z on the bend, as Mikan's digits default.
    PosedRig r(bipedWith({{"orient", Value(std::string("auto"))}, {"aim_axis", Value(std::string("y"))},
                          {"up_axis", Value(std::string("z"))}, {"up_auto", Value(true)}}));
    ASSERT_TRUE(r.ok());
    for (const std::string side : {"L", "R"}) {
        r.evaluate(r.defaults());
        std::map<std::string, std::vector<double>> rest;
        for (const std::string& name : kFingers) {
            rest[name] = knuckleBends(r, name + "." + side);
            const Mat4 world = test::node(r.rig, name + "." + side + "::skin.1").worldMatrix;
            const Vec3 along = r.restPosition(name + "." + side + "::skin.2") - r.restPosition(name + "." + side + "::skin.1");
            EXPECT_GT(glm::dot(glm::normalize(Vec3(world[1])), glm::normalize(along)), 1.0 - 1e-9) << name << ": Y aims down the finger";
        }
        Pose pose = r.defaults();
        pose[r.channel("hand." + side + "::ctrls.hand", "fist")] = 1.0;
        r.evaluate(pose);
        for (const std::string& name : kFingers) {
            const std::vector<double> now = knuckleBends(r, name + "." + side);
            for (std::size_t i = 0; i < now.size(); ++i)
                EXPECT_NEAR(now[i] - rest[name][i], name == "thumb" ? 54.0 : 90.0, 1.0) << name << "." << side << " knuckle " << i + 1;
        }
    }
}

TEST(HandRig, FingerOptionsRebuildIncrementallyAsAFullBuild)
{
    model::GuideDocument guide = test::loadSample("biped");
    const model::InstanceId index = guide.instanceNamed("index")->id;
    rigging::BuildCache cache;
    test::buildAndCompare(guide, cache, "first build");
    const std::vector<std::pair<std::string, Value>> edits = {
        {"do_pose", Value(true)}, {"add_nodes", Value(std::string("[inf, c, dyn]"))}, {"parent_scale", Value(true)},
        {"rotate_order", Value(std::string("zyx"))}, {"flip_orient", Value(true)}, {"orient", Value(std::string("auto"))},
        {"up_auto", Value(true)}, {"orient", Value(std::string("chain"))}, {"do_pose", Value(false)}};
    for (const auto& [name, value] : edits) {
        guide.instance(index)->options[name] = value;
        test::buildAndCompare(guide, cache, name);
    }
}

} // namespace
} // namespace rs
