// The evaluation engine's compile checks and plain pieces on the prop
// sample: constraint cycles and attribute references that are not
// attributes of their node are rejected with their ids, constraints whose
// settings do not fit are skipped with a warning each, aim, point and scale
// constraints follow their targets, and Euler angles round-trip in every
// rotate order.
#include "EvalTestSupport.h"

#include <gtest/gtest.h>

#include <random>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

TEST(Evaluator, CompileRejectsConstraintCyclesWithTheirIds)
{
    PosedRig r("prop");
    model::Rig rig = r.rig;
    const auto chest = *rig.findPath("chest::ctrls.xform"), lid = *rig.findPath("lid::ctrls.xform");
    rig.constraints.push_back({{}, "test::cns.a", model::kNoId, {chest}, {lid}, model::ParentConstraint{}});
    const auto program = eval::RigProgram::compile(rig);
    ASSERT_FALSE(program.ok());
    EXPECT_NE(program.diagnostics().front().message.find("cycle"), std::string::npos);
    EXPECT_NE(program.diagnostics().front().message.find("test::cns.a"), std::string::npos);
}

TEST(Evaluator, CompileRejectsEveryAttributeReferenceThatIsNotAnAttributeOfItsNode)
{
    PosedRig r("prop");
    model::Rig rig = r.rig;
    const auto chest = *rig.findPath("chest::ctrls.xform"), lid = *rig.findPath("lid::ctrls.xform");
    auto& drive = std::get<model::DriveConstraint>(rig.constraints.front().settings); // world::cns.post_scale
    drive.value = {chest, "nothing"};
    rig.constraints.push_back({{}, "test::cns.blend", model::kNoId, {*rig.findPath("antenna::skin.0")}, {chest, lid},
                               model::BlendConstraint{.weight = {model::kNoNode, "ik_blend"}}});
    const auto program = eval::RigProgram::compile(rig);
    ASSERT_FALSE(program.ok());
    ASSERT_EQ(program.diagnostics().size(), 2u) << formatAll(program.diagnostics());
    EXPECT_EQ(program.diagnostics()[0].message,
              "constraint 'world::cns.post_scale': its value attribute 'nothing' is not an attribute of node 'chest::ctrls.xform'");
    EXPECT_EQ(program.diagnostics()[1].message, "constraint 'test::cns.blend': its weight attribute 'ik_blend' names no node of the rig");
    EXPECT_EQ(program.diagnostics()[0].subject, Subject::ofNode(rig.constraints.front().key)) << "the log selects the constraint";
    EXPECT_FALSE(rig.constraints.front().key.isRoot());
}

TEST(Evaluator, ConstraintsWhoseSettingsDoNotFitAreSkippedWithAWarningEach)
{
    PosedRig r("prop");
    model::Rig rig = r.rig;
    const auto antenna = *rig.findPath("antenna::skin.3"), lid = *rig.findPath("lid::ctrls.xform");
    const model::AttributeRef postScale{*rig.findPath("world::grps.post"), "post_scale"};
    rig.constraints.push_back({{}, "t::point", model::kNoId, {antenna}, {lid}, model::PointConstraint{.weights = {1.0, 1.0}}});
    rig.constraints.push_back({{}, "t::aim", model::kNoId, {antenna}, {lid}, model::AimConstraint{.aim = model::Axis::Z, .up = model::Axis::Z}});
    rig.constraints.push_back({{}, "t::drive", model::kNoId, {antenna}, {},
                               model::DriveConstraint{.value = postScale, .response = model::DriveClamped{.low = 2.0, .high = 1.0}}});
    const auto program = eval::RigProgram::compile(rig);
    ASSERT_TRUE(program.ok()) << formatAll(program.diagnostics());
    ASSERT_EQ(program.diagnostics().size(), 3u) << formatAll(program.diagnostics());
    EXPECT_EQ(program.diagnostics()[0].message, "constraint 't::point': has 2 weights for 1 target; it is not evaluated");
    EXPECT_EQ(program.diagnostics()[1].message,
              "constraint 't::aim': aim and up axes must be two different axes of x, y, z; it is not evaluated");
    EXPECT_EQ(program.diagnostics()[2].message, "constraint 't::drive': its low limit is above its high limit; it is not evaluated");
    auto state = program->makeState();
    program->evaluate(program->channels().defaults(), state);
    EXPECT_LT(maxAbsDifference(state.worldMatrix(antenna), rig.nodes[antenna].worldMatrix), 1e-9);
}

TEST(Evaluator, AimPointScaleConstraintsFollowTheirTargets)
{
    PosedRig r("prop");
    model::Rig rig = r.rig;
    const auto antenna = *rig.findPath("antenna::skin.3"), lid = *rig.findPath("lid::ctrls.xform"), chest = *rig.findPath("chest::ctrls.xform");
    rig.constraints.push_back({{}, "t::aim", model::kNoId, {antenna}, {lid}, model::AimConstraint{.aim = model::Axis::Y, .up = model::Axis::X}});
    rig.constraints.push_back({{}, "t::point", model::kNoId, {*rig.findPath("antenna::skin.0")}, {chest, lid}, model::PointConstraint{}});
    rig.constraints.push_back({{}, "t::scale", model::kNoId, {*rig.findPath("antenna::skin.1")}, {chest}, model::ScaleConstraint{}});
    auto program = eval::RigProgram::compile(rig);
    ASSERT_TRUE(program.ok());
    auto state = program->makeState();
    Pose pose = program->channels().defaults();
    program->evaluate(pose, state);
    for (model::RigNodeIndex i = 0; i < rig.nodes.size(); ++i)
        ASSERT_LT(maxAbsDifference(state.worldMatrix(i), rig.nodes[i].worldMatrix), 1e-9) << rig.nodes[i].path;
    const int lidTx = program->channels().transformOf(lid), chestTx = program->channels().transformOf(chest);
    pose[lidTx + 0] = 0.4;     // the lid moves sideways
    pose[chestTx + 6] = 2.0;   // the chest scales in x
    program->evaluate(pose, state);
    const Vec3 origin = translationOf(state.worldMatrix(antenna));
    const Vec3 aim = glm::normalize(translationOf(state.worldMatrix(lid)) - origin);
    const Mat3 restAimFrame = Mat3(rig.nodes[antenna].worldMatrix);
    const Vec3 restAim = glm::normalize(translationOf(rig.nodes[lid].worldMatrix) - translationOf(rig.nodes[antenna].worldMatrix));
    // The antenna keeps its rest angle to the lid direction.
    EXPECT_NEAR(glm::dot(Mat3(state.worldMatrix(antenna)) * (glm::transpose(restAimFrame) * restAim), aim), 1.0, 1e-9);
    // The antenna's second joint stretches 2x along the chest's x (world x), whichever of its own axes lies there.
    const auto antenna1 = *rig.findPath("antenna::skin.1");
    const Vec3 worldXInRest = glm::transpose(Mat3(rig.nodes[antenna1].worldMatrix)) * Vec3(1, 0, 0);
    EXPECT_NEAR(glm::length(Mat3(state.worldMatrix(antenna1)) * worldXInRest), 2.0, 1e-9);
    EXPECT_GT(translationOf(state.worldMatrix(*rig.findPath("antenna::skin.0"))).x, 0.1); // half of the lid's move, weighted
}

TEST(Evaluator, EulerAnglesRoundTripInEveryRotateOrder)
{
    std::mt19937 random(3);
    std::uniform_real_distribution<double> angle(-179.0, 179.0);
    for (int order = 0; order < 6; ++order)
        for (int trial = 0; trial < 200; ++trial) {
            Vec3 degrees(angle(random), angle(random) / 2.0, angle(random));
            if (trial == 0) degrees.y = 90.0; // gimbal lock still gives the same rotation
            const auto o = static_cast<model::RotateOrder>(order);
            const Mat3 r = eval::eulerRotation(degrees, o);
            const Mat3 back = eval::eulerRotation(eval::eulerDegrees(r, o), o);
            for (int c = 0; c < 3; ++c)
                EXPECT_LT(glm::length(r[c] - back[c]), 1e-9) << model::rotateOrderName(o) << " " << trial;
        }
}

} // namespace
} // namespace rs
