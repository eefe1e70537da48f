// MainWindow's transform panel: the current guide joint's world and local
// transforms shown, and each typed value turned into one undoable session edit
// (Session::moveGuideJoints: the other selected joints move with it).
#include "MainWindow.h"

#include "TransformPanel.h"
#include "edit/GuideMove.h"

namespace rs::app {

namespace {

Mat4 rotationOf(const Vec3& degrees) { return Transform{Vec3(0.0), degrees, Vec3(1.0)}.matrix(); }

// The lead joint's new world matrix for what the panel asked.
Mat4 leadWorldFor(const model::GuideDocument& document, model::JointId joint, bool world, const Transform& value,
                  bool relative)
{
    const Mat4 current = document.jointWorldMatrix(joint);
    const Mat4 parent = document.parentWorldMatrix(joint);
    const Transform local = document.joint(joint)->local;
    if (!relative) {
        if (!world)
            return parent * Transform{value.translate, value.rotateDegrees, local.scale}.matrix();
        const Transform now = edit::localTransformOf(current);
        return Transform{value.translate, value.rotateDegrees, now.scale}.matrix();
    }
    const Mat4 turn = rotationOf(value.rotateDegrees);
    if (world) { // along the world axes; turned about them at the joint
        const Vec3 pivot = translationOf(current);
        return translationMatrix(value.translate) * translationMatrix(pivot) * turn * translationMatrix(-pivot) * current;
    }
    // Along the parent's axes; turned about the joint's own axes.
    Mat4 moved = local.matrix() * turn;
    moved[3] += Vec4(value.translate, 0.0);
    return parent * moved;
}

} // namespace

void MainWindow::connectTransformPanel()
{
    connect(m_transformPanel, &widgets::TransformPanel::transformEdited, this,
            [this](int space, const Transform& value, bool relative) {
                const model::JointId joint = m_session.gizmoJoint();
                const model::TemplateInstance* owner = m_session.document().ownerOf(joint);
                if (!owner || m_session.mode() != EditorMode::Guide) {
                    refreshTransformPanel();
                    return;
                }
                const bool world = space == int(widgets::TransformPanel::Space::World);
                const std::size_t count = std::max<std::size_t>(1, m_session.selection().joints.size());
                const QString verb = relative ? (value.translate != Vec3(0.0) ? tr("Move") : tr("Rotate")) : tr("Set transform of");
                const QString what = count > 1 ? tr("%1 %2 guide joints").arg(verb).arg(count)
                                               : tr("%1 guide joint of %2").arg(verb, QString::fromStdString(owner->name));
                const Status moved = m_session.moveGuideJoints(
                    joint, leadWorldFor(m_session.document(), joint, world, value, relative), what.toStdString());
                logStatus(moved);
                if (moved.failed())
                    refreshTransformPanel(); // show the stored values again
            });
}

void MainWindow::refreshTransformPanel()
{
    const model::JointId joint = m_session.mode() == EditorMode::Guide ? m_session.gizmoJoint() : model::kNoId;
    const model::TemplateInstance* owner = m_session.document().ownerOf(joint);
    if (!owner) {
        m_transformPanel->clear(m_session.mode() == EditorMode::Rig
                                    ? tr("Guide joints are typed in Guide mode (F3); in Rig mode the Channel box poses controllers")
                                    : QString());
        return;
    }
    const model::GuideJoint* j = owner->joint(joint);
    const auto index = std::size_t(j - owner->joints.data());
    const std::size_t count = m_session.selection().joints.size();
    QString title = tr("<b>%1</b> joint %2%3").arg(QString::fromStdString(owner->name)).arg(index)
                        .arg(j->name.empty() ? QString() : " (" + QString::fromStdString(j->name) + ")");
    if (count > 1)
        title += tr("; %1 joints selected move with it").arg(count);
    m_transformPanel->showJoint(title, edit::localTransformOf(m_session.document().jointWorldMatrix(joint)), j->local);
}

} // namespace rs::app
