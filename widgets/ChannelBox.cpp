#include "ChannelBox.h"

#include "WheelGuard.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
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

void ChannelBox::showNode(const eval::ChannelLayout* layout, model::RigNodeIndex node, const QString& title, const eval::Pose* pose)
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
    updateValues(*pose);
}

void ChannelBox::rebuild(const eval::ChannelLayout& layout, model::RigNodeIndex node)
{
    m_editors.clear();
    while (QLayoutItem* item = m_grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    if (node == model::kNoNode)
        return;
    const int first = layout.firstOf(node);
    for (int i = first; i < first + layout.countOf(node); ++i) {
        const eval::Channel& c = layout[i];
        const int row = i - first;
        auto* label = new QLabel(QString::fromStdString(c.name), m_rows);
        m_grid->addWidget(label, row, 0);
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
