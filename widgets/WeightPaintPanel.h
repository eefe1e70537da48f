#pragma once
// The Paint dock (weight painting): the brush (tool, radius in metres,
// strength 0 to 1, falloff, reach over the surface or through the volume) or
// the select-vertices tool; the skin joints, the painted one current, each
// with a lock; and the weight operations (smooth, prune below a threshold,
// normalise, limit to a count of influences, mirror, copy / paste, clear the
// vertex selection). It only emits requests; the app turns each into one
// undoable session edit and logs its refusal.
#include "skin/WeightTools.h"

#include <QString>
#include <QWidget>

#include <vector>

class QAbstractButton;
class QButtonGroup;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;
class QTreeWidget;

namespace rs::widgets {

class WeightPaintPanel : public QWidget {
    Q_OBJECT
public:
    // The left button's tool: a brush mode, or selecting vertices.
    enum class Tool { Add, Subtract, Replace, Smooth, SelectVertices };
    // Weight operations, in session::Session::WeightOperation's order.
    enum class Operation { Smooth, Prune, Normalise, Limit };
    struct JointRow {
        QString name;
        bool locked = false;
        bool operator==(const JointRow&) const = default;
    };

    explicit WeightPaintPanel(QWidget* parent = nullptr);

    Tool tool() const;
    void setTool(Tool tool);
    // The brush as set (mode, radius, strength, falloff, reach); the caller
    // fills in the joint, centre and vertex. The select tool reads as Add.
    skin::Brush brush() const;
    void setRadius(double metres); // emits nothing (the viewport's [ ] and B keys report here)
    void setStrength(double strength);

    // The skin joints (Session::skinBones() order) and which one is painted (-1 none).
    void showJoints(const std::vector<JointRow>& joints, int current);
    void setCurrentJoint(int bone);
    int currentJoint() const;
    QTreeWidget* jointList() const { return m_joints; }
    // The operation buttons by name (tests): "smooth", "prune", "normalise",
    // "limit", "mirrorPositive", "mirrorNegative", "copy", "paste", "clearSelection".
    QAbstractButton* button(const QString& name) const;
    QDoubleSpinBox* pruneThreshold() const { return m_pruneBelow; }
    QSpinBox* limitCount() const { return m_limitCount; }

signals:
    void toolChanged(int tool); // a Tool
    void brushChanged();        // radius, strength, falloff or reach
    void jointChosen(int bone);
    void jointLockChanged(int bone, bool locked);
    void operationRequested(int operation, double amount); // an Operation; the prune threshold, the limit count
    void mirrorRequested(bool fromPositive);
    void copyRequested();
    void pasteRequested();
    void clearSelectionRequested();

private:
    QWidget* makeBrushBox();
    QWidget* makeOperationsBox();
    QAbstractButton* addButton(QWidget* parent, const QString& name, const QString& text, const QString& tip);

    QButtonGroup* m_tools = nullptr;
    QDoubleSpinBox* m_radius = nullptr;
    QDoubleSpinBox* m_strength = nullptr;
    QComboBox* m_falloff = nullptr;
    QComboBox* m_reach = nullptr;
    QTreeWidget* m_joints = nullptr;
    std::vector<JointRow> m_shownJoints; // what m_joints lists
    QDoubleSpinBox* m_pruneBelow = nullptr;
    QSpinBox* m_limitCount = nullptr;
    bool m_updating = false; // filling the joint list: no requests
};

} // namespace rs::widgets
