#include "build/RigBuilder.h"
#include "core/TestSupport.h"
#include "io/GuideFile.h"
#include "io/RigDump.h"
#include "model/Skeleton.h"
#include "templates/ManifestReader.h"

#include <gtest/gtest.h>

using namespace rs;
using model::RigNodeKind;

namespace {

const model::RigNode& node(const model::Rig& rig, const std::string& id)
{
    auto index = rig.find(id);
    EXPECT_TRUE(index.has_value()) << "no rig node " << id;
    static const model::RigNode none;
    return index ? rig.nodes[*index] : none;
}

} // namespace

TEST(RigBuilder, BuildsTheBipedSampleAsTheGoldenDump)
{
    const model::Rig rig = build::buildRig(test::loadSample("biped"), test::builtinTemplates());
    EXPECT_TRUE(rig.diagnostics.empty()) << formatAll(rig.diagnostics);
    test::expectMatchesGolden(io::writeRigDump(rig), "RigBuilder/biped/rig.yml");
}

TEST(RigBuilder, SameGuideGivesAByteIdenticalDump)
{
    const auto guide = test::loadSample("biped");
    EXPECT_EQ(io::writeRigDump(build::buildRig(guide, test::builtinTemplates())),
              io::writeRigDump(build::buildRig(guide, test::builtinTemplates())));
}

TEST(RigBuilder, OneControllerAndSkinJointPerGuideJoint)
{
    const model::Rig rig = build::buildRig(test::loadSample("biped"), test::builtinTemplates());
    // world: world + move controllers and a root joint; 6 chains of 4+3+5+5+5+5 joints.
    EXPECT_EQ(rig.count(RigNodeKind::Controller), 2u + 27u);
    EXPECT_EQ(rig.count(RigNodeKind::Joint), 1u + 27u);
    const auto& c = node(rig, "arm_L::ctrls.2");
    EXPECT_EQ(c.name, "c_arm_L3");
    EXPECT_NEAR(glm::length(translationOf(c.worldMatrix) - Vec3(0.46, 1.5, -0.02)), 0.0, 1e-12);
    EXPECT_EQ(c.shape, "circle");
    ASSERT_EQ(c.curves.size(), 1u);
    EXPECT_EQ(c.curves[0].color, Vec3(30 / 255.0, 144 / 255.0, 1.0));
}

TEST(RigBuilder, ParentsAChildTemplateUnderTheNodeThatHooksItsJoint)
{
    const model::Rig rig = build::buildRig(test::loadSample("biped"), test::builtinTemplates());
    // arm_L hangs under spine's last joint, legs under its first.
    EXPECT_EQ(rig.nodes[node(rig, "arm_L::roots.0").parent].id, "spine::ctrls.3");
    EXPECT_EQ(rig.nodes[node(rig, "leg_R::roots.0").parent].id, "spine::ctrls.0");
    EXPECT_EQ(rig.nodes[node(rig, "spine::roots.0").parent].id, "world::ctrls.move");
    // Virtual hierarchies follow the same hooks, per domain.
    EXPECT_EQ(rig.nodes[node(rig, "arm_L::ctrls.0").virtualParent].id, "spine::ctrls.3");
    EXPECT_EQ(rig.nodes[node(rig, "arm_L::skin.0").virtualParent].id, "spine::skin.3");
    EXPECT_EQ(rig.nodes[node(rig, "spine::skin.0").virtualParent].id, "world::skin.root");
}

TEST(RigBuilder, TheSkinHierarchyHasOneRoot)
{
    const model::Rig rig = build::buildRig(test::loadSample("biped"), test::builtinTemplates());
    EXPECT_EQ(rig.virtualRoots("skin").size(), 1u);
    EXPECT_EQ(rig.virtualRoots("ctrls").size(), 1u);
    auto skeleton = model::extractSkeleton(rig);
    ASSERT_TRUE(skeleton.ok());
    EXPECT_EQ(skeleton->joints.size(), 28u);
    EXPECT_EQ(skeleton->joints.front().name, "sk_world_root");
}

TEST(RigBuilder, SkipsAnUnknownTemplateAndAttachesItsChildrenAbove)
{
    model::GuideDocument guide = test::loadSample("biped");
    guide.instance(guide.instanceNamed("spine")->id)->templateId = "spine.missing";
    const model::Rig rig = build::buildRig(guide, test::builtinTemplates());
    ASSERT_FALSE(rig.diagnostics.empty());
    EXPECT_EQ(rig.diagnostics[0].message,
              "instance 'spine' (spine.missing): unknown template 'spine.missing'; the instance is skipped and its children attach above it");
    EXPECT_EQ(rig.diagnostics[0].subject, "spine");
    EXPECT_FALSE(rig.find("spine::ctrls.0"));
    EXPECT_EQ(rig.nodes[node(rig, "arm_L::roots.0").parent].id, "world::ctrls.move");
}

TEST(RigBuilder, FallsBackToTheJointChainBuilderForDataOnlyManifests)
{
    auto manifest = templates::readManifestText("name: tail\nstructure:\n  chain: /*\n", "tail.yml", "rig", "tail");
    ASSERT_TRUE(manifest.ok());
    Diagnostics d;
    EXPECT_NE(&build::BuilderRegistry::builtin().resolve(*manifest, d), nullptr);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].format(), "tail.yml: warning: no builder for rig.tail; using the generic joint-chain builder");
}

namespace {
// A builder that names every node the same, to provoke a clash between instances.
class ClashingBuilder final : public build::TemplateBuilder {
public:
    std::vector<build::GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                                   const std::map<std::string, Value>&) const override { return {{}}; }
    void generate(build::BuildContext& ctx) const override
    {
        ctx.createNode(RigNodeKind::Controller, "ctrls.0", "c_same", model::kNoNode, Mat4(1.0));
    }
};
} // namespace

TEST(RigBuilder, ReportsANameClash)
{
    build::BuilderRegistry builders;
    builders.add("core.joints", std::make_unique<ClashingBuilder>());
    builders.add("world.character", std::make_unique<ClashingBuilder>());
    const model::Rig rig = build::buildRig(test::loadSample("biped"), test::builtinTemplates(), builders);
    ASSERT_TRUE(hasErrors(rig.diagnostics));
    EXPECT_EQ(rig.diagnostics.back().message,
              "name clash: 'c_same' is used by world::ctrls.0, spine::ctrls.0, neck::ctrls.0, arm_L::ctrls.0, "
              "arm_R::ctrls.0, leg_L::ctrls.0, leg_R::ctrls.0");
}

TEST(RigBuilder, RollsBackAnInstanceWhoseStructureFails)
{
    model::GuideDocument guide = test::loadSample("biped");
    // A world whose root joint is missing cannot resolve /1.
    auto* world = guide.instance(guide.instanceNamed("world")->id);
    guide.instance(guide.instanceNamed("spine")->id)->parentJoint = world->joints[0].id;
    world->joints.pop_back();
    const model::Rig rig = build::buildRig(guide, test::builtinTemplates());
    ASSERT_TRUE(hasErrors(rig.diagnostics));
    EXPECT_EQ(rig.diagnostics[0].message, "instance 'world' (world.character): structure 'root': address '/1': index [1] is out of range (1 joints)");
    EXPECT_FALSE(rig.find("world::ctrls.world")) << "never half-built";
    EXPECT_EQ(rig.nodes[node(rig, "spine::roots.0").parent].id, "::rig");
}
