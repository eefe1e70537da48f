// The production templates: golden dumps per builder and per sample, symmetry,
// one skin root, unique names, and what a bad guide gives.
#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"
#include "io/GuideFile.h"
#include "io/RigDump.h"
#include "model/Skeleton.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>

using namespace rs;
using model::ConstraintKind;
using model::RigNodeKind;

namespace {

using test::node;

const model::RigConstraint* constraint(const model::Rig& rig, const std::string& id)
{
    for (const auto& c : rig.constraints)
        if (c.path == id)
            return &c;
    ADD_FAILURE() << "no constraint " << id;
    return nullptr;
}

std::vector<std::string> builderCases()
{
    std::vector<std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(test::dataPath("Builders")))
        out.push_back(entry.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

std::string caseName(const testing::TestParamInfo<std::string>& info)
{
    std::string name = info.param;
    std::replace(name.begin(), name.end(), '.', '_');
    return name;
}

std::size_t countTagged(const model::Rig& rig, const std::string& prefix)
{
    return static_cast<std::size_t>(std::count_if(rig.nodes.begin(), rig.nodes.end(), [&](const model::RigNode& n) {
        return n.path.rfind(prefix, 0) == 0;
    }));
}

Vec3 at(const model::Rig& rig, const std::string& id) { return translationOf(node(rig, id).worldMatrix); }

} // namespace

// One guide per template (a world and the template with its default guide
// joints), built and compared with its golden dump.
class BuilderGolden : public testing::TestWithParam<std::string> {};

TEST_P(BuilderGolden, BuildsTheDefaultGuideAsTheGoldenDump)
{
    const model::Rig rig = rigging::buildRig(test::loadGuide("Builders/" + GetParam() + "/guide.yml"), test::builtinTemplates());
    EXPECT_TRUE(rig.diagnostics.empty()) << formatAll(rig.diagnostics);
    EXPECT_LE(rig.virtualRoots("skin").size(), 1u);
    test::expectMatchesGolden(io::writeRigDump(rig), "Builders/" + GetParam() + "/rig.yml");
}

INSTANTIATE_TEST_SUITE_P(Templates, BuilderGolden, testing::ValuesIn(builderCases()), caseName);

class SampleGolden : public testing::TestWithParam<std::string> {};

TEST_P(SampleGolden, BuildsWithoutDiagnosticsOneSkinRootAndUniqueNames)
{
    const model::Rig rig = rigging::buildRig(test::loadSample(GetParam()), test::builtinTemplates());
    EXPECT_TRUE(rig.diagnostics.empty()) << formatAll(rig.diagnostics);
    auto skeleton = model::extractSkeleton(rig);
    ASSERT_TRUE(skeleton.ok()) << formatAll(skeleton.diagnostics());
    std::set<std::string> names;
    for (const auto& n : rig.nodes)
        EXPECT_TRUE(names.insert(n.name).second) << "duplicate name " << n.name;
    EXPECT_EQ(rig.virtualRoots("ctrls").size(), 1u) << "pickwalk starts at the world controller";
    ASSERT_TRUE(rig.sets.count("controllers"));
    EXPECT_EQ(rig.sets.at("controllers").size(), rig.count(RigNodeKind::Controller));
    test::expectMatchesGolden(io::writeRigDump(rig), "RigBuilder/" + GetParam() + "/rig.yml");
}

INSTANTIATE_TEST_SUITE_P(Samples, SampleGolden, testing::Values("biped", "quadruped", "prop", "vehicle", "robot", "claw", "cart", "strider"));

TEST(Templates, TheBipedIsMirroredExactlyFromLeftToRight)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    Mat4 mirror(1.0);
    mirror[0][0] = -1.0;
    std::size_t pairs = 0;
    for (const auto& n : rig.nodes) {
        const auto r = n.path.find(".R::");
        if (r == std::string::npos)
            continue;
        const auto& left = node(rig, std::string(n.path).replace(r, 4, ".L::"));
        EXPECT_LT(maxAbsDifference(n.worldMatrix, mirror * left.worldMatrix * mirror), 1e-6) << n.path;
        EXPECT_EQ(n.name.substr(0, n.name.rfind("_R")), left.name.substr(0, left.name.rfind("_L"))) << n.path;
        ++pairs;
    }
    EXPECT_EQ(pairs, 202u) << "arms and legs (with their IK, pole and FK space groups, pins, auto-clavicle groups, bendy "
                              "controls, the hands' reverse lock pivots and the legs' front chains), two hand masters and ten "
                              "fingers (with their pose groups)";
    // Constraints come in pairs too.
    for (const auto& c : rig.constraints)
        if (auto r = c.path.find(".R::"); r != std::string::npos)
            constraint(rig, std::string(c.path).replace(r, 4, ".L::"));
}

TEST(Templates, ANewBipedLooksLikeA180CentimetreHuman)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    EXPECT_NEAR(at(rig, "neck::ctrls.head").y, 1.62, 0.02);
    EXPECT_NEAR(at(rig, "spine::ctrls.hips").y, 1.0, 1e-9);
    EXPECT_NEAR(at(rig, "leg.L::blend.2").y, 0.08, 0.01) << "ankle";
    EXPECT_NEAR(at(rig, "leg.L::rfoot.heel").y, 0.0, 1e-9) << "feet on the ground";
    EXPECT_GT(at(rig, "arm.L::blend.2").x, 0.6) << "T-pose, left arm along +X";
    // The head top guide (the neck's tip) at 1.8 m.
    const auto guide = test::loadSample("biped");
    EXPECT_NEAR(guide.jointWorldMatrix(guide.instanceNamed("neck")->joints.back().id)[3].y, 1.8, 0.01);
}

TEST(Templates, TheLimbBlendsFkAndIkAndSpreadsTwistJoints)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    const auto& settings = node(rig, "arm.L::ctrls.switch");
    ASSERT_NE(settings.attribute("ik_blend"), nullptr);
    EXPECT_EQ(settings.attribute("ik_blend")->value, 1.0);
    const auto& ikControl = node(rig, "arm.L::ctrls.ik"); // what only the IK does is on the IK control
    EXPECT_EQ(ikControl.attribute("stretch")->value, 1.0) << "stretch is on by default";
    EXPECT_EQ(ikControl.attribute("soft_ik")->value, 0.0);
    EXPECT_EQ(ikControl.attribute("volume")->value, 0.0) << "volume is off by default";
    EXPECT_EQ(ikControl.attribute("pin")->value, 0.0);
    EXPECT_EQ(settings.attribute("stretch"), nullptr);
    const auto* ik = constraint(rig, "arm.L::cns.ik");
    ASSERT_NE(ik, nullptr);
    ASSERT_EQ(ik->kind(), ConstraintKind::Ik);
    EXPECT_EQ(ik->driven.size(), 3u);
    EXPECT_EQ(rig.nodes[ik->targets[1]].path, "arm.L::ctrls.pole");
    EXPECT_EQ(std::get<model::IkConstraint>(ik->settings).stretch,
              (model::AttributeRef{*rig.findPath("arm.L::ctrls.ik"), "stretch"}));
    const auto* blend = constraint(rig, "arm.L::cns.blend.1");
    ASSERT_NE(blend, nullptr);
    EXPECT_EQ(rig.nodes[blend->targets[0]].path, "arm.L::ctrls.fk.1");
    EXPECT_EQ(rig.nodes[blend->targets[1]].path, "arm.L::ik.1");
    // Two twist joints per segment by default, at 1/3 and 2/3 of the upper arm.
    EXPECT_EQ(countTagged(rig, "arm.L::skin.up."), 2u);
    EXPECT_EQ(countTagged(rig, "arm.L::skin.dn."), 2u);
    const Vec3 shoulder = at(rig, "arm.L::blend.0"), elbow = at(rig, "arm.L::blend.1");
    EXPECT_LT(glm::length(at(rig, "arm.L::skin.up.0") - glm::mix(shoulder, elbow, 1.0 / 3.0)), 1e-9);
    EXPECT_EQ(std::get<model::TwistConstraint>(constraint(rig, "arm.L::cns.up.1")->settings).fraction, 2.0 / 3.0);
    // Blend joints at elbow and wrist, halfway between their segments.
    EXPECT_EQ(std::get<model::OrientConstraint>(constraint(rig, "arm.L::cns.mid.0")->settings).weights,
              (std::vector<double>{0.5, 0.5}));
    // The pole sits behind the elbow, the knee's pole in front of the knee.
    EXPECT_LT(at(rig, "arm.L::ctrls.pole").z, elbow.z - 0.1);
    EXPECT_GT(at(rig, "leg.L::ctrls.pole").z, at(rig, "leg.L::blend.1").z + 0.1);
    // IK controllers live in a space group under the post transform, switched by
    // their space attribute (world by default; cog, hips... on demand).
    EXPECT_EQ(rig.nodes[node(rig, "leg.L::roots.ik").parent].path, "leg.L::spaces.ik");
    EXPECT_EQ(rig.nodes[node(rig, "leg.L::spaces.ik").parent].path, "world::grps.post");
    const auto* space = constraint(rig, "leg.L::cns.ik_space");
    ASSERT_NE(space, nullptr);
    EXPECT_EQ(rig.nodes[space->targets[2]].path, "spine::ctrls.cog");
    EXPECT_EQ(node(rig, "leg.L::ctrls.ik").attribute("space")->labels,
              (std::vector<std::string>{"world", "root", "cog", "hips", "chest"}));
}

TEST(Templates, TheOptionsChangeWhatTheLimbBuilds)
{
    model::GuideDocument guide = test::loadSample("biped");
    auto* arm = guide.instance(guide.instanceNamed("arm")->id);
    arm->options["twist_upper"] = 4LL;
    arm->options["twist_lower"] = 0LL;
    arm->options["clavicle"] = false;
    arm->options["stretch"] = false;
    arm->options["blend_joints"] = false;
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    EXPECT_TRUE(rig.diagnostics.empty()) << formatAll(rig.diagnostics);
    EXPECT_EQ(countTagged(rig, "arm.R::skin.up."), 4u);
    EXPECT_EQ(countTagged(rig, "arm.R::skin.dn."), 0u);
    EXPECT_EQ(countTagged(rig, "arm.R::skin.mid."), 0u);
    EXPECT_FALSE(rig.findPath("arm.L::ctrls.clavicle"));
    EXPECT_EQ(rig.nodes[node(rig, "arm.L::grps.limb").parent].path, "spine::blend.4") << "hangs on the chest hook";
    EXPECT_EQ(node(rig, "arm.L::ctrls.ik").attribute("stretch")->value, 0.0);
}

TEST(Templates, TheLegHasAReverseFootFromTaggedPivots)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    // ik > heel > toe > bank_ext > bank_int > ball > ankle (the IK effector)
    std::string chain;
    for (auto i = *rig.findPath("leg.L::rfoot.ankle"); i != *rig.findPath("leg.L::ctrls.ik"); i = rig.nodes[i].parent)
        chain = rig.nodes[i].path.substr(rig.nodes[i].path.find("::") + 2) + (chain.empty() ? "" : " > ") + chain;
    EXPECT_EQ(chain, "rfoot.heel > rfoot.toe > rfoot.bank_ext > rfoot.bank_int > rfoot.ball > rfoot.ankle");
    const auto guide = test::loadSample("biped");
    const auto* leg = guide.instanceNamed("leg");
    for (const char* tag : {"heel", "bank_int", "bank_ext"}) {
        const auto joint = std::find_if(leg->joints.begin(), leg->joints.end(), [&](const model::GuideJoint& j) {
            return std::find(j.tags.begin(), j.tags.end(), tag) != j.tags.end();
        });
        ASSERT_NE(joint, leg->joints.end()) << tag;
        EXPECT_LT(glm::length(at(rig, std::string("leg.L::rfoot.") + tag) - Vec3(guide.jointWorldMatrix(joint->id)[3])), 1e-9) << tag;
    }
    EXPECT_EQ(rig.nodes[constraint(rig, "leg.L::cns.ik")->targets[0]].path, "leg.L::rfoot.ankle");
    const auto& ik = node(rig, "leg.L::ctrls.ik");
    for (const char* attribute : {"roll", "roll_break", "bank", "heel_twist", "toe_twist", "toe_tap"})
        EXPECT_NE(ik.attribute(attribute), nullptr) << attribute;
    const auto& toeRoll = std::get<model::DriveConstraint>(constraint(rig, "leg.L::cns.rfoot.toe_roll")->settings);
    ASSERT_TRUE(std::holds_alternative<model::DrivePastBreak>(toeRoll.response));
    EXPECT_EQ(std::get<model::DrivePastBreak>(toeRoll.response).breakAngle,
              (model::AttributeRef{*rig.findPath("leg.L::ctrls.ik"), "roll_break"}));
}

TEST(Templates, TheHeadFollowsTheSpaceItsOptionPicks)
{
    model::GuideDocument guide = test::loadSample("biped");
    guide.instance(guide.instanceNamed("neck")->id)->options["head_space"] = std::string("world");
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    const auto* space = constraint(rig, "neck::cns.head_space");
    ASSERT_NE(space, nullptr);
    std::vector<std::string> targets;
    for (auto t : space->targets)
        targets.push_back(rig.nodes[t].path);
    EXPECT_EQ(targets, (std::vector<std::string>{"neck::ctrls.fk.1", "spine::blend.4", "spine::ctrls.cog", "world::grps.post"}));
    EXPECT_EQ(node(rig, "neck::ctrls.head").attribute("space")->value, 3.0);
}

TEST(Templates, FingersFollowTheHandOfTheirBranch)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    // The fingers hang on their side's hand master, which hangs on that side's wrist.
    EXPECT_EQ(rig.nodes[node(rig, "index.R::roots.fk.0").parent].path, "hand.R::ctrls.hand");
    EXPECT_EQ(rig.nodes[node(rig, "hand.R::roots.hand").parent].path, "arm.R::blend.2");
    EXPECT_EQ(node(rig, "index.L::ctrls.fk.0").name, "c_index_base_L");
    EXPECT_EQ(node(rig, "index.L::ctrls.fk.1").name, "c_index1_L");
    EXPECT_EQ(rig.nodes[node(rig, "index.L::skin.0").virtualParent].path, "arm.L::skin.limb.2");
    EXPECT_EQ(rig.nodes[node(rig, "index.L::ctrls.fk.0").virtualParent].path, "hand.L::ctrls.hand");
    EXPECT_EQ(rig.nodes[node(rig, "hand.L::ctrls.hand").virtualParent].path, "arm.L::ctrls.fk.2");
    EXPECT_NE(node(rig, "index.L::ctrls.fk.0").attribute("curl"), nullptr);
}

TEST(Templates, BadGuidesGiveDiagnosticsAndSaneFallbacks)
{
    {   // A straight arm: the bend is unknown, the pole goes behind.
        model::GuideDocument guide = test::loadSample("biped");
        auto* arm = guide.instance(guide.instanceNamed("arm")->id);
        arm->joints[2].local.translate.z = 0.0;
        arm->joints[3].local.translate.z = 0.0;
        const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
        EXPECT_FALSE(hasErrors(rig.diagnostics));
        ASSERT_FALSE(rig.diagnostics.empty());
        EXPECT_EQ(rig.diagnostics[0].message.rfind("instance 'arm.L' (arm.limb): limb1, limb2 and limb3 guides are in a straight line", 0), 0u)
            << rig.diagnostics[0].message;
        EXPECT_LT(at(rig, "arm.L::ctrls.pole").z, at(rig, "arm.L::blend.1").z - 0.1);
    }
    {   // No guide tagged heel: warned, the pivot placed from the foot.
        model::GuideDocument guide = test::loadSample("biped");
        auto* leg = guide.instance(guide.instanceNamed("leg")->id);
        leg->joints.erase(std::remove_if(leg->joints.begin(), leg->joints.end(), [](const model::GuideJoint& j) {
            return std::find(j.tags.begin(), j.tags.end(), "heel") != j.tags.end();
        }), leg->joints.end());
        const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
        EXPECT_FALSE(hasErrors(rig.diagnostics));
        ASSERT_FALSE(rig.diagnostics.empty());
        EXPECT_EQ(rig.diagnostics[0].message, "instance 'leg.L' (leg.limb): no guide is tagged 'heel'; the heel pivot is placed "
                                              "from the foot (add a guide with tag 'heel' under the ankle)");
        EXPECT_NEAR(at(rig, "leg.L::rfoot.heel").y, 0.0, 1e-9);
    }
    {   // Overlapping guides: warned, and the frames stay finite.
        model::GuideDocument guide = test::loadSample("biped");
        guide.instance(guide.instanceNamed("arm")->id)->joints[3].local.translate = Vec3(0.0);
        const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
        EXPECT_FALSE(hasErrors(rig.diagnostics));
        bool warned = false;
        for (const auto& d : rig.diagnostics)
            warned = warned || d.message == "instance 'arm.L' (arm.limb): limb: guide joints 1 and 2 overlap (closer than 1 mm); move one of them";
        EXPECT_TRUE(warned) << formatAll(rig.diagnostics);
        for (const auto& n : rig.nodes)
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    ASSERT_TRUE(std::isfinite(n.worldMatrix[c][r])) << n.path;
    }
    {   // A spine with too few joints: refused whole, naming the option; children attach above.
        model::GuideDocument guide = test::loadSample("biped");
        auto* spine = guide.instance(guide.instanceNamed("spine")->id);
        const model::JointId chest = spine->joints.back().id;
        for (auto& i : guide.instances())
            if (i.parentJoint != model::kNoId && i.parentJoint != chest && i.parent == spine->id)
                guide.instance(i.id)->parentJoint = chest;
        spine->joints.erase(spine->joints.begin() + 1, spine->joints.end() - 1);
        spine->joints.back().parent = spine->joints.front().id;
        const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
        ASSERT_TRUE(hasErrors(rig.diagnostics));
        EXPECT_EQ(rig.diagnostics[0].message, "instance 'spine' (spine.torso): the spine needs at least 3 guide joints (hips, one "
                                              "spine joint, chest); it has 2 (option 'number')");
        EXPECT_EQ(countTagged(rig, "spine::"), 0u) << "never half-built";
        EXPECT_EQ(rig.nodes[node(rig, "neck::roots.fk.0").parent].path, "world::ctrls.fly");
    }
}

TEST(Templates, AGuideWithAJointCycleIsRefusedAtLoad)
{
    const std::string text = "rigsmith_guide: 1\nname: loop\ninstances:\n  - id: 1\n    template: core.joints\n    name: chain\n"
                              "    joints:\n      - {id: 1, parent: 2, t: [0, 0, 0]}\n      - {id: 2, parent: 1, t: [0, 1, 0]}\n";
    auto guide = io::readGuideText(text, "loop.yml");
    ASSERT_FALSE(guide.ok());
    EXPECT_NE(formatAll(guide.diagnostics()).find("loop.yml:"), std::string::npos) << formatAll(guide.diagnostics());
}
