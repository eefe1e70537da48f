// The core session: transactions (a drag is one undo step, previews replace
// each other and roll back), typed change events that name what changed, and
// live rebuild (the rig follows every guide change, previews included, with
// the test pose applied), all without Qt.
#include "TestSupport.h"

#include "edit/GuideEdits.h"
#include "eval/PoseTools.h"
#include "rigging/RigBuilder.h"
#include "io/RigDump.h"
#include "session/Session.h"

#include <gtest/gtest.h>

#include <memory>

using namespace rs;
using session::Change;
using session::ChangeKind;

namespace {

std::shared_ptr<const templates::TemplateRegistry> templatesForSession()
{
    // A shared copy of the built-in library (the session keeps its own pointer).
    return std::make_shared<templates::TemplateRegistry>(test::builtinTemplates());
}

struct Recorder {
    explicit Recorder(session::Session& s)
    {
        s.subscribe([this](const Change& c) { changes.push_back(c); });
    }
    std::vector<Change> changes;
    const Change& last() const { return changes.back(); }
};

model::JointId elbowOf(const model::GuideDocument& guide) { return guide.instanceNamed("arm")->joints[2].id; }

Mat4 raised(Mat4 world, double metres)
{
    world[3][1] += metres;
    return world;
}

} // namespace

TEST(Session, AGuideDragIsOneUndoStepAndItsPreviewsRebuildTheRigLive)
{
    session::Session s(templatesForSession());
    s.replaceDocument(test::loadSample("biped"));
    const model::GuideDocument original = s.document();
    s.build();
    Recorder events(s);
    const model::JointId elbow = elbowOf(s.document());
    const auto ik = *s.rig()->findPath("arm.L::ik.1"); // the IK elbow joint follows the guide's elbow
    const Vec3 before = translationOf(s.rig()->nodes[ik].worldMatrix);
    const Mat4 start = s.document().jointWorldMatrix(elbow);

    s.selectGuideJoints({elbow}, false);
    s.beginGuideDrag(elbow);
    for (int step = 1; step <= 3; ++step) {
        s.dragGuideTo(raised(start, 0.02 * step));
        const Change& c = events.last();
        EXPECT_TRUE(c.preview);
        EXPECT_TRUE(c.has(ChangeKind::Joints) && c.has(ChangeKind::Rig) && c.has(ChangeKind::Evaluation));
        EXPECT_FALSE(c.has(ChangeKind::History)) << "a preview is not a step";
        EXPECT_EQ(c.instances, std::vector<model::InstanceId>{s.document().instanceNamed("arm")->id});
        // The rig was rebuilt under the cursor: the elbow moved with the guide.
        const auto moved = *s.rig()->findPath("arm.L::ik.1");
        EXPECT_NEAR(translationOf(s.rig()->nodes[moved].worldMatrix).y - before.y, 0.02 * step, 1e-9);
        EXPECT_EQ(s.history().size(), 0u) << "nothing recorded while dragging";
    }
    s.endGuideDrag("Move guide joint of arm");
    EXPECT_EQ(s.history().size(), 1u);
    EXPECT_EQ(s.history().undoText(), "Move guide joint of arm");
    EXPECT_FALSE(events.last().preview);
    EXPECT_TRUE(events.last().has(ChangeKind::History));
    EXPECT_NEAR(translationOf(s.document().jointWorldMatrix(elbow)).y - translationOf(start).y, 0.06, 1e-9);
    EXPECT_EQ(s.selection().joint, elbow);

    s.history().undo();
    EXPECT_TRUE(s.document() == original);
    EXPECT_TRUE(events.last().has(ChangeKind::Rig)) << "undo rebuilds too";
    EXPECT_LT(glm::length(translationOf(s.rig()->nodes[*s.rig()->findPath("arm.L::ik.1")].worldMatrix) - before), 1e-12);
}

TEST(Session, ADragThatEndsWhereItBeganRecordsNothingAndPreviewsLeaveNoTrace)
{
    session::Session s(templatesForSession());
    s.replaceDocument(test::loadSample("biped"));
    const model::GuideDocument original = s.document();
    const model::JointId elbow = elbowOf(s.document());
    const Mat4 start = s.document().jointWorldMatrix(elbow);
    s.selectGuideJoints({elbow}, false);
    s.beginGuideDrag(elbow);
    s.dragGuideTo(raised(start, 0.1));
    EXPECT_FALSE(s.document() == original) << "the preview shows in the document, inside the transaction";
    s.dragGuideTo(start);
    s.endGuideDrag("Move guide joint of arm");
    EXPECT_EQ(s.history().size(), 0u);
    EXPECT_TRUE(s.document() == original);
    // A transaction rolled back (undo during a drag) restores the document exactly.
    s.beginGuideDrag(elbow);
    s.dragGuideTo(raised(start, 0.1));
    s.history().rollback();
    EXPECT_TRUE(s.document() == original);
    s.endGuideDrag("nothing");
    EXPECT_EQ(s.history().size(), 0u);
}

TEST(Session, EventsNameWhatChanged)
{
    session::Session s(templatesForSession());
    Recorder events(s);
    s.replaceDocument(test::loadSample("biped"));
    EXPECT_TRUE(events.last().has(ChangeKind::Document));
    const model::InstanceId spine = s.document().instanceNamed("spine")->id;

    ASSERT_TRUE(test::succeeded(s.setOption(spine, "stretch", Value(false))));
    EXPECT_EQ(events.last().kinds, (ChangeKind::Options | ChangeKind::History));
    EXPECT_EQ(events.last().instances, std::vector<model::InstanceId>{spine});
    EXPECT_FALSE(events.last().has(ChangeKind::Rig)) << "no rig built yet: nothing to rebuild";

    ASSERT_TRUE(test::succeeded(s.setOption(spine, "number", Value(7LL)))); // a guide parameter: joints regenerated
    EXPECT_TRUE(events.last().has(ChangeKind::Options) && events.last().has(ChangeKind::Joints));

    ASSERT_TRUE(test::succeeded(s.renameInstance(spine, "torso")));
    EXPECT_TRUE(events.last().has(ChangeKind::Instances) && events.last().has(ChangeKind::Names));

    s.build();
    EXPECT_EQ(events.last().kinds, (ChangeKind::Rig | ChangeKind::Evaluation | ChangeKind::Selection));
    ASSERT_TRUE(test::succeeded(s.setNameOverride(s.document().instanceNamed("arm")->id, "ik", "hand")));
    EXPECT_TRUE(events.last().has(ChangeKind::Names) && events.last().has(ChangeKind::Rig));
    EXPECT_FALSE(events.last().has(ChangeKind::Joints) || events.last().has(ChangeKind::Options));
    EXPECT_TRUE(s.rig()->findPath("arm.L::ctrls.ik"));
    EXPECT_EQ(s.rig()->nodes[*s.rig()->findPath("arm.L::ctrls.ik")].name, "c_arm_hand_L") << "rebuilt at once";

    s.select(session::Selection::ofInstance(spine));
    EXPECT_EQ(events.last().kinds, std::uint32_t(ChangeKind::Selection));
}

TEST(Session, PoseEditsEvaluateWithoutRebuildingAndRebuildsKeepThePose)
{
    session::Session s(templatesForSession());
    s.replaceDocument(test::loadSample("biped"));
    s.build();
    Recorder events(s);
    const model::Rig* built = s.rig();
    const auto fk = *s.rig()->findPath("arm.L::ctrls.fk.0");
    const auto hand = *s.rig()->findPath("arm.L::skin.limb.2");
    const auto blend = s.program()->channels().find(*s.rig()->findPath("arm.L::ctrls.switch"), "ik_blend");
    ASSERT_TRUE(blend);
    ASSERT_TRUE(test::succeeded(s.setChannel(*blend, 0.0, false))); // FK
    const auto rz = s.program()->channels().find(fk, "rz");
    ASSERT_TRUE(rz);
    ASSERT_TRUE(test::succeeded(s.setChannel(*rz, -45.0, false)));
    EXPECT_TRUE(events.last().has(ChangeKind::Pose) && events.last().has(ChangeKind::Evaluation));
    EXPECT_FALSE(events.last().has(ChangeKind::Rig)) << "posing never rebuilds";
    EXPECT_EQ(s.rig(), built);
    const Vec3 posedHand = translationOf(s.evaluation()->worldMatrix(hand));
    EXPECT_GT(glm::length(posedHand - translationOf(s.rig()->nodes[hand].worldMatrix)), 0.1);

    // A guide edit rebuilds live and the test pose is applied to the new rig.
    const model::JointId wrist = s.document().instanceNamed("spine")->joints[0].id;
    Transform moved = s.document().joint(wrist)->local;
    moved.translate.z += 0.05;
    ASSERT_TRUE(test::succeeded(edit::setJointTransform(s.history(), wrist, moved)));
    EXPECT_TRUE(events.last().has(ChangeKind::Rig));
    const auto handAfter = *s.rig()->findPath("arm.L::skin.limb.2");
    const model::Rig expected = rigging::buildRig(s.document(), s.templates());
    const auto posed = eval::posedRig(expected, model::testPose(s.document().overrides));
    ASSERT_TRUE(posed.ok());
    EXPECT_LT(maxAbsDifference(s.evaluation()->worldMatrix(handAfter), posed->nodes[*expected.findPath("arm.L::skin.limb.2")].worldMatrix),
              1e-9) << "the live rig equals a fresh build, posed";
    EXPECT_NEAR(translationOf(s.evaluation()->worldMatrix(handAfter)).z - posedHand.z, 0.05, 1e-9);
}

TEST(Session, ShapeAndCvDragsAreTransactionsOnTheAuthoredSide)
{
    session::Session s(templatesForSession());
    s.replaceDocument(test::loadSample("biped"));
    s.build();
    const model::GuideDocument original = s.document();
    const auto right = *s.rig()->findPath("arm.R::ctrls.ik");
    const Vec3 rightBefore = s.rig()->nodes[right].curves.front().points.front();
    s.selectControllers({right}, false);
    const Mat4 frame = *s.shapeFrame(right);
    s.beginShapeDrag(right);
    s.dragShapeTo(glm::translate(Mat4(1.0), Vec3(0.0, 0.1, 0.0)) * frame);
    const model::InstanceId arm = s.document().instanceNamed("arm")->id;
    ASSERT_TRUE(s.document().overrides.count({arm, {}, "ctrls.ik"})) << "the L side (authored) holds the edit";
    EXPECT_TRUE(s.document().overrides.at({arm, {}, "ctrls.ik"}).shape) << "the L side (authored) holds the edit";
    const auto previewed = *s.rig()->findPath("arm.R::ctrls.ik");
    EXPECT_GT(glm::length(s.rig()->nodes[previewed].curves.front().points.front() - rightBefore), 0.05) << "rebuilt live";
    EXPECT_EQ(s.history().size(), 0u);
    s.endShapeDrag();
    EXPECT_EQ(s.history().size(), 1u);
    EXPECT_EQ(s.history().undoText(), "Edit shape ctrls.ik of arm");
    s.history().undo();
    EXPECT_TRUE(s.document() == original);

    // CV mode: one undo step named by the CVs.
    s.setCvMode(true);
    const auto ik = *s.rig()->findPath("arm.L::ctrls.ik");
    s.selectControllers({ik}, false);
    s.selectCvs({{ik, 0, 0}, {ik, 0, 1}}, false);
    const Mat4 cvFrame = *s.cvFrame();
    s.beginCvDrag();
    s.dragCvsTo(glm::translate(Mat4(1.0), Vec3(0.0, 0.0, 0.05)) * cvFrame);
    s.dragCvsTo(glm::translate(Mat4(1.0), Vec3(0.0, 0.0, 0.1)) * cvFrame);
    EXPECT_EQ(s.history().size(), 1u) << "the undone shape step is still there to redo; nothing new yet";
    ASSERT_TRUE(test::succeeded(s.endCvDrag("Move")));
    EXPECT_EQ(s.history().size(), 1u);
    EXPECT_EQ(s.history().undoText(), "Move 2 CVs of ctrls.ik of arm");
    EXPECT_EQ(s.selection().cvs.size(), 2u) << "kept across the live rebuilds";
    s.history().undo();
    EXPECT_TRUE(s.document() == original);
}

namespace {

// The live rig of the session after an edit must be exactly what a full build
// of the edited guide makes (dumped: every node, matrix, curve, constraint),
// posed the same.
void expectLiveRigIsAFullBuild(session::Session& s, const std::string& what)
{
    ASSERT_NE(s.rig(), nullptr) << what;
    const model::Rig fresh = rigging::buildRig(s.document(), s.templates());
    EXPECT_EQ(io::writeRigDump(*s.rig()), io::writeRigDump(fresh)) << what;
    const auto posed = eval::posedRig(fresh, model::testPose(s.document().overrides));
    ASSERT_TRUE(posed.ok()) << what;
    ASSERT_EQ(s.evaluation()->world.size(), posed->nodes.size()) << what;
    for (model::RigNodeIndex i = 0; i < posed->nodes.size(); ++i)
        ASSERT_LT(maxAbsDifference(s.evaluation()->worldMatrix(i), posed->nodes[i].worldMatrix), 1e-9) << what << " " << posed->nodes[i].path;
}

} // namespace

TEST(Session, TheLiveRigEqualsAFullBuildAfterEveryKindOfEditOnEverySample)
{
    int cvDrags = 0, floatOptions = 0;
    for (const std::string sample : {"biped", "quadruped", "prop", "face", "claw", "cart", "strider"}) {
        session::Session s(templatesForSession());
        s.replaceDocument(test::loadSample(sample));
        s.build();
        // The last instance with a controller of its own: a finger, a tail, a lid.
        model::InstanceId leaf = model::kNoId;
        std::string controllerTag;
        NodeKey leafControl;
        for (const auto& node : s.rig()->nodes)
            if (node.kind == model::RigNodeKind::Controller && !node.shapeFromTwin) {
                leaf = node.key.instance;
                controllerTag = node.key.tag;
                leafControl = node.key;
            }
        ASSERT_NE(leaf, model::kNoId);
        const model::InstanceId root = s.document().instances().front().id;
        const std::string label = sample + ": ";

        // A guide-joint drag: previews, then the commit.
        const model::JointId joint = s.document().instance(leaf)->joints.front().id;
        const Mat4 start = s.document().jointWorldMatrix(joint);
        s.selectGuideJoints({joint}, false);
        s.beginGuideDrag(joint);
        s.dragGuideTo(raised(start, 0.03));
        expectLiveRigIsAFullBuild(s, label + "drag preview");
        s.dragGuideTo(raised(start, 0.05));
        s.endGuideDrag("Move");
        expectLiveRigIsAFullBuild(s, label + "drag commit");

        // A CV drag of the leaf's controller: previews, then the commit.
        if (const auto control = s.rig()->find(leafControl); control && !s.rig()->nodes[*control].curves.empty()) {
            s.selectControllers({*control}, false);
            s.setCvMode(true);
            s.selectCvs({{*control, 0, 0}}, false);
            const auto frame = s.cvFrame();
            ASSERT_TRUE(frame.has_value()) << label;
            s.beginCvDrag();
            s.dragCvsTo(raised(*frame, 0.02));
            expectLiveRigIsAFullBuild(s, label + "CV drag preview");
            s.dragCvsTo(raised(*frame, 0.04));
            ASSERT_TRUE(test::succeeded(s.endCvDrag("Move")));
            expectLiveRigIsAFullBuild(s, label + "CV drag commit");
            ++cvDrags;
            s.setCvMode(false);
        }

        // Options and guide parameters of the leaf's template.
        const auto* manifest = s.templates().find(s.document().instance(leaf)->templateId);
        ASSERT_NE(manifest, nullptr);
        for (const auto& option : manifest->opts)
            if (std::holds_alternative<bool>(option.value)) {
                ASSERT_TRUE(test::succeeded(s.setOption(leaf, option.name, Value(!std::get<bool>(option.value)))));
                expectLiveRigIsAFullBuild(s, label + "option " + option.name);
                break;
            }
        for (const auto& option : manifest->opts)
            if (std::holds_alternative<double>(option.value)) {
                const double v = std::get<double>(option.value);
                const double other = option.max && v + 0.25 > *option.max ? v - 0.25 : v + 0.25;
                ASSERT_TRUE(test::succeeded(s.setOption(leaf, option.name, Value(other))));
                expectLiveRigIsAFullBuild(s, label + "float option " + option.name);
                ++floatOptions;
                break;
            }
        for (const auto& guide : manifest->guides)
            if (std::holds_alternative<long long>(guide.value) && guide.max && *guide.max > double(std::get<long long>(guide.value))) {
                ASSERT_TRUE(test::succeeded(s.setOption(leaf, guide.name, Value(std::get<long long>(guide.value) + 1))));
                expectLiveRigIsAFullBuild(s, label + "guide parameter " + guide.name);
                break;
            }

        // A shape edit, a name override, a rename, a pose.
        model::ShapeEdit shape; // (an option above may have removed the controller: then the edit is kept, unused)
        shape.transform.scale = Vec3(1.5);
        ASSERT_TRUE(test::succeeded(edit::setShapeEdit(s.history(), leaf, controllerTag, shape)));
        expectLiveRigIsAFullBuild(s, label + "shape edit");
        for (const auto& [token, name] : manifest->names)
            if (s.setNameOverride(leaf, token, "renamed").ok()) {
                expectLiveRigIsAFullBuild(s, label + "name override " + token);
                break;
            }
        ASSERT_TRUE(test::succeeded(s.renameInstance(leaf, "leafy")));
        expectLiveRigIsAFullBuild(s, label + "rename");
        const auto fk = std::find_if(s.rig()->nodes.begin(), s.rig()->nodes.end(), [](const model::RigNode& n) {
            return n.kind == model::RigNodeKind::Controller;
        });
        model::PoseValues pose = model::testPose(s.document().overrides);
        pose[fk->key]["rx"] = 20.0;
        ASSERT_TRUE(test::succeeded(edit::setPose(s.history(), pose, "Pose")));
        expectLiveRigIsAFullBuild(s, label + "pose");

        // Instances: duplicate, re-hang, remove; then undo and redo everything.
        ASSERT_TRUE(test::succeeded(s.duplicateInstances({leaf})));
        expectLiveRigIsAFullBuild(s, label + "duplicate");
        const model::InstanceId copy = s.document().instances().back().id;
        ASSERT_TRUE(test::succeeded(s.reparentInstance(copy, s.document().instance(root)->joints.front().id)));
        expectLiveRigIsAFullBuild(s, label + "re-hang");
        ASSERT_TRUE(test::succeeded(s.removeInstances({copy})));
        expectLiveRigIsAFullBuild(s, label + "remove");
        ASSERT_TRUE(test::succeeded(s.addTemplate("core.joints", s.document().instance(root)->joints.front().id)));
        expectLiveRigIsAFullBuild(s, label + "add template");
        while (s.history().canUndo()) {
            s.history().undo();
            expectLiveRigIsAFullBuild(s, label + "undo to " + std::to_string(s.history().index()));
        }
        while (s.history().canRedo())
            s.history().redo();
        expectLiveRigIsAFullBuild(s, label + "redo all");
    }
    EXPECT_EQ(cvDrags, 7) << "a CV drag on every sample's leaf controller";
    EXPECT_GE(floatOptions, 1);
}

TEST(Session, MirroredGuideJointsAreTheAuthoredBranchReflected)
{
    // What the viewport draws for the `.R` copies: the authored arm's joints
    // reflected across x, owned by the authored instance.
    session::Session s(templatesForSession());
    s.replaceDocument(test::loadSample("biped"));
    const model::TemplateInstance& arm = *s.document().instanceNamed("arm");
    const std::vector<session::MirroredGuideJoint> mirrored = s.mirroredGuideJoints();
    std::vector<Vec3> armCopy;
    for (const auto& j : mirrored)
        if (j.owner == arm.id)
            armCopy.push_back(j.position);
    ASSERT_EQ(armCopy.size(), arm.joints.size());
    for (std::size_t i = 0; i < arm.joints.size(); ++i) {
        const Vec3 authored = translationOf(s.document().jointWorldMatrix(arm.joints[i].id));
        EXPECT_NEAR(glm::distance(armCopy[i], Vec3(-authored.x, authored.y, authored.z)), 0.0, 1e-9) << i;
    }
    for (const auto& j : mirrored)
        EXPECT_NE(s.document().instance(j.owner), nullptr) << "owned by an authored instance";
}
