// Shape placement at build: parent, point, aim/aim_axis/up_axis/do_aim, axis,
// clone, reference and wildcard expansion, checked on built controller curves.
#include "base/Paths.h"
#include "io/TemplateFolders.h"
#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace rs;

namespace {

struct Bounds {
    Vec3 lo{1e300}, hi{-1e300};
    Vec3 centre() const { return (lo + hi) * 0.5; }
    Vec3 extent() const { return hi - lo; }
};

Bounds boundsOf(const model::RigNode& node, std::size_t curve = 0)
{
    Bounds b;
    for (const Vec3& p : node.curves.at(curve).points) {
        b.lo = glm::min(b.lo, p);
        b.hi = glm::max(b.hi, p);
    }
    return b;
}

void expectNear(const Vec3& actual, const Vec3& expected, const char* what)
{
    EXPECT_NEAR(actual.x, expected.x, 1e-6) << what;
    EXPECT_NEAR(actual.y, expected.y, 1e-6) << what;
    EXPECT_NEAR(actual.z, expected.z, 1e-6) << what;
}

class ShapeStage : public ::testing::Test {
protected:
    void SetUp() override
    {
        folder = test::temporaryPath("shape-stage-templates");
        std::filesystem::remove_all(folder);
        std::filesystem::create_directories(folder + "/test/shaped");
        std::ofstream(folder + "/test/shaped/template.yml") << R"(base: core.joints
structure:
  chain: /*
  tip: chain[-1]
guides:
  length: {value: 1.0, min: 0.001}
opts:
  style: {value: auto, enum: [auto, world]}
shapes:
  ctrls.0: {shape: square, size: 2, parent: 'chain[1]', color: red}
  ctrls.1:
    shape: arrow
    parent: chain[1]
    aim: tip
    aim_axis: +z
    do_aim: {style: auto}
  ctrls.2: {clone: ctrls.0, size: 0.5, color: blue}
  ctrls.*:
    shape: circle
    size: 0.5
    parent: chain[*]
    point: ['chain[*]', 'chain[0]']
    axis: z
  extra: {shape: cube, size: 0.25, reference: ctrls.3}
)";
        Diagnostics d = io::scanTemplates(registry, {builtinTemplatesDirectory(), folder}, iconsDirectory());
        ASSERT_FALSE(hasErrors(d)) << formatAll(d);
    }

    // Five guide joints `spacing` metres apart (the template's default guide: 1 m).
    model::GuideDocument guideOf(const std::map<std::string, Value>& options = {}, double spacing = 1.0)
    {
        model::GuideDocument guide;
        model::TemplateInstance i;
        i.id = 1;
        i.templateId = "test.shaped";
        i.name = std::string(1, 's');
        i.options = options;
        for (model::JointId j = 1; j <= 5; ++j)
            i.joints.push_back({j, j - 1, {Vec3(0, j == 1 ? 0 : spacing, 0)}, {}, {}});
        guide.insertInstance(i, 0);
        return guide;
    }

    model::Rig build(const std::map<std::string, Value>& options = {}) { return rigging::buildRig(guideOf(options), registry); }

    const model::RigNode& node(const model::Rig& rig, const std::string& id) { return rig.nodes[*rig.findPath(id)]; }

    std::string folder;
    templates::TemplateRegistry registry;
};

} // namespace

TEST_F(ShapeStage, PlacesTheShapeUnderItsParentJointAtItsSize)
{
    const auto rig = build();
    ASSERT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    const Bounds b = boundsOf(node(rig, "s::ctrls.0")); // controller at y=0, parent joint at y=1
    expectNear(b.centre(), Vec3(0, 1, 0), "centre");
    expectNear(b.extent(), Vec3(2, 0, 2), "extent");
    EXPECT_EQ(node(rig, "s::ctrls.0").curves[0].color, Vec3(1, 0, 0));
}

TEST_F(ShapeStage, AimsTheAimAxisAtTheTargetOnlyWhenDoAimMatches)
{
    const auto aimed = build();
    const Bounds b = boundsOf(node(aimed, "s::ctrls.1")); // the arrow's +Z now points up at the tip
    EXPECT_NEAR(b.hi.y, 0.5, 1e-6);
    EXPECT_NEAR(b.lo.y, -0.5, 1e-6);
    EXPECT_NEAR(b.extent().z, 0.0, 1e-6);

    const auto flat = build({{"style", std::string("world")}});
    const Bounds f = boundsOf(node(flat, "s::ctrls.1"));
    EXPECT_NEAR(f.extent().y, 0.0, 1e-6);
    EXPECT_NEAR(f.hi.z, 0.5, 1e-6);
}

TEST_F(ShapeStage, ClonesAnotherControllersCurvesInWorldSpaceWithRelativeSizeAndColour)
{
    const auto rig = build();
    const auto& clone = node(rig, "s::ctrls.2"); // at y=2; the source's curves sit at y=1
    EXPECT_EQ(clone.shape, "square");
    const Bounds b = boundsOf(clone);
    expectNear(b.centre(), Vec3(0, -0.5, 0), "centre (world offset -1, scaled by 0.5)");
    expectNear(b.extent(), Vec3(1, 0, 1), "extent");
    EXPECT_EQ(clone.curves[0].color, Vec3(0, 0, 1));
}

TEST_F(ShapeStage, ExpandsWildcardsPerIndexAndTurnsTheLibraryAxis)
{
    const auto rig = build();
    // ctrls.4 (wildcard): point = average of chain[4] (y=4) and chain[0] (y=0); axis z stands the circle up.
    const Bounds b4 = boundsOf(node(rig, "s::ctrls.4"));
    expectNear(b4.centre(), Vec3(0, -2, 0), "ctrls.4 centre");
    EXPECT_NEAR(b4.extent().z, 0.0, 1e-6);
    EXPECT_NEAR(b4.extent().y, 0.5, 1e-3);
    // ctrls.3 takes the `extra` entry through `reference`, not the wildcard.
    EXPECT_EQ(node(rig, "s::ctrls.3").shape, "cube");
}

TEST_F(ShapeStage, ReportsAnUnresolvableShapeAddressAndKeepsTheController)
{
    std::ofstream(folder + "/test/shaped/template.yml") << "base: core.joints\nshapes:\n  ctrls.0: {shape: circle, parent: nowhere}\n";
    io::scanTemplates(registry, {builtinTemplatesDirectory(), folder}, iconsDirectory());
    const auto rig = build();
    ASSERT_EQ(rig.diagnostics.size(), 1u) << formatAll(rig.diagnostics);
    EXPECT_EQ(rig.diagnostics[0].message, "instance 's' (test.shaped): shapes.ctrls.0.parent: unknown structure tag 'nowhere'");
    EXPECT_FALSE(node(rig, "s::ctrls.0").curves.empty());
}

TEST_F(ShapeStage, SizesFollowTheCharacterTheGuideIsPlacedFor)
{
    // A guide twice the template's default proportions gets shapes twice the
    // manifest's sizes; a one-joint instance hung on it (nothing to measure)
    // takes its parent's scale.
    auto withProp = [&](double spacing) {
        model::GuideDocument guide = guideOf({}, spacing);
        model::TemplateInstance prop;
        prop.id = 2;
        prop.templateId = "core.xform";
        prop.name = "p";
        prop.parent = 1;
        prop.parentJoint = 3;
        prop.joints.push_back({10, model::kNoId, {}, {}, {}});
        guide.insertInstance(prop, 1);
        return rigging::buildRig(guide, registry);
    };
    const auto normal = withProp(1.0);
    const auto giant = withProp(2.0);
    const auto tiny = withProp(0.01);
    ASSERT_FALSE(hasErrors(giant.diagnostics)) << formatAll(giant.diagnostics);
    expectNear(boundsOf(node(normal, "s::ctrls.0")).extent(), Vec3(2, 0, 2), "default proportions: the manifest's size");
    expectNear(boundsOf(node(giant, "s::ctrls.0")).extent(), Vec3(4, 0, 4), "twice the default: twice the size");
    expectNear(boundsOf(node(tiny, "s::ctrls.0")).extent(), Vec3(0.02, 0, 0.02), "a hundredth: a hundredth");
    const Vec3 propNormal = boundsOf(node(normal, "p::ctrls.xform")).extent();
    const Vec3 propGiant = boundsOf(node(giant, "p::ctrls.xform")).extent();
    EXPECT_NEAR(std::max({propNormal.x, propNormal.y, propNormal.z}), 0.2, 1e-6);
    expectNear(propGiant, propNormal * 2.0, "the one-joint child takes its parent's scale");
}

TEST_F(ShapeStage, MoreJointsOfTheSameSpacingKeepTheirSizes)
{
    model::GuideDocument guide = guideOf();
    auto& joints = guide.instance(1)->joints;
    for (model::JointId j = 6; j <= 12; ++j)
        joints.push_back({j, j - 1, {Vec3(0, 1, 0)}, {}, {}});
    const auto rig = rigging::buildRig(guide, registry);
    expectNear(boundsOf(node(rig, "s::ctrls.0")).extent(), Vec3(2, 0, 2), "a longer chain of the default spacing");
}
