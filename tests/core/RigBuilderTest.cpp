#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"
#include "io/GuideFile.h"
#include "io/RigDump.h"
#include "model/Skeleton.h"
#include "io/ManifestReader.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace rs;
using model::RigNodeKind;

namespace {

using test::node;

} // namespace

TEST(RigBuilder, BuildsTheChainFixtureAsTheGoldenDump)
{
    const model::Rig rig = rigging::buildRig(test::loadChains(), test::builtinTemplates());
    EXPECT_TRUE(rig.diagnostics.empty()) << formatAll(rig.diagnostics);
    test::expectMatchesGolden(io::writeRigDump(rig), "RigBuilder/chains/rig.yml");
}

TEST(RigBuilder, SameGuideGivesAByteIdenticalDump)
{
    const auto guide = test::loadChains();
    EXPECT_EQ(io::writeRigDump(rigging::buildRig(guide, test::builtinTemplates())),
              io::writeRigDump(rigging::buildRig(guide, test::builtinTemplates())));
}

TEST(RigBuilder, OneControllerAndSkinJointPerGuideJoint)
{
    const model::Rig rig = rigging::buildRig(test::loadChains(), test::builtinTemplates());
    // world: world, move, scale and fly controllers and a root joint; 6 chains of 4+3+5+5+5+5 joints.
    EXPECT_EQ(rig.count(RigNodeKind::Controller), 4u + 27u);
    EXPECT_EQ(rig.count(RigNodeKind::Joint), 1u + 27u);
    const auto& c = node(rig, "arm.L::ctrls.2");
    EXPECT_EQ(c.name, "c_arm3_L");
    EXPECT_NEAR(glm::length(translationOf(c.worldMatrix) - Vec3(0.46, 1.5, -0.02)), 0.0, 1e-12);
    EXPECT_EQ(c.shape, "circle");
    ASSERT_EQ(c.curves.size(), 1u);
    EXPECT_EQ(c.curves[0].color, Vec3(30 / 255.0, 144 / 255.0, 1.0));
}

TEST(RigBuilder, ParentsAChildTemplateUnderTheNodeThatHooksItsJoint)
{
    const model::Rig rig = rigging::buildRig(test::loadChains(), test::builtinTemplates());
    // arm_L hangs under spine's last joint, legs under its first.
    EXPECT_EQ(rig.nodes[node(rig, "arm.L::roots.0").parent].path, "spine::ctrls.3");
    EXPECT_EQ(rig.nodes[node(rig, "leg.R::roots.0").parent].path, "spine::ctrls.0");
    EXPECT_EQ(rig.nodes[node(rig, "spine::roots.0").parent].path, "world::ctrls.fly");
    // Virtual hierarchies follow the same hooks, per domain.
    EXPECT_EQ(rig.nodes[node(rig, "arm.L::ctrls.0").virtualParent].path, "spine::ctrls.3");
    EXPECT_EQ(rig.nodes[node(rig, "arm.L::skin.0").virtualParent].path, "spine::skin.3");
    EXPECT_EQ(rig.nodes[node(rig, "spine::skin.0").virtualParent].path, "world::skin.root");
}

TEST(RigBuilder, TheSkinHierarchyHasOneRoot)
{
    const model::Rig rig = rigging::buildRig(test::loadChains(), test::builtinTemplates());
    EXPECT_EQ(rig.virtualRoots("skin").size(), 1u);
    EXPECT_EQ(rig.virtualRoots("ctrls").size(), 1u);
    auto skeleton = model::extractSkeleton(rig);
    ASSERT_TRUE(skeleton.ok());
    EXPECT_EQ(skeleton->joints.size(), 28u);
    EXPECT_EQ(skeleton->joints.front().name, "sk_world_root");
}

TEST(RigBuilder, ReportsProgressThroughEveryStageAndEachInstance)
{
    const model::GuideDocument guide = test::loadSample("biped");
    std::vector<std::pair<double, std::string>> steps;
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates(), rigging::BuilderRegistry::builtin(),
                                           [&](double fraction, const std::string& stage) { steps.emplace_back(fraction, stage); });
    ASSERT_FALSE(steps.empty());
    EXPECT_EQ(steps.front(), (std::pair<double, std::string>{0.0, "gather"}));
    EXPECT_EQ(steps.back(), (std::pair<double, std::string>{1.0, "done"}));
    for (std::size_t i = 1; i < steps.size(); ++i)
        EXPECT_GE(steps[i].first, steps[i - 1].first) << steps[i].second << " never goes back";
    std::size_t generated = 0;
    for (const auto& [fraction, stage] : steps)
        generated += stage.rfind("generate ", 0) == 0;
    EXPECT_GT(generated, guide.instances().size()) << "each built instance, mirrored branches included";
    EXPECT_NE(std::find_if(steps.begin(), steps.end(), [](const auto& s) { return s.second == "generate arm.R"; }), steps.end());
    EXPECT_EQ(io::writeRigDump(rig), io::writeRigDump(rigging::buildRig(guide, test::builtinTemplates())))
        << "watching changes nothing";
}

TEST(RigBuilder, SkipsAnUnknownTemplateAndAttachesItsChildrenAbove)
{
    model::GuideDocument guide = test::loadChains();
    guide.instance(guide.instanceNamed("spine")->id)->templateId = "spine.missing";
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    ASSERT_FALSE(rig.diagnostics.empty());
    EXPECT_EQ(rig.diagnostics[0].message,
              "instance 'spine' (spine.missing): unknown template 'spine.missing'; the instance is skipped and its children attach above it");
    EXPECT_EQ(rig.diagnostics[0].subject, Subject::ofInstance(guide.instanceNamed("spine")->id));
    EXPECT_FALSE(rig.findPath("spine::ctrls.0"));
    EXPECT_EQ(rig.nodes[node(rig, "arm.L::roots.0").parent].path, "world::ctrls.fly");
}

TEST(RigBuilder, FallsBackToTheJointChainBuilderForDataOnlyManifests)
{
    auto manifest = io::readManifestText("name: tail\nstructure:\n  chain: /*\n", "tail.yml", "rig", "tail");
    ASSERT_TRUE(manifest.ok());
    Diagnostics d;
    const auto& registry = rigging::BuilderRegistry::builtin();
    EXPECT_EQ(&registry.resolve(*manifest, d), registry.find("core.joints")); // the generic builder, not another
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].format(), "tail.yml: warning: no builder for rig.tail; using the generic joint-chain builder");
}

namespace {
// A builder that names every node the same, to provoke a clash between instances.
class ClashingBuilder final : public rigging::TemplateBuilder {
public:
    std::vector<rigging::GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                                   const std::map<std::string, Value>&) const override { return {{}}; }
    void generate(rigging::BuildContext& ctx) const override
    {
        ctx.createNode(RigNodeKind::Controller, "ctrls.0", "c_same", model::kNoNode, Mat4(1.0));
    }
};

} // namespace

TEST(RigBuilder, ReportsANameClash)
{
    rigging::BuilderRegistry builders;
    builders.add("core.joints", std::make_unique<ClashingBuilder>());
    builders.add("world.character", std::make_unique<ClashingBuilder>());
    const model::Rig rig = rigging::buildRig(test::loadChains(), test::builtinTemplates(), builders);
    ASSERT_TRUE(hasErrors(rig.diagnostics));
    EXPECT_EQ(rig.diagnostics.back().message,
              "name clash: 'c_same' is used by world::ctrls.0, spine::ctrls.0, neck::ctrls.0, arm.L::ctrls.0, "
              "arm.R::ctrls.0, leg.L::ctrls.0, leg.R::ctrls.0");
}

TEST(RigBuilder, RollsBackAnInstanceWhoseStructureFails)
{
    model::GuideDocument guide = test::loadChains();
    // A world whose root joint is missing cannot resolve /1.
    auto* world = guide.instance(guide.instanceNamed("world")->id);
    guide.instance(guide.instanceNamed("spine")->id)->parentJoint = world->joints[0].id;
    world->joints.pop_back();
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    ASSERT_TRUE(hasErrors(rig.diagnostics));
    EXPECT_EQ(rig.diagnostics[0].message, "instance 'world' (world.character): structure 'root': address '/1': index [1] is out of range (1 joints)");
    EXPECT_FALSE(rig.findPath("world::ctrls.world")) << "never half-built";
    EXPECT_EQ(rig.nodes[node(rig, "spine::roots.0").parent].path, "::rig");
}

TEST(RigBuilder, MirrorsBranchesSoEveryRightNodeIsTheMirrorOfItsLeftTwin)
{
    const model::Rig rig = rigging::buildRig(test::loadChains(), test::builtinTemplates());
    ASSERT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    Mat4 mirror(1.0);
    mirror[0][0] = -1.0; // the x plane of an L/R pair
    std::size_t pairs = 0;
    for (const auto& n : rig.nodes) {
        if (n.name.size() < 2 || n.name.substr(n.name.size() - 2) != "_R")
            continue;
        const std::string leftId = std::string(n.path).replace(n.path.find(".R::"), 4, ".L::");
        const auto& left = node(rig, leftId);
        EXPECT_EQ(left.name, n.name.substr(0, n.name.size() - 2) + "_L");
        EXPECT_LT(maxAbsDifference(n.worldMatrix, mirror * left.worldMatrix * mirror), 1e-6) << n.path;
        if (n.kind == RigNodeKind::Controller) {
            ASSERT_EQ(n.curves.size(), left.curves.size());
            EXPECT_EQ(n.curves[0].points[1], Vec3(-left.curves[0].points[1].x, left.curves[0].points[1].y, left.curves[0].points[1].z))
                << "shapes are negatively scaled in x";
            EXPECT_NE(n.curves[0].color, left.curves[0].color) << "and hue-shifted";
        }
        ++pairs;
    }
    EXPECT_EQ(pairs, 30u) << "arm and leg: 5 joints x (offset, controller, skin) each";
}

TEST(RigBuilder, NestedBranchesMultiplyIdsAndSuffixes)
{
    model::GuideDocument guide = test::loadChains();
    // A digit chain under the arm's hand with its own branches [A, B]: 2 x 2 copies.
    auto digit = rigging::makeInstance(guide, test::builtinTemplates(), "core.joints", guide.instanceNamed("arm")->joints.back().id);
    ASSERT_TRUE(digit.ok());
    digit->name = "finger";
    digit->options["branches"] = std::string("[A, B]");
    guide.insertInstance(digit.take(), guide.instances().size());
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    ASSERT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    for (const char* id : {"finger.L.A::ctrls.0", "finger.L.B::ctrls.0", "finger.R.A::ctrls.0", "finger.R.B::ctrls.0"})
        EXPECT_TRUE(rig.findPath(id)) << id;
    EXPECT_EQ(node(rig, "finger.R.B::ctrls.0").name, "c_finger1_R_B");
    EXPECT_EQ(rig.nodes[node(rig, "finger.R.A::roots.0").parent].path, "arm.R::ctrls.4") << "hangs under the mirrored hand";
    EXPECT_LT(translationOf(node(rig, "finger.R.A::ctrls.0").worldMatrix).x, 0.0);
}

TEST(RigBuilder, NamesNodesByTheDocumentsNamingRules)
{
    model::GuideDocument guide = test::loadChains();
    guide.naming = *model::namingPreset("suffix"); // seed 004: arm_L_ctrl, arm_L_jnt, _gp groups
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    ASSERT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    EXPECT_EQ(node(rig, "arm.L::ctrls.0").name, "arm1_L_ctrl");
    EXPECT_EQ(node(rig, "arm.R::skin.2").name, "arm3_R_jnt");
    EXPECT_EQ(node(rig, "arm.L::roots.0").name, "arm1_L_gp");
    EXPECT_EQ(node(rig, "world::ctrls.move").name, "world_move_ctrl");
    EXPECT_EQ(node(rig, "spine::ctrls.0").name, "spine1_ctrl");
}

TEST(Naming, PresetsAndCustomRules)
{
    model::NamingRules rules = *model::namingPreset("mikan");
    EXPECT_EQ(rules.make(model::NameRole::Controller, "arm1", "A_L"), "c_arm1_A_L");
    rules.lowercase = true;
    rules.side = "-";
    EXPECT_EQ(rules.make(model::NameRole::Skin, "Arm1", "L"), "sk_arm1-l");
    EXPECT_FALSE(model::namingPreset("maya"));
}

TEST(RigBuilder, ARepeatedBranchNameIsOneErrorAboutTheInstanceAndEachBranchIsBuiltOnce)
{
    model::GuideDocument guide = test::loadChains();
    model::TemplateInstance* arm = guide.instance(4);
    ASSERT_NE(arm, nullptr);
    arm->options["branches"] = Value(std::string("[L, L, R]"));
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    std::vector<Diagnostic> errors;
    for (const Diagnostic& d : rig.diagnostics)
        if (d.severity == Severity::Error)
            errors.push_back(d);
    ASSERT_EQ(errors.size(), 1u) << formatAll(rig.diagnostics);
    EXPECT_NE(errors.front().message.find("names branch 'L' twice"), std::string::npos) << errors.front().message;
    EXPECT_EQ(errors.front().subject, Subject::ofInstance(4));
    EXPECT_TRUE(rig.findPath("arm.L::ctrls.0"));
    EXPECT_TRUE(rig.findPath("arm.R::ctrls.0"));
}

// A value the template does not take, read from a guide file, is named at
// its file:line in the build's messages (the build goes on with the default).
TEST(RigBuilder, ABadOptionValueIsReportedAtItsLineInTheGuideFile)
{
    const std::string text = test::readText(test::samplePath("biped"));
    std::string bad = text;
    const std::string good = "fk_space: chest";
    const std::size_t at = bad.find(good);
    ASSERT_NE(at, std::string::npos);
    bad.replace(at, good.size(), "fk_space: chets");
    const int line = 1 + int(std::count(bad.begin(), bad.begin() + std::ptrdiff_t(at), '\n'));
    auto guide = io::readGuideText(bad, "biped-typo.yml");
    ASSERT_TRUE(guide) << formatAll(guide.diagnostics());
    const model::Rig rig = rigging::buildRig(*guide, test::builtinTemplates());
    bool named = false;
    for (const Diagnostic& d : rig.diagnostics)
        if (d.message.find("'chets' is not one of its labels") != std::string::npos) {
            EXPECT_EQ(d.where.file, "biped-typo.yml");
            EXPECT_EQ(d.where.line, line);
            named = true;
        }
    EXPECT_TRUE(named) << formatAll(rig.diagnostics);
    // An edit of the option leaves the file's line behind.
    model::GuideDocument edited = *guide;
    model::TemplateInstance& arm = *edited.instance(edited.instanceNamed("arm")->id);
    EXPECT_EQ(arm.optionSources.at.count("fk_space"), 1u);
    EXPECT_EQ(arm, guide->instances()[std::size_t(*guide->indexOf(arm.id))]) << "where an option was read is not part of equality";
}
