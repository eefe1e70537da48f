// digit.finger's aim rig (target_weights, target_parent; Mikan's digit.legacy)
// on the biped's index finger, as an animator checks it: moving the target
// towards the palm bends each aimed phalanx onto its target (weight 1) or
// halfway by angle (0.5); the target rides with the hand; curl, fist and
// spread still turn the phalanges; the right hand is the exact mirror of the
// left; `meta` loads as `base`; bad values are refused where they are written;
// incremental = full.
#include "EvalTestSupport.h"
#include "IncrementalCheck.h"
#include "io/GuideFile.h"
#include "io/RigDump.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

// The biped with `options` on its index fingers.
model::GuideDocument bipedIndexWith(const std::map<std::string, Value>& options)
{
    model::GuideDocument guide = test::loadSample("biped");
    auto* index = guide.instance(guide.instanceNamed("index")->id);
    index->options.erase("target_weights");
    for (const auto& [name, value] : options)
        index->options[name] = value;
    return guide;
}

double angleRadians(const Vec3& a, const Vec3& b)
{
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The node each aimed phalanx k (1..3: the base is not aimed) aims at.
std::string goalOf(const std::string& finger, int k)
{
    return k == 3 ? finger + "::ctrls.target" : finger + "::mch.aim_target." + std::to_string(k);
}

// Phalanx k's aim axis (X: at the next joint) as evaluated.
Vec3 aimAxis(const PosedRig& r, const std::string& finger, int k)
{
    return glm::normalize(r.state().world[r.index(finger + "::roots.fk." + std::to_string(k))].linear[0]);
}

// Phalanx k's aim axis with no aim: its offset placed by its parent as at rest.
Vec3 fkAxis(const PosedRig& r, const std::string& finger, int k)
{
    const model::RigNode& offset = test::node(r.rig, finger + "::roots.fk." + std::to_string(k));
    const Mat4 local = glm::inverse(r.rig.nodes[offset.parent].worldMatrix) * offset.worldMatrix;
    return glm::normalize(Vec3((r.state().world[offset.parent].matrix() * local)[0]));
}

// Where a fist or a curl moves the index's tip: towards the palm.
Vec3 towardsPalm(PosedRig& r)
{
    Pose pose = r.defaults();
    pose[r.channel("index.L::ctrls.fk.0", "curl")] = 30.0;
    r.evaluate(pose);
    const Vec3 curled = r.position("index.L::ctrls.fk.3");
    return glm::normalize(curled - r.restPosition("index.L::ctrls.fk.3"));
}

TEST(FingerAim, MovingTheTargetTowardsThePalmBendsEachAimedPhalanxOntoItsTarget)
{
    PosedRig r(bipedIndexWith({{"target_weights", Value(std::string("[1]"))}}));
    ASSERT_TRUE(r.ok());
    const Vec3 palm = towardsPalm(r);
    const Pose pose = r.moveTo(r.defaults(), "index.L::ctrls.target", r.restPosition("index.L::ctrls.target") + 0.03 * palm,
                               "index.L::ctrls.target");
    r.evaluate(pose);
    for (int k = 1; k <= 3; ++k) {
        const Vec3 origin = r.position("index.L::roots.fk." + std::to_string(k));
        const Vec3 goal = r.position(goalOf("index.L", k));
        EXPECT_NEAR(glm::length(goal - (r.restPosition(goalOf("index.L", k)) + 0.03 * palm)), 0.0, 1e-9) << k << ": the goal rides on the target";
        EXPECT_LT(angleRadians(aimAxis(r, "index.L", k), goal - origin), 1e-6) << "phalanx " << k;
        EXPECT_GT(angleRadians(aimAxis(r, "index.L", k), fkAxis(r, "index.L", k)), 0.05) << "phalanx " << k << " turned";
    }
    // The finger bends towards the palm: its last knuckle moves that way.
    EXPECT_GT(glm::dot(r.position("index.L::ctrls.fk.3") - r.restPosition("index.L::ctrls.fk.3"), palm), 0.01);
    // The base (metacarpal) is not aimed and has no aim attribute.
    EXPECT_LT(maxAbsDifference(r.state().worldMatrix(r.index("index.L::roots.fk.0")),
                               r.rig.nodes[r.index("index.L::roots.fk.0")].worldMatrix), 1e-12);
    for (const model::RigAttribute& a : test::node(r.rig, "index.L::ctrls.fk.0").attributes)
        EXPECT_NE(a.name, "aim");
}

TEST(FingerAim, AHalfWeightTurnsEachPhalanxHalfwayByAngleAndZeroKeepsTheFkPose)
{
    PosedRig r(bipedIndexWith({{"target_weights", Value(std::string("[1, 0.5, 0]"))}}));
    ASSERT_TRUE(r.ok());
    const Vec3 palm = towardsPalm(r);
    Pose pose = r.moveTo(r.defaults(), "index.L::ctrls.target", r.restPosition("index.L::ctrls.target") + 0.03 * palm,
                         "index.L::ctrls.target");
    pose[r.channel("index.L::ctrls.fk.1", "ry")] = 10.0; // an FK pose under the aim
    r.evaluate(pose);
    const std::vector<double> weights = {1.0, 0.5, 0.0};
    for (int k = 1; k <= 3; ++k) {
        const Vec3 fk = fkAxis(r, "index.L", k);
        const Vec3 aimed = r.position(goalOf("index.L", k)) - r.position("index.L::roots.fk." + std::to_string(k));
        const double full = angleRadians(fk, aimed);
        EXPECT_GT(full, 0.05) << k;
        EXPECT_NEAR(angleRadians(fk, aimAxis(r, "index.L", k)), weights[k - 1] * full, 1e-6) << "phalanx " << k;
        EXPECT_NEAR(angleRadians(aimAxis(r, "index.L", k), aimed), (1.0 - weights[k - 1]) * full, 1e-6) << "phalanx " << k;
    }
    // The weights are the aim attributes' defaults; the attribute blends live.
    EXPECT_DOUBLE_EQ(r.defaults()[r.channel("index.L::ctrls.fk.2", "aim")], 0.5);
    pose[r.channel("index.L::ctrls.fk.3", "aim")] = 1.0;
    r.evaluate(pose);
    EXPECT_LT(angleRadians(aimAxis(r, "index.L", 3), r.position(goalOf("index.L", 3)) - r.position("index.L::roots.fk.3")), 1e-6);
}

TEST(FingerAim, TheTargetFollowsTheHandWhenItTurns)
{
    PosedRig r(bipedIndexWith({{"target_weights", Value(std::string("[1]"))}}));
    ASSERT_TRUE(r.ok());
    const model::RigNodeIndex hand = r.index("hand.L::ctrls.hand");
    EXPECT_EQ(test::node(r.rig, "index.L::roots.target").parent, hand) << "*::hooks.digits: what the finger hangs from";
    Pose pose = r.defaults();
    pose[r.channel("arm.L::ctrls.ik", "ry")] = 40.0;
    pose[r.channel("arm.L::ctrls.ik", "rz")] = -25.0;
    r.evaluate(pose);
    const Mat4 handNow = r.state().worldMatrix(hand), handRest = r.rig.nodes[hand].worldMatrix;
    ASSERT_GT(maxAbsDifference(handNow, handRest), 0.1) << "the hand turned";
    for (const std::string tag : {"ctrls.target", "ctrls.fk.1", "ctrls.fk.2", "ctrls.fk.3", "skin.3"}) {
        const model::RigNodeIndex i = r.index("index.L::" + tag);
        EXPECT_LT(maxAbsDifference(glm::inverse(handNow) * r.state().worldMatrix(i), glm::inverse(handRest) * r.rig.nodes[i].worldMatrix), 1e-9)
            << tag << " keeps its place in the hand";
    }
}

TEST(FingerAim, TargetParentNamesASpaceOfTheRigAndAMissingOneFollowsTheHook)
{
    for (const std::string space : {"*::space.cog", "cog"}) {
        PosedRig r(bipedIndexWith({{"target_weights", Value(std::string("[1]"))}, {"target_parent", Value(space)}}));
        ASSERT_TRUE(r.ok()) << space;
        EXPECT_EQ(r.rig.nodes[test::node(r.rig, "index.L::roots.target").parent].path, "spine::ctrls.cog") << space;
        // Turning the hand now leaves the target in place: the finger reaches back to it.
        Pose pose = r.defaults();
        pose[r.channel("arm.L::ctrls.ik", "ry")] = 40.0;
        r.evaluate(pose);
        EXPECT_LT(glm::length(r.position("index.L::ctrls.target") - r.restPosition("index.L::ctrls.target")), 1e-9) << space;
    }
    const model::Rig rig = rigging::buildRig(bipedIndexWith({{"target_weights", Value(std::string("[1]"))},
                                                             {"target_parent", Value(std::string("tail"))}}),
                                             test::builtinTemplates());
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    EXPECT_NE(formatAll(rig.diagnostics).find("warning: instance 'index.L' (digit.finger): target_parent 'tail' is not a space of this rig"),
              std::string::npos) << formatAll(rig.diagnostics);
    EXPECT_EQ(rig.nodes[test::node(rig, "index.L::roots.target").parent].path, "hand.L::ctrls.hand");
}

TEST(FingerAim, FistCurlAndSpreadStillTurnTheAimedPhalanges)
{
    PosedRig plain("biped"), aimed(bipedIndexWith({{"target_weights", Value(std::string("[1]"))}}));
    ASSERT_TRUE(plain.ok() && aimed.ok());
    for (PosedRig* r : {&plain, &aimed}) {
        Pose pose = r->defaults();
        pose[r->channel("index.L::ctrls.fk.0", "curl")] = 30.0;
        pose[r->channel("index.L::ctrls.fk.0", "spread")] = 15.0;
        r->evaluate(pose);
    }
    // The first phalanx's parent did not move and its target is at rest: the
    // aim leaves it where FK has it, and curl and spread turn it as before.
    EXPECT_LT(maxAbsDifference(aimed.state().worldMatrix(aimed.index("index.L::ctrls.fk.1")),
                               plain.state().worldMatrix(plain.index("index.L::ctrls.fk.1"))), 1e-9);
    // A fist turns each phalanx its 90 degrees from where the aim leaves it,
    // whether the drives land in pose groups (the biped's do_pose) or on the
    // aimed offsets themselves (after the aim).
    for (const bool pose : {true, false}) {
        PosedRig r(bipedIndexWith({{"target_weights", Value(std::string("[1]"))}, {"do_pose", Value(pose)}}));
        ASSERT_TRUE(r.ok());
        Pose fist = r.defaults();
        fist[r.channel("hand.L::ctrls.hand", "fist")] = 1.0;
        r.evaluate(fist);
        for (int k = 1; k <= 3; ++k) {
            const Vec3 origin = r.position("index.L::roots.fk." + std::to_string(k));
            const Vec3 ctrl = r.state().world[r.index("index.L::ctrls.fk." + std::to_string(k))].linear[0];
            EXPECT_NEAR(glm::degrees(angleRadians(r.position(goalOf("index.L", k)) - origin, ctrl)), 90.0, 1e-6)
                << "do_pose " << pose << " phalanx " << k;
        }
        EXPECT_GT(glm::dot(r.position("index.L::ctrls.fk.3") - r.restPosition("index.L::ctrls.fk.3"), towardsPalm(r)), 0.01)
            << "the fist closes the finger";
    }
}

TEST(FingerAim, TheRightHandIsTheExactMirrorOfTheLeft)
{
    for (const bool flip : {false, true}) { // flip_orient: reflected control frames, the aim's blend included
        PosedRig r(bipedIndexWith({{"target_weights", Value(std::string("[1, 0.5, 0.8]"))}, {"flip_orient", Value(flip)}}));
        ASSERT_TRUE(r.ok());
        const Mat4 mirror = glm::scale(Mat4(1.0), Vec3(-1.0, 1.0, 1.0));
        const Vec3 move(0.01, -0.03, 0.02);
        Pose pose = r.moveTo(r.defaults(), "index.L::ctrls.target", r.restPosition("index.L::ctrls.target") + move, "index.L::ctrls.target");
        pose = r.moveTo(pose, "index.R::ctrls.target", r.restPosition("index.R::ctrls.target") + Vec3(-move.x, move.y, move.z),
                        "index.R::ctrls.target");
        pose[r.channel("index.L::ctrls.fk.0", "curl")] = pose[r.channel("index.R::ctrls.fk.0", "curl")] = 20.0;
        r.evaluate(pose);
        std::size_t compared = 0;
        for (model::RigNodeIndex i = 0; i < r.rig.nodes.size(); ++i) {
            const std::string& path = r.rig.nodes[i].path;
            if (path.rfind("index.L::", 0) != 0)
                continue;
            const model::RigNodeIndex twin = r.index("index.R::" + path.substr(9));
            // A flipped control's frame is the reflection M W, its skin joint the mirror image M W M.
            const Mat4 left = r.state().worldMatrix(i), right = r.state().worldMatrix(twin);
            const bool reflected = flip && path.find("::skin.") == std::string::npos && glm::determinant(Mat3(right)) < 0.0;
            EXPECT_LT(maxAbsDifference(reflected ? mirror * left : mirror * left * mirror, right), 1e-9) << path << " flip " << flip;
            ++compared;
        }
        EXPECT_GT(compared, 20u);
    }
}

TEST(FingerAim, MetaLoadsAsBaseAndWithoutABaseEveryPhalanxIsAimed)
{
    const std::string guide = "rigsmith_guide: 3\nname: g\ninstances:\n  - id: 1\n    template: digit.finger\n    name: claw\n"
                              "    options:\n      meta: off\n      target_weights: [1, 0.5, 0.5, 0.5]\n    joints:\n"
                              "      - {id: 1, t: [0, 0, 0]}\n      - {id: 2, parent: 1, t: [0.03, 0, 0]}\n"
                              "      - {id: 3, parent: 2, t: [0.03, -0.01, 0]}\n      - {id: 4, parent: 3, t: [0.03, -0.01, 0]}\n"
                              "      - {id: 5, parent: 4, t: [0.02, -0.01, 0]}\n";
    auto read = io::readGuideText(guide, "claw.yml");
    ASSERT_TRUE(read.ok()) << formatAll(read.diagnostics());
    EXPECT_EQ(read->instances().front().options.at("target_weights"), Value(std::string("[1, 0.5, 0.5, 0.5]")));
    const model::Rig rig = rigging::buildRig(*read, test::builtinTemplates());
    ASSERT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    for (int k = 0; k < 4; ++k) {
        EXPECT_TRUE(std::any_of(rig.constraints.begin(), rig.constraints.end(),
                                [&](const model::RigConstraint& c) { return c.path == "claw::cns.aim." + std::to_string(k); }))
            << k;
        EXPECT_EQ(test::node(rig, "claw::ctrls.fk." + std::to_string(k)).name.find("base"), std::string::npos);
    }
}

TEST(FingerAim, BadValuesAreRefusedWhereTheyAreWritten)
{
    const std::string head = "rigsmith_guide: 3\nname: g\ninstances:\n  - id: 1\n    template: digit.finger\n    name: claw\n"
                             "    options:\n      ";
    const std::string joints = "\n    joints:\n      - {id: 1, t: [0, 0, 0]}\n      - {id: 2, parent: 1, t: [0.03, 0, 0]}\n"
                               "      - {id: 3, parent: 2, t: [0.03, -0.01, 0]}\n      - {id: 4, parent: 3, t: [0.03, -0.01, 0]}\n"
                               "      - {id: 5, parent: 4, t: [0.02, -0.01, 0]}\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"target_weights: [1, 2, 0]", "claw.yml:8:23: error: instance 'claw' (digit.finger): target_weights: '2' is no weight"},
        {"target_weights: \"[1, 0.5]\"", "claw.yml:8:23: error: instance 'claw' (digit.finger): target_weights has 2 weights for 3 aimed phalanges"},
        {"target_weights: \"[a]\"", "claw.yml:8:23: error: instance 'claw' (digit.finger): target_weights: 'a' is no weight"},
        {"target_weights: \"[1, \"", "claw.yml:8:23: error: instance 'claw' (digit.finger): option 'target_weights' = '[1, ' is not a YAML list"},
        {"target_parent: arm::ctrls.ik", "claw.yml:8:22: error: instance 'claw' (digit.finger): target_parent 'arm::ctrls.ik' names no node"},
        {"target_weights: [[1], 1]", "claw.yml:8:24: error: option target_weights: each item must be a number"},
    };
    for (const auto& [option, message] : cases) {
        auto read = io::readGuideText(head + option + joints, "claw.yml");
        std::string all = formatAll(read.diagnostics());
        if (read.ok()) {
            const model::Rig rig = rigging::buildRig(*read, test::builtinTemplates());
            all = formatAll(rig.diagnostics);
            EXPECT_TRUE(hasErrors(rig.diagnostics)) << option;
            EXPECT_FALSE(rig.findPath("claw::ctrls.fk.1")) << option << ": never half-built";
        }
        EXPECT_NE(all.find(message), std::string::npos) << option << "\n" << all;
    }
}

TEST(FingerAim, AFullWeightSolvesAsAnAimWithoutOneAndExistingAimsHaveNone)
{
    // The face's eyes, the vehicle's camera: aims without a weight, dumped as before (no weight field).
    for (const std::string sample : {"face", "vehicle"}) {
        PosedRig r(sample);
        ASSERT_TRUE(r.ok());
        std::size_t aims = 0;
        for (const model::RigConstraint& c : r.rig.constraints)
            if (const auto* aim = std::get_if<model::AimConstraint>(&c.settings)) {
                EXPECT_FALSE(aim->weight.has_value()) << c.path;
                ++aims;
            }
        EXPECT_GT(aims, 0u) << sample;
        const std::string dump = io::writeRigDump(r.rig);
        for (std::size_t at = dump.find("kind: aim\n"); at != std::string::npos; at = dump.find("kind: aim\n", at + 1)) {
            const std::string entry = dump.substr(at, dump.find("\n  - ", at) - at);
            EXPECT_EQ(entry.find("weight:"), std::string::npos) << sample << ": " << entry;
        }
    }
    // The claw's talons at weight 1 (their aim attributes' default) solve exactly as unweighted aims.
    PosedRig weighted("claw");
    ASSERT_TRUE(weighted.ok());
    model::Rig unweighted = weighted.rig;
    for (model::RigConstraint& c : unweighted.constraints)
        if (auto* aim = std::get_if<model::AimConstraint>(&c.settings); aim && c.path.rfind("talon_in", 0) == 0)
            aim->weight.reset();
    auto program = eval::RigProgram::compile(unweighted);
    ASSERT_TRUE(program.ok()) << formatAll(program.diagnostics());
    eval::EvalState state = program->makeState();
    Pose pose = weighted.moveTo(weighted.defaults(), "talon_in.L::ctrls.target",
                                weighted.restPosition("talon_in.L::ctrls.target") + Vec3(0.0, -0.02, 0.01), "talon_in.L::ctrls.target");
    ASSERT_EQ(pose[weighted.channel("talon_in.L::ctrls.fk.1", "aim")], 1.0);
    pose[weighted.channel("talon_in.L::ctrls.fk.2", "aim")] = 1.0;
    weighted.evaluate(pose);
    program->evaluate(pose, state);
    for (int k = 0; k < 3; ++k) {
        const model::RigNodeIndex i = weighted.index("talon_in.L::skin." + std::to_string(k));
        EXPECT_EQ(weighted.state().worldMatrix(i), state.worldMatrix(i)) << k;
    }
}

TEST(FingerAim, AimOptionsRebuildIncrementallyAsAFullBuild)
{
    model::GuideDocument guide = test::loadSample("biped");
    const model::InstanceId index = guide.instanceNamed("index")->id;
    rigging::BuildCache cache;
    test::buildAndCompare(guide, cache, "first build");
    const std::vector<std::pair<std::string, Value>> edits = {
        {"target_weights", Value(std::string("[1, 0.5, 0]"))}, {"target_parent", Value(std::string("cog"))},
        {"do_pose", Value(false)}, {"base", Value(false)}, {"target_weights", Value(std::string("[0.25]"))},
        {"target_parent", Value(std::string("*::hooks.digits"))}, {"orient", Value(std::string("auto"))},
        {"target_weights", Value(std::string(""))}};
    for (const auto& [name, value] : edits) {
        guide.instance(index)->options[name] = value;
        test::buildAndCompare(guide, cache, name + " = " + formatValue(value));
    }
    // A guide joint of the finger dragged.
    guide.instance(index)->options["target_weights"] = Value(std::string("[1]"));
    test::buildAndCompare(guide, cache, "aim on again");
    guide.instance(index)->joints.back().local.translate += Vec3(0.0, -0.01, 0.0);
    test::buildAndCompare(guide, cache, "tip moved");
}

} // namespace
} // namespace rs
