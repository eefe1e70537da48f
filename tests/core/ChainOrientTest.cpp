// Joint orientation computed at build from guide positions (Mikan's orient,
// aim_axis, up_axis, up_dir, up_auto) on core.joints, core.bones and
// rig.spline, as an animator checks it on the built rig: each joint's aim
// axis points at its child, its up axis where it was asked, the rest positions
// stay where the guides are, a mirrored branch is the exact mirror, circles
// ring the chain, and a bad axis is refused where it is written.
#include "base/Paths.h"
#include "core/TestSupport.h"
#include "io/GuideFile.h"
#include "io/TemplateFolders.h"
#include "rigging/RigBuilder.h"
#include "templates/Manifest.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>

namespace rs {
namespace {

using Options = std::map<std::string, Value>;

// A chain of `templateId` whose guide joints are only translated: a bend in
// the side (YZ) plane, then a turn out of it, as a rigger drags guides.
model::GuideDocument bentChain(const std::string& templateId, const Options& options, int count = 5)
{
    model::GuideDocument doc;
    Options all = options;
    all["number"] = Value(static_cast<long long>(count));
    auto made = rigging::makeInstance(doc, test::builtinTemplates(), templateId, model::kNoId, all);
    EXPECT_TRUE(made.ok()) << formatAll(made.diagnostics());
    model::TemplateInstance instance = made.take();
    const Vec3 steps[] = {{0.3, 1.0, 0.1}, {0.0, 0.2, 0.05}, {0.0, 0.15, 0.12}, {0.0, 0.05, 0.2}, {0.1, 0.0, 0.15}, {0.0, -0.1, 0.1}};
    for (std::size_t i = 0; i < instance.joints.size(); ++i) {
        instance.joints[i].local.translate = steps[i % 6];
        instance.joints[i].local.rotateDegrees = Vec3(0.0);
    }
    doc.insertInstance(instance, 0);
    return doc;
}

model::Rig build(const model::GuideDocument& doc)
{
    model::Rig rig = rigging::buildRig(doc, test::builtinTemplates());
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    return rig;
}

Vec3 axisOf(const Mat4& world, const std::string& axis) { return Mat3(world) * *templates::parseAxis(axis); }

std::vector<Vec3> guidePositions(const model::GuideDocument& doc)
{
    std::vector<Vec3> out;
    for (const auto& joint : doc.instances().front().joints)
        out.push_back(translationOf(doc.jointWorldMatrix(joint.id)));
    return out;
}

std::string pathOf(const model::GuideDocument& doc, const std::string& tag) { return doc.instances().front().name + "::" + tag; }

TEST(ChainOrient, AutoAimsEachJointAtItsChildWithTheUpAxisTowardsUpDir)
{
    const std::vector<std::pair<std::string, std::string>> axes{{"x", "y"}, {"-y", "z"}, {"z", "-x"}, {"-x", "-z"}};
    for (const auto& [aim, up] : axes) {
        const Vec3 upDir = glm::normalize(Vec3(0.2, 1.0, -0.3));
        const auto doc = bentChain("core.joints", {{"orient", Value(std::string("auto"))}, {"aim_axis", Value(aim)},
                                                   {"up_axis", Value(up)}, {"up_dir", Value(Vec3(0.2, 1.0, -0.3))}});
        const model::Rig rig = build(doc);
        const auto points = guidePositions(doc);
        for (std::size_t i = 0; i < points.size(); ++i) {
            for (const char* tag : {"ctrls.", "skin.", "roots."}) {
                const Mat4 world = test::node(rig, pathOf(doc, tag + std::to_string(i))).worldMatrix;
                SCOPED_TRACE(aim + "/" + up + " " + tag + std::to_string(i));
                EXPECT_LT(glm::length(translationOf(world) - points[i]), 1e-12) << "the rest position is the guide's";
                EXPECT_NEAR(glm::determinant(Mat3(world)), 1.0, 1e-12) << "rigid and right-handed";
                if (i + 1 == points.size()) { // the last joint takes its parent's frame
                    const Mat4 parent = test::node(rig, pathOf(doc, tag + std::to_string(i - 1))).worldMatrix;
                    EXPECT_LT(maxAbsDifference(Mat4(Mat3(world)), Mat4(Mat3(parent))), 1e-12);
                    continue;
                }
                const Vec3 child = glm::normalize(points[i + 1] - points[i]);
                EXPECT_GT(glm::dot(axisOf(world, aim), child), 1.0 - 1e-9) << "the aim axis points at the child";
                const Vec3 upAxis = axisOf(world, up);
                EXPECT_NEAR(glm::dot(upAxis, glm::cross(child, upDir)), 0.0, 1e-9) << "the up axis lies in the plane of aim and up_dir";
                EXPECT_GT(glm::dot(upAxis, upDir), 0.0) << "on up_dir's side";
            }
        }
    }
}

TEST(ChainOrient, UpAutoTurnsTheUpAxisToTheBendNormal)
{
    // A chain bending in one plane (x = 0.3): the up axis is the plane's normal, the aim axes lie in it.
    auto doc = bentChain("core.joints", {{"orient", Value(std::string("auto"))}, {"up_auto", Value(true)}, {"up_axis", Value(std::string("z"))}}, 4);
    const model::Rig rig = build(doc);
    const auto points = guidePositions(doc);
    const Vec3 normal = glm::normalize(glm::cross(points[1] - points[0], points[2] - points[1]));
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Mat4 world = test::node(rig, pathOf(doc, "skin." + std::to_string(i))).worldMatrix;
        EXPECT_GT(glm::dot(axisOf(world, "z"), normal), 1.0 - 1e-9) << i;
        EXPECT_NEAR(glm::dot(axisOf(world, "x"), normal), 0.0, 1e-9) << i << ": the aim axis stays in the bend plane";
    }
}

TEST(ChainOrient, CopyKeepsTheGuideFramesAndWorldTheWorldAxes)
{
    auto doc = bentChain("core.joints", {});
    doc.instance(doc.instances().front().id)->joints[1].local.rotateDegrees = Vec3(10.0, 20.0, 30.0);
    const model::Rig copied = build(doc);
    for (const auto& joint : doc.instances().front().joints) {
        const auto& node = test::node(copied, pathOf(doc, "skin." + std::to_string(&joint - &doc.instances().front().joints[0])));
        EXPECT_LT(maxAbsDifference(node.worldMatrix, doc.jointWorldMatrix(joint.id)), 1e-12) << "copy is today's behaviour";
    }
    doc.instance(doc.instances().front().id)->options["orient"] = Value(std::string("world"));
    const model::Rig world = build(doc);
    const auto points = guidePositions(doc);
    for (std::size_t i = 0; i < points.size(); ++i)
        EXPECT_LT(maxAbsDifference(test::node(world, pathOf(doc, "skin." + std::to_string(i))).worldMatrix, translationMatrix(points[i])), 1e-12);
}

// Every node of the R copy is the mirror (x plane) of its L twin, paired for pose mirroring.
void expectExactMirror(const std::string& templateId, const Options& options)
{
    Options branched = options;
    branched["branches"] = Value(std::string("[L, R]"));
    const auto doc = bentChain(templateId, branched);
    const model::Rig rig = build(doc);
    Mat4 mirror(1.0);
    mirror[0][0] = -1.0;
    std::size_t pairs = 0;
    for (const model::RigNode& right : rig.nodes) {
        const auto at = right.path.find(".R::");
        if (at == std::string::npos)
            continue;
        const model::RigNode& left = test::node(rig, std::string(right.path).replace(at, 4, ".L::"));
        EXPECT_LT(maxAbsDifference(right.worldMatrix, mirror * left.worldMatrix * mirror), 1e-12) << templateId << " " << right.path;
        EXPECT_EQ(right.mirrorPlane, 0) << right.path;
        EXPECT_NE(right.twin, model::kNoNode) << right.path;
        ++pairs;
    }
    EXPECT_GT(pairs, 10u) << templateId;
}

TEST(ChainOrient, ABranchCopyMirrorsExactly)
{
    const Value autoMode(std::string("auto"));
    expectExactMirror("core.joints", {{"orient", autoMode}});
    expectExactMirror("core.joints", {{"orient", autoMode}, {"up_auto", Value(true)}, {"aim_axis", Value(std::string("-z"))}});
    expectExactMirror("core.bones", {{"orient", autoMode}});
    expectExactMirror("rig.spline", {{"aim_axis", Value(std::string("y"))}, {"up_axis", Value(std::string("x"))}});
}

TEST(ChainOrient, BonesAimTheirAimAxisAndTakeTheirRollFromOrient)
{
    const Vec3 upDir(0.0, 0.0, 1.0);
    const auto doc = bentChain("core.bones", {{"orient", Value(std::string("auto"))}, {"up_axis", Value(std::string("x"))}});
    const model::Rig rig = build(doc);
    const auto points = guidePositions(doc);
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const Mat4 world = test::node(rig, pathOf(doc, "ctrls." + std::to_string(i))).worldMatrix;
        const Vec3 child = glm::normalize(points[i + 1] - points[i]);
        EXPECT_GT(glm::dot(axisOf(world, "y"), child), 1.0 - 1e-9) << "+Y along the bone by default";
        EXPECT_NEAR(glm::dot(axisOf(world, "x"), glm::cross(child, upDir)), 0.0, 1e-9) << i;
        EXPECT_GT(glm::dot(axisOf(world, "x"), upDir), 0.0) << i;
    }
    const Mat4 tip = test::node(rig, pathOf(doc, "hooks.tip")).worldMatrix;
    const Mat4 last = test::node(rig, pathOf(doc, "ctrls." + std::to_string(points.size() - 2))).worldMatrix;
    EXPECT_LT(glm::length(translationOf(tip) - points.back()), 1e-12);
    EXPECT_LT(maxAbsDifference(Mat4(Mat3(tip)), Mat4(Mat3(last))), 1e-12) << "the tip keeps the last bone's frame";
}

TEST(ChainOrient, SplineJointsAimTheAxisAskedForAndKeepTheirPlaces)
{
    const auto doc = bentChain("rig.spline", {{"aim_axis", Value(std::string("-y"))}, {"up_axis", Value(std::string("x"))}}, 6);
    const model::Rig rig = build(doc);
    const auto points = guidePositions(doc);
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const Mat4 world = test::node(rig, pathOf(doc, "skin." + std::to_string(i))).worldMatrix;
        EXPECT_LT(glm::length(translationOf(world) - points[i]), 1e-12);
        EXPECT_GT(glm::dot(axisOf(world, "-y"), glm::normalize(points[i + 1] - points[i])), 1.0 - 1e-9) << i;
    }
}

// rig.spline's frames before these options rolled a straight chain with its
// root guide; an instance that leaves up_dir unset keeps that, one that sets
// it gets it.
TEST(ChainOrient, AStraightSplineRollsWithItsRootGuideUnlessUpDirIsSet)
{
    for (const bool setUpDir : {false, true}) {
        Options options{{"number", Value(5LL)}};
        if (setUpDir)
            options["up_dir"] = Value(Vec3(0.0, 1.0, 0.0));
        model::GuideDocument doc;
        auto made = rigging::makeInstance(doc, test::builtinTemplates(), "rig.spline", model::kNoId, options);
        ASSERT_TRUE(made.ok()) << formatAll(made.diagnostics());
        model::TemplateInstance instance = made.take();
        // The root guide turned 90 degrees about Y after 45 about X (its X to
        // world -Z, its Z to (1, -1, 0) / sqrt 2); every child 0.2 m along its
        // parent's X: straight back along -Z.
        for (std::size_t i = 0; i < instance.joints.size(); ++i) {
            instance.joints[i].local.translate = i == 0 ? Vec3(0.0, 1.0, 0.0) : Vec3(0.2, 0.0, 0.0);
            instance.joints[i].local.rotateDegrees = i == 0 ? Vec3(45.0, 90.0, 0.0) : Vec3(0.0);
        }
        doc.insertInstance(instance, 0);
        const model::Rig rig = build(doc);
        const auto points = guidePositions(doc);
        ASSERT_LT(glm::length(points[1] - points[0] - Vec3(0.0, 0.0, -0.2)), 1e-12) << "a straight chain back along -Z";
        const Vec3 expectedUp = setUpDir ? Vec3(0.0, 1.0, 0.0) : glm::normalize(Vec3(1.0, -1.0, 0.0)); // up_dir, or the root guide's Z
        for (std::size_t i = 0; i < points.size(); ++i) {
            const Mat4 world = test::node(rig, pathOf(doc, "skin." + std::to_string(i))).worldMatrix;
            EXPECT_GT(glm::dot(axisOf(world, "x"), Vec3(0.0, 0.0, -1.0)), 1.0 - 1e-9) << i;
            EXPECT_GT(glm::dot(axisOf(world, "z"), expectedUp), 1.0 - 1e-9) << (setUpDir ? "up_dir " : "root guide ") << i;
        }
    }
}

// The largest extent of a controller's curve along a world direction.
double thickness(const model::RigNode& node, const Vec3& direction)
{
    double lo = 1e300, hi = -1e300;
    for (const Vec3& p : node.curves.at(0).points) {
        const double along = glm::dot(Vec3(node.worldMatrix * Vec4(p, 1.0)), direction);
        lo = std::min(lo, along);
        hi = std::max(hi, along);
    }
    return hi - lo;
}

TEST(ChainOrient, CirclesRingTheChainWhicheverAxisAims)
{
    for (const std::string aim : {"x", "y", "-z"}) {
        const std::string up = aim == "y" ? "z" : "y";
        const auto doc = bentChain("core.joints", {{"orient", Value(std::string("auto"))}, {"aim_axis", Value(aim)}, {"up_axis", Value(up)}});
        const model::Rig rig = build(doc);
        const auto points = guidePositions(doc);
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            const auto& ctrl = test::node(rig, pathOf(doc, "ctrls." + std::to_string(i)));
            ASSERT_FALSE(ctrl.curves.empty());
            const Vec3 chain = glm::normalize(points[i + 1] - points[i]);
            EXPECT_LT(thickness(ctrl, chain), 1e-9) << aim << " " << i << ": the circle lies across the chain";
            EXPECT_GT(thickness(ctrl, glm::normalize(glm::cross(chain, Vec3(1.0, 0.0, 0.0)))), 0.01) << aim;
        }
    }
    const auto spline = bentChain("rig.spline", {{"aim_axis", Value(std::string("z"))}, {"up_axis", Value(std::string("y"))}}, 6);
    const model::Rig rig = build(spline);
    const auto& first = test::node(rig, pathOf(spline, "ctrls.spline.0"));
    const auto points = guidePositions(spline);
    EXPECT_LT(thickness(first, glm::normalize(points[1] - points[0])), 1e-9) << "the spline's circles too";
}

TEST(ChainOrient, TheOptionsRoundTripThroughTheGuideFile)
{
    const Options options{{"orient", Value(std::string("auto"))}, {"aim_axis", Value(std::string("-y"))},
                          {"up_axis", Value(std::string("z"))}, {"up_dir", Value(Vec3(1.0, 0.0, 0.5))}, {"up_auto", Value(true)}};
    const auto doc = bentChain("core.joints", options);
    const std::string text = io::writeGuideText(doc);
    auto read = io::readGuideText(text, "orient.yml");
    ASSERT_TRUE(read.ok()) << formatAll(read.diagnostics());
    const model::GuideDocument back = read.take();
    for (const auto& [name, value] : options)
        EXPECT_EQ(back.instances().front().options.at(name), value) << name;
    EXPECT_EQ(io::writeGuideText(back), text);
    EXPECT_NE(text.find("up_dir: [1, 0, 0.5]"), std::string::npos) << text;
}

TEST(ChainOrient, AnUpAxisAlongTheAimAxisIsRefusedWhereItIsWritten)
{
    // In a guide file: at the up_axis line.
    const std::string guide = "rigsmith_guide: 3\nname: g\ninstances:\n  - id: 1\n    template: core.joints\n    name: tail\n"
                              "    options:\n      aim_axis: -y\n      up_axis: y\n    joints:\n      - {id: 1, t: [0, 0, 0]}\n";
    auto read = io::readGuideText(guide, "bad.yml");
    ASSERT_FALSE(read.ok());
    EXPECT_NE(formatAll(read.diagnostics()).find("bad.yml:9:"), std::string::npos) << formatAll(read.diagnostics());
    EXPECT_NE(formatAll(read.diagnostics()).find("lies along aim_axis"), std::string::npos);

    // Against the template's default (aim x): the build refuses it, naming the option.
    const auto doc = bentChain("core.joints", {{"orient", Value(std::string("auto"))}, {"up_axis", Value(std::string("-x"))}});
    const model::Rig rig = rigging::buildRig(doc, test::builtinTemplates());
    EXPECT_TRUE(hasErrors(rig.diagnostics));
    EXPECT_NE(formatAll(rig.diagnostics).find("option 'up_axis'"), std::string::npos) << formatAll(rig.diagnostics);

    // In a template's defaults: at the manifest's line.
    const std::string folder = test::temporaryPath("orient-templates");
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder + "/test/chain");
    std::ofstream(folder + "/test/chain/template.yml") << "base: core.joints\nopts:\n  aim_axis: {value: z, enum: [x, y, z]}\n"
                                                          "  up_axis:\n    value: z\n    enum: [x, y, z]\n";
    templates::TemplateRegistry registry;
    const Diagnostics d = io::scanTemplates(registry, {builtinTemplatesDirectory(), folder}, iconsDirectory());
    EXPECT_NE(formatAll(d).find("template.yml:5:"), std::string::npos) << formatAll(d);
}

TEST(ChainOrient, AShapeAxisNamingAnOptionThatIsNoAxisIsRefusedAtItsLine)
{
    const std::string folder = test::temporaryPath("orient-shape-templates");
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder + "/test/ringed");
    std::ofstream(folder + "/test/ringed/template.yml") << "base: core.joints\nopts:\n  orient: {value: copy, enum: [copy, auto, world]}\n"
                                                           "shapes:\n  ctrls.*:\n    shape: circle\n"
                                                           "    axis: orient\n  ctrls.0:\n    shape: circle\n    axis: nowhere\n";
    templates::TemplateRegistry registry;
    const std::string all = formatAll(io::scanTemplates(registry, {builtinTemplatesDirectory(), folder}, iconsDirectory()));
    EXPECT_NE(all.find("template.yml:7:11: error: shapes.ctrls.*.axis: option 'orient' can be 'copy', which is no axis"), std::string::npos) << all;
    EXPECT_NE(all.find("template.yml:10:11: error: shapes.ctrls.0.axis: no option 'nowhere'"), std::string::npos) << all;
}

} // namespace
} // namespace rs
