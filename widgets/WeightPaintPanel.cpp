#include "WeightPaintPanel.h"

#include "WheelGuard.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QSpinBox>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace rs::widgets {

WeightPaintPanel::WeightPaintPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(makeBrushBox());

    m_joints = new QTreeWidget(this);
    m_joints->setObjectName("paintJoints");
    m_joints->setColumnCount(2);
    m_joints->setHeaderLabels({tr("Joint"), tr("Lock")});
    m_joints->setRootIsDecorated(false);
    m_joints->setMinimumHeight(160);
    // The dark theme draws unchecked boxes almost black on black: outline them, fill a lock.
    m_joints->setStyleSheet("QTreeView::indicator { width: 11px; height: 11px; border: 1px solid #8a8f98; border-radius: 2px; }"
                            "QTreeView::indicator:checked { background: #e0a030; border-color: #f0c060; }");
    m_joints->header()->setStretchLastSection(false);
    m_joints->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_joints->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_joints->setToolTip(tr("Click a joint to show and paint its weights; a locked joint's weights stay as they are"));
    layout->addWidget(m_joints, 1);
    connect(m_joints, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (!m_updating && item)
            emit jointChosen(m_joints->indexOfTopLevelItem(item));
    });
    connect(m_joints, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        if (!m_updating && column == 1)
            emit jointLockChanged(m_joints->indexOfTopLevelItem(item), item->checkState(1) == Qt::Checked);
    });

    layout->addWidget(makeOperationsBox());
    guardWheel(this);
}

QWidget* WeightPaintPanel::makeBrushBox()
{
    auto* box = new QGroupBox(tr("Brush"), this);
    auto* form = new QFormLayout(box);
    auto* tools = new QHBoxLayout;
    box->setStyleSheet("QToolButton:checked { background: palette(highlight); color: palette(highlighted-text); }");
    m_tools = new QButtonGroup(this);
    const std::pair<QString, QString> toolNames[] = {
        {tr("Add"), tr("Add weight of the chosen joint (Ctrl+drag subtracts, Shift+drag smooths)")},
        {tr("Subtract"), tr("Take weight from the chosen joint; it goes to the other joints")},
        {tr("Replace"), tr("Move the chosen joint's weight towards the strength")},
        {tr("Smooth"), tr("Average the weights with the neighbouring vertices")},
        {tr("Select"), tr("Select vertices: click one, drag a box around those facing the camera (Shift adds)")}};
    int id = 0;
    for (const auto& [text, tip] : toolNames) {
        auto* b = new QToolButton(box);
        b->setObjectName("paintTool:" + text.toLower());
        b->setText(text);
        b->setToolTip(tip);
        b->setCheckable(true);
        b->setChecked(id == 0);
        m_tools->addButton(b, id++);
        tools->addWidget(b);
    }
    connect(m_tools, &QButtonGroup::idClicked, this, [this](int tool) { emit toolChanged(tool); });
    form->addRow(tools);

    m_radius = new QDoubleSpinBox(box);
    m_radius->setObjectName("paintRadius");
    m_radius->setRange(0.001, 10.0);
    m_radius->setDecimals(3);
    m_radius->setSingleStep(0.005);
    m_radius->setSuffix(tr(" m"));
    m_radius->setValue(0.05);
    m_radius->setToolTip(tr("The brush radius in metres ([ and ] in the viewport, or B+drag)"));
    m_strength = new QDoubleSpinBox(box);
    m_strength->setObjectName("paintStrength");
    m_strength->setRange(0.0, 1.0);
    m_strength->setSingleStep(0.05);
    m_strength->setValue(0.5);
    m_strength->setToolTip(tr("How far one dab goes towards its goal at the brush centre (Replace: the weight it sets)"));
    m_falloff = new QComboBox(box);
    m_falloff->setObjectName("paintFalloff");
    m_falloff->addItems({tr("Smooth"), tr("Linear"), tr("Constant")});
    m_falloff->setToolTip(tr("How the brush fades from its centre to its radius"));
    m_reach = new QComboBox(box);
    m_reach->setObjectName("paintReach");
    m_reach->addItems({tr("Surface"), tr("Volume")});
    m_reach->setToolTip(tr("Surface: reach along the mesh from the hit (no bleeding to a leg from the other leg); "
                           "Volume: everything within the radius"));
    form->addRow(tr("Radius"), m_radius);
    form->addRow(tr("Strength"), m_strength);
    form->addRow(tr("Falloff"), m_falloff);
    form->addRow(tr("Reach"), m_reach);
    auto changed = [this] { emit brushChanged(); };
    connect(m_radius, &QDoubleSpinBox::valueChanged, this, changed);
    connect(m_strength, &QDoubleSpinBox::valueChanged, this, changed);
    connect(m_falloff, &QComboBox::currentIndexChanged, this, changed);
    connect(m_reach, &QComboBox::currentIndexChanged, this, changed);
    return box;
}

QAbstractButton* WeightPaintPanel::addButton(QWidget* parent, const QString& name, const QString& text, const QString& tip)
{
    auto* b = new QPushButton(text, parent);
    b->setObjectName(name);
    b->setToolTip(tip);
    return b;
}

QWidget* WeightPaintPanel::makeOperationsBox()
{
    auto* box = new QGroupBox(tr("Selected vertices (all when none)"), this);
    auto* grid = new QGridLayout(box);
    QAbstractButton* smooth = addButton(box, "smooth", tr("Smooth"), tr("Average each vertex's weights with its neighbours'"));
    QAbstractButton* normalise = addButton(box, "normalise", tr("Normalise"), tr("Make each vertex's weights sum to 1"));
    QAbstractButton* prune = addButton(box, "prune", tr("Prune"), tr("Drop influences below the threshold"));
    m_pruneBelow = new QDoubleSpinBox(box);
    m_pruneBelow->setObjectName("pruneThreshold");
    m_pruneBelow->setRange(0.0, 0.5);
    m_pruneBelow->setDecimals(3);
    m_pruneBelow->setSingleStep(0.005);
    m_pruneBelow->setValue(0.01);
    QAbstractButton* limit = addButton(box, "limit", tr("Limit"), tr("Keep each vertex's largest influences only"));
    m_limitCount = new QSpinBox(box);
    m_limitCount->setObjectName("limitCount");
    m_limitCount->setRange(1, 8);
    m_limitCount->setValue(4);
    m_limitCount->setSuffix(tr(" joints"));
    grid->addWidget(smooth, 0, 0);
    grid->addWidget(normalise, 0, 1);
    grid->addWidget(prune, 1, 0);
    grid->addWidget(m_pruneBelow, 1, 1);
    grid->addWidget(limit, 2, 0);
    grid->addWidget(m_limitCount, 2, 1);
    QAbstractButton* mirrorPositive = addButton(box, "mirrorPositive", tr("Mirror +X → −X"),
                                                tr("Copy the +X side's weights onto the −X side, each joint swapped for its twin"));
    QAbstractButton* mirrorNegative = addButton(box, "mirrorNegative", tr("Mirror −X → +X"),
                                                tr("Copy the −X side's weights onto the +X side, each joint swapped for its twin"));
    grid->addWidget(mirrorPositive, 3, 0);
    grid->addWidget(mirrorNegative, 3, 1);
    QAbstractButton* copy = addButton(box, "copy", tr("Copy"), tr("Copy the first selected vertex's weights"));
    QAbstractButton* paste = addButton(box, "paste", tr("Paste"), tr("Paste the copied weights onto every selected vertex"));
    grid->addWidget(copy, 4, 0);
    grid->addWidget(paste, 4, 1);
    QAbstractButton* clear = addButton(box, "clearSelection", tr("Clear Selection"), tr("Deselect every vertex"));
    grid->addWidget(clear, 5, 0, 1, 2);

    auto operation = [this](Operation op, auto amount) { return [this, op, amount] { emit operationRequested(int(op), amount()); }; };
    connect(smooth, &QAbstractButton::clicked, this, operation(Operation::Smooth, [] { return 0.5; }));
    connect(prune, &QAbstractButton::clicked, this, operation(Operation::Prune, [this] { return m_pruneBelow->value(); }));
    connect(normalise, &QAbstractButton::clicked, this, operation(Operation::Normalise, [] { return 0.0; }));
    connect(limit, &QAbstractButton::clicked, this, operation(Operation::Limit, [this] { return double(m_limitCount->value()); }));
    connect(mirrorPositive, &QAbstractButton::clicked, this, [this] { emit mirrorRequested(true); });
    connect(mirrorNegative, &QAbstractButton::clicked, this, [this] { emit mirrorRequested(false); });
    connect(copy, &QAbstractButton::clicked, this, &WeightPaintPanel::copyRequested);
    connect(paste, &QAbstractButton::clicked, this, &WeightPaintPanel::pasteRequested);
    connect(clear, &QAbstractButton::clicked, this, &WeightPaintPanel::clearSelectionRequested);
    return box;
}

WeightPaintPanel::Tool WeightPaintPanel::tool() const { return Tool(std::max(0, m_tools->checkedId())); }

void WeightPaintPanel::setTool(Tool tool)
{
    if (QAbstractButton* b = m_tools->button(int(tool)))
        b->setChecked(true);
}

skin::Brush WeightPaintPanel::brush() const
{
    skin::Brush b;
    const Tool t = tool();
    b.mode = t == Tool::SelectVertices ? skin::BrushMode::Add : skin::BrushMode(int(t));
    b.radius = m_radius->value();
    b.strength = m_strength->value();
    b.falloff = skin::Falloff(m_falloff->currentIndex());
    b.surface = m_reach->currentIndex() == 0;
    return b;
}

void WeightPaintPanel::setRadius(double metres)
{
    const QSignalBlocker block(m_radius);
    m_radius->setValue(metres);
}

void WeightPaintPanel::setStrength(double strength) { m_strength->setValue(strength); }

void WeightPaintPanel::showJoints(const std::vector<JointRow>& joints, int current)
{
    if (joints == m_shownJoints) { // a rebuild that kept the skin joints (a guide drag): the rows stand
        setCurrentJoint(current);
        return;
    }
    m_shownJoints = joints;
    m_updating = true;
    m_joints->clear();
    for (const JointRow& joint : joints) {
        auto* item = new QTreeWidgetItem(m_joints, {joint.name, QString()});
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable);
        item->setCheckState(1, joint.locked ? Qt::Checked : Qt::Unchecked);
    }
    m_updating = false;
    setCurrentJoint(current);
}

void WeightPaintPanel::setCurrentJoint(int bone)
{
    m_updating = true;
    QTreeWidgetItem* item = bone >= 0 ? m_joints->topLevelItem(bone) : nullptr;
    m_joints->setCurrentItem(item);
    if (item)
        m_joints->scrollToItem(item);
    m_updating = false;
}

int WeightPaintPanel::currentJoint() const
{
    QTreeWidgetItem* item = m_joints->currentItem();
    return item ? m_joints->indexOfTopLevelItem(item) : -1;
}

QAbstractButton* WeightPaintPanel::button(const QString& name) const { return findChild<QAbstractButton*>(name); }

} // namespace rs::widgets
