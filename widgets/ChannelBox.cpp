#include "ChannelBox.h"

#include "LimitDialog.h"
#include "WheelGuard.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QVBoxLayout>

#include <cmath>

namespace rs::widgets {

namespace {

constexpr int kSliderSteps = 1000;

int sliderPosition(const eval::Channel& c, double value)
{
    return c.max > c.min ? int(std::lround((value - c.min) / (c.max - c.min) * kSliderSteps)) : 0;
}

} // namespace

ChannelBox::ChannelBox(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    m_title = new QLabel(tr("No controller selected"), this);
    m_title->setObjectName("channelBoxTitle");
    layout->addWidget(m_title);
    m_rows = new QWidget(this);
    m_grid = new QGridLayout(m_rows);
    m_grid->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_rows);
    m_match = new QCheckBox(tr("Match on switch"), this);
    m_match->setObjectName("matchSpaces");
    m_match->setToolTip(tr("Switching a space or the rotate order keeps the control where it is instead of jumping"));
    m_match->setChecked(true);
    layout->addWidget(m_match);
    layout->addStretch(1);
    createActions();
}

void ChannelBox::createActions()
{
    auto add = [this](const char* name, const QString& text, const QString& tip, auto slot) {
        auto* a = new QAction(text, this);
        a->setObjectName(name);
        a->setToolTip(tip);
        connect(a, &QAction::triggered, this, slot);
        addAction(a);
        return a;
    };
    using A = ChannelAction;
    add("channelSetDefault", tr("Set as Default"), tr("The selected channels' current values become what Reset returns to (and export writes as rest)"),
        [this] { emitAction(A::SetDefault); });
    add("channelResetDefault", tr("Reset to Default"), tr("The selected channels go back to their defaults"),
        [this] { emitAction(A::ResetDefault); });
    add("channelLock", tr("Lock"), tr("Lock the selected channels"), [this] { emitAction(A::Lock); });
    add("channelUnlock", tr("Unlock"), tr("Unlock the selected channels"), [this] { emitAction(A::Unlock); });
    add("channelKeyable", tr("Make Keyable"), tr("Animators key the selected channels"), [this] { emitAction(A::Keyable); });
    add("channelNonKeyable", tr("Make Non-keyable"), tr("The selected channels are shown and set, never keyed"),
        [this] { emitAction(A::NonKeyable); });
    add("channelLimit", tr("Limit..."), tr("A minimum and maximum for the selected channels"), [this] { openLimitDialog(); });
    add("channelRemoveLimit", tr("Remove Limit"), tr("The selected channels take any value"), [this] { emitAction(A::RemoveLimit); });
    auto* separator = new QAction(this);
    separator->setSeparator(true);
    addAction(separator);
}

QAction* ChannelBox::channelAction(const QString& objectName) const
{
    for (QAction* a : actions())
        if (a->objectName() == objectName)
            return a;
    return nullptr;
}

void ChannelBox::emitAction(ChannelAction action)
{
    if (!m_selected.isEmpty())
        emit channelActionRequested(action, selectedChannels());
}

QStringList ChannelBox::selectedChannels() const
{
    QStringList names;
    for (const auto& [index, label] : m_labels)
        if (m_selected.contains(label->text()))
            names << label->text();
    return names.isEmpty() ? m_selected : names;
}

void ChannelBox::setSelectedChannels(const QStringList& names)
{
    m_selected = names;
    m_anchor = names.isEmpty() ? QString() : names.back();
    for (const auto& [index, label] : m_labels) {
        label->setProperty("selected", m_selected.contains(label->text()));
        label->style()->unpolish(label);
        label->style()->polish(label);
    }
}

QLabel* ChannelBox::labelFor(int channel) const
{
    for (const auto& [index, label] : m_labels)
        if (index == channel)
            return label;
    return nullptr;
}

void ChannelBox::openLimitDialog()
{
    const QStringList names = selectedChannels();
    if (names.isEmpty() || !m_layout)
        return;
    // Start from the first selected channel's limits, else a range around its kind's usual values.
    double min = -1.0, max = 1.0;
    for (const auto& [index, label] : m_labels)
        if (label->text() == names.front()) {
            const eval::Channel& c = (*m_layout)[index];
            if (c.limited) { min = c.min; max = c.max; }
            else if (c.transform >= 3 && c.transform < 6) { min = -90.0; max = 90.0; }
            else if (c.transform >= 6 && c.transform < 9) { min = 0.01; max = 2.0; }
        }
    auto* dialog = new LimitDialog(names.join(", "), min, max, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog, names] {
        emit limitRequested(names, dialog->minimum(), dialog->maximum());
    });
    dialog->open();
}

bool ChannelBox::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::MouseButtonPress)
        if (auto* label = qobject_cast<QLabel*>(watched); label && label->property("channelName").isValid()) {
            auto* mouse = static_cast<QMouseEvent*>(event);
            clickLabel(label->text(), mouse->modifiers(), mouse->button() == Qt::RightButton);
            return mouse->button() != Qt::RightButton; // the right button goes on to the context menu
        }
    return QWidget::eventFilter(watched, event);
}

void ChannelBox::clickLabel(const QString& name, Qt::KeyboardModifiers modifiers, bool rightButton)
{
    if (rightButton) {
        if (!m_selected.contains(name))
            setSelectedChannels({name});
        return;
    }
    if (modifiers & Qt::ShiftModifier && !m_anchor.isEmpty()) {
        QStringList rows;
        for (const auto& [index, label] : m_labels)
            rows << label->text();
        const int a = int(rows.indexOf(m_anchor)), b = int(rows.indexOf(name));
        if (a >= 0 && b >= 0) {
            QStringList range = rows.mid(std::min(a, b), std::abs(a - b) + 1);
            const QString anchor = m_anchor;
            setSelectedChannels(range);
            m_anchor = anchor;
            return;
        }
    }
    if (modifiers & Qt::ControlModifier) {
        QStringList names = m_selected;
        if (!names.removeAll(name))
            names << name;
        setSelectedChannels(names);
        return;
    }
    setSelectedChannels({name});
}

void ChannelBox::decorate(const model::Override* record)
{
    for (const auto& [index, label] : m_labels) {
        const eval::Channel& c = (*m_layout)[index];
        const std::string name = c.name;
        const bool overridden = record && record->defaults.count(name);
        label->setProperty("locked", c.locked);
        label->setProperty("keyable", c.keyable);
        label->setProperty("defaultOverridden", overridden);
        label->setProperty("selected", m_selected.contains(label->text()));
        QStringList tip;
        if (c.locked) tip << tr("Locked");
        if (!c.keyable) tip << tr("Not keyable");
        if (overridden) tip << tr("Default %1 (set as default; Reset to Default returns here)").arg(record->defaults.at(name));
        else if (c.transform != eval::kRotateOrderChannel) tip << tr("Default %1").arg(c.defaultValue);
        if (c.limited) tip << tr("Limits %1 to %2").arg(c.min).arg(c.max);
        label->setToolTip(tip.join("\n"));
        label->style()->unpolish(label);
        label->style()->polish(label);
    }
}

void ChannelBox::invalidate()
{
    m_layout = nullptr;
    m_node = model::kNoNode;
}

bool ChannelBox::matchesSpaces() const { return m_match->isChecked(); }

QWidget* ChannelBox::editorFor(int channel) const
{
    for (const auto& [index, editor] : m_editors)
        if (index == channel)
            return editor;
    return nullptr;
}

void ChannelBox::showNode(const eval::ChannelLayout* layout, model::RigNodeIndex node, const QString& title, const eval::Pose* pose,
                          const model::Override* record)
{
    if (!layout || node >= layout->nodeCount() || !pose) {
        m_layout = nullptr;
        m_node = model::kNoNode;
        m_title->setText(tr("No controller selected"));
        rebuild(eval::ChannelLayout{}, model::kNoNode);
        return;
    }
    if (layout != m_layout || node != m_node) {
        m_layout = layout;
        m_node = node;
        rebuild(*layout, node);
    }
    m_title->setText(title);
    decorate(record);
    updateValues(*pose);
}

void ChannelBox::rebuild(const eval::ChannelLayout& layout, model::RigNodeIndex node)
{
    m_editors.clear();
    m_labels.clear();
    while (QLayoutItem* item = m_grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    if (node == model::kNoNode)
        return;
    const int first = layout.firstOf(node);
    int row = -1;
    for (int i = first; i < first + layout.countOf(node); ++i) {
        const eval::Channel& c = layout[i];
        if (c.hidden)
            continue; // cleanup locked and hid it: not the animator's
        ++row;
        auto* label = new QLabel(QString::fromStdString(c.name), m_rows);
        label->setObjectName(QString::fromStdString("channelLabel_" + c.name));
        label->setProperty("channelName", QString::fromStdString(c.name));
        label->setCursor(Qt::PointingHandCursor);
        label->installEventFilter(this);
        m_grid->addWidget(label, row, 0);
        m_labels.push_back({i, label});
        if (c.isEnum()) {
            auto* combo = new QComboBox(m_rows);
            for (const auto& text : *c.labels)
                combo->addItem(QString::fromStdString(text));
            combo->setEnabled(!c.locked);
            connect(combo, &QComboBox::activated, this, [this, i](int index) {
                if (!m_updating) emit channelEdited(i, double(index), m_match->isChecked());
                emit editingDone();
            });
            m_grid->addWidget(combo, row, 1, 1, 2);
            m_editors.push_back({i, combo});
            continue;
        }
        auto* spin = new QDoubleSpinBox(m_rows);
        spin->setDecimals(c.transform >= 3 && c.transform < 6 ? 2 : 3);
        spin->setRange(c.limited ? c.min : -1e6, c.limited ? c.max : 1e6);
        spin->setSingleStep(c.transform >= 3 && c.transform < 6 ? 5.0 : c.transform >= 0 ? 0.01 : (c.max - c.min) / 20.0);
        spin->setKeyboardTracking(false);
        spin->setEnabled(!c.locked);
        spin->setToolTip(c.locked ? tr("Locked") : QString());
        if (c.locked)
            spin->setStyleSheet("QDoubleSpinBox { background: #4a5563; color: #b8c0cc; }");
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, i](double value) {
            if (!m_updating) emit channelEdited(i, value, m_match->isChecked());
        });
        connect(spin, &QDoubleSpinBox::editingFinished, this, [this, spin] {
            if (spin->hasFocus()) // Enter; focus moving elsewhere also finishes an edit
                emit editingDone();
        });
        m_grid->addWidget(spin, row, 1);
        m_editors.push_back({i, spin});
        if (c.transform < 0 && c.limited && !c.locked) {
            auto* slider = new QSlider(Qt::Horizontal, m_rows);
            slider->setRange(0, kSliderSteps);
            connect(slider, &QSlider::sliderMoved, this, [spin, c](int position) {
                QSignalBlocker block(spin);
                spin->setValue(c.min + (c.max - c.min) * position / kSliderSteps);
            });
            connect(slider, &QSlider::sliderReleased, this, [this, i, spin] {
                if (!m_updating) emit channelEdited(i, spin->value(), m_match->isChecked());
                emit editingDone();
            });
            connect(spin, &QDoubleSpinBox::valueChanged, slider, [slider, c](double value) {
                QSignalBlocker block(slider);
                slider->setValue(sliderPosition(c, value));
            });
            m_grid->addWidget(slider, row, 2);
        }
    }
    guardWheel(m_rows);
    // How a name shows its channel's state (decorate sets the properties).
    m_rows->setStyleSheet("QLabel { padding: 1px 4px; }"
                          "QLabel[locked=\"true\"] { background: #4a5563; color: #b8c0cc; }"
                          "QLabel[keyable=\"false\"] { font-style: italic; color: #8a8a8a; }"
                          "QLabel[defaultOverridden=\"true\"] { font-weight: bold; color: #2aa198; }"
                          "QLabel[selected=\"true\"] { background: palette(highlight); color: palette(highlighted-text); }");
}

void ChannelBox::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Escape) {
        emit editingDone();
        return;
    }
    QWidget::keyPressEvent(event);
}

void ChannelBox::updateValues(const eval::Pose& pose)
{
    m_updating = true;
    for (const auto& [index, editor] : m_editors) {
        if (index < 0 || std::size_t(index) >= pose.size())
            continue;
        if (auto* combo = qobject_cast<QComboBox*>(editor))
            combo->setCurrentIndex(int(std::lround(pose[index])));
        else if (auto* spin = qobject_cast<QDoubleSpinBox*>(editor))
            spin->setValue(pose[index]);
    }
    m_updating = false;
}

} // namespace rs::widgets
