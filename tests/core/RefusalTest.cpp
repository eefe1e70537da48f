// Refused edits: each returns a failed Status whose error names what it is
// about with a typed subject (the instance, the guide joint, the shape, the rig
// node), changes nothing, and reaches the session's caller unchanged.
#include "TestSupport.h"

#include "edit/GuideEdits.h"
#include "edit/GuideMove.h"
#include "edit/ShapeCvEdit.h"
#include "session/Session.h"

#include <gtest/gtest.h>

#include <limits>
#include <memory>

using namespace rs;

namespace {

// The one error of a refusal (fails the test when there is not exactly one).
Diagnostic onlyError(const Status& status)
{
    EXPECT_TRUE(status.failed());
    EXPECT_EQ(status.diagnostics().size(), 1u) << status.message();
    if (status.diagnostics().empty())
        return {};
    const Diagnostic& d = status.diagnostics().front();
    EXPECT_EQ(d.severity, Severity::Error);
    EXPECT_TRUE(d.where.file.empty()) << "an edit's refusal has no file position";
    return d;
}

std::shared_ptr<const templates::TemplateRegistry> templatesForSession()
{
    return std::make_shared<templates::TemplateRegistry>(test::builtinTemplates());
}

} // namespace

TEST(GuideEdits, RenamingToATakenNameIsRefusedNamingTheRenamedInstance)
{
    model::GuideDocument doc = test::loadSample("biped");
    const model::GuideDocument original = doc;
    edit::History history(doc);
    const model::InstanceId spine = doc.instanceNamed("spine")->id;

    const Diagnostic refused = onlyError(edit::renameInstance(history, spine, "neck"));
    EXPECT_EQ(refused.message, "an instance named 'neck' already exists");
    EXPECT_EQ(refused.subject, Subject::ofInstance(spine));
    EXPECT_EQ(refused.format(), "error: an instance named 'neck' already exists");
    EXPECT_EQ(onlyError(edit::renameInstance(history, spine, "2spine")).subject, Subject::ofInstance(spine));
    EXPECT_EQ(history.size(), 0u);
    EXPECT_EQ(doc, original);
}

TEST(GuideEdits, AnEditOfAMissingInstanceNamesThatInstance)
{
    model::GuideDocument doc = test::loadSample("biped");
    const model::GuideDocument original = doc;
    edit::History history(doc);
    const model::InstanceId missing = 999;
    ASSERT_EQ(doc.instance(missing), nullptr);
    model::ShapeEdit shape;
    shape.transform.scale = Vec3(2.0);
    const std::vector<std::pair<const char*, Status>> refusals{
        {"rename", edit::renameInstance(history, missing, "ghost")},
        {"remove", edit::removeInstance(history, missing)},
        {"option", edit::setOption(history, missing, "do_skin", false, true)},
        {"name override", edit::setNameOverride(history, missing, "ik", "hand", "ik")},
        {"shape", edit::setShapeEdit(history, missing, "ctrls.ik", shape)},
        {"duplicate", edit::duplicateInstances(history, {missing})},
        {"re-hang", edit::reparentInstance(history, missing, model::kNoId)},
    };
    for (const auto& [what, status] : refusals) {
        const Diagnostic refused = onlyError(status);
        EXPECT_EQ(refused.message, "no instance with id 999") << what;
        EXPECT_EQ(refused.subject, Subject::ofInstance(missing)) << what;
    }
    EXPECT_EQ(history.size(), 0u);
    EXPECT_EQ(doc, original);
}

TEST(GuideEdits, AJointEditRefusalNamesTheGuideJoint)
{
    model::GuideDocument doc = test::loadSample("biped");
    edit::History history(doc);
    const model::JointId missing = 99999;
    ASSERT_EQ(doc.joint(missing), nullptr);
    Transform moved;
    moved.translate = Vec3(0.1, 0.0, 0.0);
    EXPECT_EQ(onlyError(edit::setJointTransform(history, missing, moved)).subject, Subject::ofJoint(model::kNoId, missing));
    EXPECT_EQ(onlyError(edit::setJointTransforms(history, {{missing, moved}}, "Move")).subject,
              Subject::ofJoint(model::kNoId, missing));
    const model::InstanceId arm = doc.instanceNamed("arm")->id;
    EXPECT_EQ(onlyError(edit::reparentInstance(history, arm, missing)).subject, Subject::ofJoint(model::kNoId, missing));

    // Adding an instance whose joint id another instance owns names that joint.
    model::TemplateInstance copy = *doc.instanceNamed("neck");
    copy.id = doc.nextInstanceId();
    copy.name = "neck2";
    const Diagnostic taken = onlyError(edit::addInstance(history, copy));
    EXPECT_EQ(taken.message, "joint id " + std::to_string(copy.joints.front().id) + " is not free");
    EXPECT_EQ(taken.subject, Subject::ofJoint(doc.instanceNamed("neck")->id, copy.joints.front().id));
    EXPECT_EQ(history.size(), 0u);
}

TEST(GuideEdits, AShapeEditWithABadOffsetNamesTheShape)
{
    model::GuideDocument doc = test::loadSample("biped");
    edit::History history(doc);
    const model::InstanceId arm = doc.instanceNamed("arm")->id;
    model::ShapeEdit bad;
    bad.cvs[{0, 1}] = Vec3(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
    const Diagnostic refused = onlyError(edit::setShapeEdit(history, arm, "ctrls.ik", bad));
    EXPECT_EQ(refused.message, "a CV offset needs indices from 0 and a finite offset");
    EXPECT_EQ(refused.subject, Subject::ofShape({arm, {}, "ctrls.ik"}));
    EXPECT_EQ(history.size(), 0u);
}

TEST(GuideEdits, AnEditThatChangesNothingSucceedsWithoutAStepOrMessage)
{
    model::GuideDocument doc = test::loadSample("biped");
    edit::History history(doc);
    const model::InstanceId spine = doc.instanceNamed("spine")->id;
    const Status same = edit::renameInstance(history, spine, "spine");
    EXPECT_TRUE(same.ok());
    EXPECT_FALSE(same.failed());
    EXPECT_TRUE(same.diagnostics().empty());
    EXPECT_EQ(history.size(), 0u);
}

TEST(Session, ForwardsAnEditsRefusalUnchanged)
{
    session::Session s(templatesForSession());
    s.replaceDocument(test::loadSample("biped"));
    const model::InstanceId spine = s.document().instanceNamed("spine")->id;
    model::GuideDocument copy = s.document();
    edit::History direct(copy);
    const Status fromEdit = edit::renameInstance(direct, spine, "neck");
    const Status fromSession = s.renameInstance(spine, "neck");

    const Diagnostic expected = onlyError(fromEdit);
    const Diagnostic forwarded = onlyError(fromSession);
    EXPECT_EQ(forwarded.format(), expected.format());
    EXPECT_EQ(forwarded.subject, expected.subject);
    EXPECT_EQ(forwarded.subject, Subject::ofInstance(spine));
    EXPECT_EQ(s.history().size(), 0u);

    const Diagnostic missing = onlyError(s.reparentInstance(999, model::kNoId));
    EXPECT_EQ(missing.message, "no instance with id 999");
    EXPECT_EQ(missing.subject, Subject::ofInstance(999));
}

TEST(Session, ItsOwnRefusalsNameTheInstanceOrTheRigNode)
{
    session::Session s(templatesForSession());
    s.replaceDocument(test::loadSample("biped"));
    const model::InstanceId arm = s.document().instanceNamed("arm")->id;
    const Diagnostic unknown = onlyError(s.setOption(arm, "no_such_option", Value(true)));
    EXPECT_NE(unknown.message.find("has no option 'no_such_option'"), std::string::npos) << unknown.message;
    EXPECT_EQ(unknown.subject, Subject::ofInstance(arm));
    EXPECT_EQ(onlyError(s.setNameOverride(999, "ik", "hand")).subject, Subject::ofInstance(999));

    s.build();
    const model::RigNodeIndex pole = *s.rig()->findPath("arm.L::ctrls.pole");
    const auto rx = s.program()->channels().find(pole, "rx");
    ASSERT_TRUE(rx);
    ASSERT_TRUE(s.program()->channels()[*rx].locked);
    const Diagnostic locked = onlyError(s.setChannel(*rx, 10.0, false));
    EXPECT_NE(locked.message.find("is locked"), std::string::npos) << locked.message;
    EXPECT_EQ(locked.subject, Subject::ofNode(s.rig()->nodes[pole].key));

    // A limb match on a control that is on no FK/IK limb: the pose tool's refusal names it.
    s.setMode(session::Mode::Rig);
    const model::RigNodeIndex head = *s.rig()->findPath("neck::ctrls.head");
    s.selectControllers({head}, false);
    const std::size_t steps = s.history().size();
    const Diagnostic notALimb = onlyError(s.applyPoseTool(session::PoseTool::IkToFk));
    EXPECT_EQ(notALimb.message, "'neck::ctrls.head' is not on an FK/IK limb to match");
    EXPECT_EQ(notALimb.subject, Subject::ofNode(s.rig()->nodes[head].key));
    EXPECT_EQ(s.history().size(), steps);
}

TEST(ShapeCvEdit, ABeginOnCvsOfSeveralControllersNamesTheShape)
{
    session::Session s(templatesForSession());
    s.replaceDocument(test::loadSample("biped"));
    s.build();
    const model::RigNodeIndex ik = *s.rig()->findPath("arm.L::ctrls.ik");
    const model::RigNodeIndex pole = *s.rig()->findPath("arm.L::ctrls.pole");
    const auto drag = edit::CvDrag::begin(s.document(), *s.rig(), {{ik, 0, 0}, {pole, 0, 0}});
    ASSERT_FALSE(drag);
    ASSERT_EQ(drag.diagnostics().size(), 1u);
    EXPECT_EQ(drag.diagnostics().front().subject, Subject::ofShape(s.rig()->nodes[ik].key));
}
