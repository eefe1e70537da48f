#include "base/Nurbs.h"
#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"
#include "edit/ShapeCvEdit.h"
#include "io/GuideFile.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

model::Rig buildBiped(const model::GuideDocument& doc)
{
    model::Rig rig = rigging::buildRig(doc, test::builtinTemplates());
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    return rig;
}

model::CurveCv cvOf(const model::Rig& rig, const std::string& id, int curve, int cv)
{
    return {*rig.findPath(id), curve, cv};
}

Vec3 reflectedX(const Vec3& v) { return Vec3(-v.x, v.y, v.z); }

// Every CV of a controller in the world, curve after curve.
std::vector<Vec3> worldCvs(const model::Rig& rig, const std::string& id)
{
    std::vector<Vec3> out;
    const model::RigNodeIndex n = *rig.findPath(id);
    for (int k = 0; k < int(rig.nodes[n].curves.size()); ++k)
        for (int i = 0; i < int(rig.nodes[n].curves[k].cvs.size()); ++i)
            out.push_back(edit::cvWorldPosition(rig, {n, k, i}));
    return out;
}

void expectNear(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const char* what)
{
    ASSERT_EQ(a.size(), b.size()) << what;
    for (std::size_t i = 0; i < a.size(); ++i)
        EXPECT_LT(glm::length(a[i] - b[i]), 1e-9) << what << " CV " << i;
}

} // namespace

TEST(ShapeCvEdit, BuiltCurvesCarryTheirCvsAndAreSampledFromThem)
{
    const model::Rig rig = buildBiped(test::loadSample("biped"));
    int curves = 0;
    for (const model::RigNode& node : rig.nodes)
        for (const model::ControllerCurve& curve : node.curves) {
            ASSERT_FALSE(curve.cvs.empty()) << node.path;
            const auto sampled = evaluateNurbs(curve.cvs, curve.degree, curve.periodic);
            ASSERT_EQ(sampled.size(), curve.points.size()) << node.path;
            for (std::size_t i = 0; i < sampled.size(); ++i)
                ASSERT_LT(glm::length(sampled[i] - curve.points[i]), 1e-9) << node.path << " point " << i;
            ++curves;
        }
    EXPECT_GT(curves, 80);
}

TEST(ShapeCvEdit, MovingACvMovesItExactlyTheMirroredSideFollowsAndItIsSaved)
{
    model::GuideDocument doc = test::loadSample("biped");
    const model::GuideDocument original = doc;
    edit::History history(doc);
    const model::Rig before = buildBiped(doc);
    const std::string left = "arm.L::ctrls.ik", right = "arm.R::ctrls.ik";

    auto drag = edit::CvDrag::begin(doc, before, {cvOf(before, left, 0, 2)});
    ASSERT_TRUE(drag) << formatAll(drag.diagnostics());
    EXPECT_LT(glm::length(translationOf(drag->frame()) - edit::cvWorldPosition(before, cvOf(before, left, 0, 2))), 1e-12)
        << "one CV: the gizmo sits on it";
    const Vec3 move(0.0, 0.1, 0.05);
    ASSERT_TRUE(test::succeeded(drag->commit(history, translationMatrix(move))));
    EXPECT_EQ(history.undoText(), "Move CV 2 of ctrls.ik of arm");
    const model::Rig after = buildBiped(doc);

    std::vector<Vec3> expected = worldCvs(before, left);
    expected[2] += move;
    expectNear(worldCvs(after, left), expected, "left");
    std::vector<Vec3> mirrored;
    for (const Vec3& p : worldCvs(after, left))
        mirrored.push_back(reflectedX(p));
    expectNear(worldCvs(after, right), mirrored, "right = left reflected");
    // The drawn polyline is sampled again from the moved CVs.
    const model::ControllerCurve& curve = test::node(after, left).curves[0];
    EXPECT_EQ(curve.points, evaluateNurbs(curve.cvs, curve.degree, curve.periodic));
    EXPECT_NE(curve.points, test::node(before, left).curves[0].points);
    EXPECT_EQ(test::node(after, "arm.L::ctrls.fk.0").curves[0].points, test::node(before, "arm.L::ctrls.fk.0").curves[0].points)
        << "other controls unchanged";

    // The guide keeps the edit, a line per CV, and reads it back.
    const std::string text = io::writeGuideText(doc);
    const auto at = text.find("    node: ctrls.ik\n    shape: {}\n    cvs:\n      - {curve: 0, cv: 2, offset: [");
    EXPECT_NE(at, std::string::npos) << text;
    auto read = io::readGuideText(text, "cvs.yml");
    ASSERT_TRUE(read) << formatAll(read.diagnostics());
    EXPECT_TRUE(*read == doc);
    std::string broken = text;
    broken.replace(broken.find("{curve: 0, cv: 2"), 16, "{curve: 0, cv: -2");
    auto refused = io::readGuideText(broken, "broken.yml");
    ASSERT_FALSE(refused);
    EXPECT_NE(formatAll(refused.diagnostics()).find("broken.yml:"), std::string::npos) << formatAll(refused.diagnostics());
    EXPECT_NE(formatAll(refused.diagnostics()).find("indices from 0"), std::string::npos) << formatAll(refused.diagnostics());

    history.undo();
    EXPECT_TRUE(doc == original);
}

TEST(ShapeCvEdit, CvsOfTheMirroredCopyAndOfATransformedShapeAreEditedExactly)
{
    model::GuideDocument doc = test::loadSample("biped");
    edit::History history(doc);
    const model::InstanceId leg = doc.instanceNamed("leg")->id;
    // The whole shape first turned and scaled: CV offsets live before that transform.
    model::ShapeEdit whole;
    whole.transform.rotateDegrees = Vec3(0.0, 30.0, 10.0);
    whole.transform.scale = Vec3(1.5, 2.0, 1.0);
    ASSERT_TRUE(test::succeeded(edit::setShapeEdit(history, leg, "ctrls.ik", whole)));
    const model::Rig before = buildBiped(doc);
    const std::string left = "leg.L::ctrls.ik", right = "leg.R::ctrls.ik";
    ASSERT_TRUE(test::node(before, right).shapeFromTwin);
    ASSERT_FALSE(test::node(before, left).shapeFromTwin);

    // Three CVs of the right (mirrored) side turned 90 degrees about Y around their centre.
    auto drag = edit::CvDrag::begin(doc, before, {cvOf(before, right, 0, 0), cvOf(before, right, 0, 1), cvOf(before, right, 0, 3)});
    ASSERT_TRUE(drag) << formatAll(drag.diagnostics());
    const Vec3 centre = translationOf(drag->frame());
    const Mat4 change = translationMatrix(centre) * rotationMatrix(Vec3(0, 1, 0), glm::half_pi<double>()) * translationMatrix(-centre);
    const auto preview = drag->previewFor(change);
    ASSERT_EQ(preview.size(), 2u) << "the dragged side and its twin preview";
    ASSERT_TRUE(test::succeeded(drag->commit(history, change, "Rotate")));
    EXPECT_EQ(history.undoText(), "Rotate 3 CVs of ctrls.ik of leg");
    EXPECT_EQ(doc.overrides.at({leg, {}, "ctrls.ik"}).shape->edit.transform, whole.transform) << "the whole-shape edit is kept";
    const model::Rig after = buildBiped(doc);

    std::vector<Vec3> expected = worldCvs(before, right);
    for (int i : {0, 1, 3})
        expected[i] = Vec3(change * Vec4(expected[i], 1.0));
    expectNear(worldCvs(after, right), expected, "right");
    std::vector<Vec3> mirrored;
    for (const Vec3& p : expected)
        mirrored.push_back(reflectedX(p));
    expectNear(worldCvs(after, left), mirrored, "left = right reflected");
    // The preview showed what the build makes.
    const model::RigNodeIndex r = *before.findPath(right);
    for (std::size_t i = 0; i < preview.at(r)[0].cvs.size(); ++i)
        EXPECT_LT(glm::length(preview.at(r)[0].cvs[i] - test::node(after, right).curves[0].cvs[i]), 1e-9);
}

TEST(ShapeCvEdit, RefusesCvsOfSeveralControllersOrOutOfRangeAndWarnsOfEditsTheShapeLacks)
{
    model::GuideDocument doc = test::loadSample("biped");
    const model::Rig rig = buildBiped(doc);
    auto mixed = edit::CvDrag::begin(doc, rig, {cvOf(rig, "arm.L::ctrls.ik", 0, 0), cvOf(rig, "arm.L::ctrls.fk.0", 0, 0)});
    ASSERT_FALSE(mixed);
    EXPECT_NE(formatAll(mixed.diagnostics()).find("several controllers"), std::string::npos);
    auto outside = edit::CvDrag::begin(doc, rig, {cvOf(rig, "arm.L::ctrls.ik", 0, 999)});
    ASSERT_FALSE(outside);
    EXPECT_NE(formatAll(outside.diagnostics()).find("has no CV 999"), std::string::npos) << formatAll(outside.diagnostics());
    EXPECT_FALSE(edit::CvDrag::begin(doc, rig, {}));

    // An edit of a CV the shape no longer has (the template's shape changed) is a warning, not a failure.
    edit::History history(doc);
    model::ShapeEdit stale;
    stale.cvs[{0, 999}] = Vec3(0.0, 1.0, 0.0);
    ASSERT_TRUE(test::succeeded(edit::setShapeEdit(history, doc.instanceNamed("arm")->id, "ctrls.ik", stale)));
    const model::Rig warned = rigging::buildRig(doc, test::builtinTemplates());
    EXPECT_FALSE(hasErrors(warned.diagnostics));
    const std::string all = formatAll(warned.diagnostics);
    const std::string warning = "override of 'arm::ctrls.ik': the shape has no CV 999 on curve 0";
    const auto first = all.find(warning);
    EXPECT_NE(first, std::string::npos) << all;
    EXPECT_EQ(all.find(warning, first + 1), std::string::npos) << "once, not again for the mirrored copy: " << all;
    EXPECT_EQ(test::node(warned, "arm.L::ctrls.ik").curves[0].points, test::node(rig, "arm.L::ctrls.ik").curves[0].points);
}
