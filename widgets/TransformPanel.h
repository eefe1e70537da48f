#pragma once
// The transform panel (Guide mode): the current guide joint's translate
// (metres) and rotate (degrees, Euler XYZ as the guide file keeps them), in
// world space or local (its parent's) space, to type.
// - Absolute: entering a field sets that value (the other fields keep theirs).
// - Relative: the fields hold an offset, applied when entered, then back to 0.
//   A world offset moves along / turns about the world axes at the joint; a
//   local one moves along its parent's axes / turns about its own axes.
// The other selected guide joints move with the shown one, as in a gizmo drag.
// It only emits requests; the app makes each one undoable session edit.
#include "base/Math.h"

#include <QWidget>

#include <array>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace rs::widgets {

class TransformPanel : public QWidget {
    Q_OBJECT
public:
    enum class Space { World, Local };

    explicit TransformPanel(QWidget* parent = nullptr);

    // `world` and `local` are the joint's transforms in both spaces; the panel shows the chosen one.
    void showJoint(const QString& title, const Transform& world, const Transform& local);
    // Nothing to type into: the fields are disabled and `why` says what to do
    // (empty: select guide joints).
    void clear(const QString& why = {});
    Space space() const;
    void setSpace(Space space);
    bool isRelative() const;
    void setRelative(bool relative);
    // row 0 translate, 1 rotate; axis 0..2 (tests and tools).
    QDoubleSpinBox* field(int row, int axis) const;

signals:
    // Absolute: the whole translate and rotate to set. Relative: the offset
    // (one field non-zero). `space` is a Space.
    void transformEdited(int space, const rs::Transform& value, bool relative);

private:
    void showValues();
    void fieldEntered(int row, int axis);

    QLabel* m_title = nullptr;
    QComboBox* m_space = nullptr;
    QCheckBox* m_relative = nullptr;
    std::array<std::array<QDoubleSpinBox*, 3>, 2> m_fields{};
    Transform m_world, m_local;
    bool m_hasJoint = false;
    bool m_updating = false;
};

} // namespace rs::widgets
