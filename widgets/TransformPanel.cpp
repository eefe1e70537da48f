#include "TransformPanel.h"

#include "WheelGuard.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace rs::widgets {

namespace {
constexpr double kLimit = 1e5;
}

TransformPanel::TransformPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName("transformPanel");
    auto* layout = new QVBoxLayout(this);
    m_title = new QLabel(this);
    m_title->setObjectName("transformTitle");
    m_title->setWordWrap(true);
    layout->addWidget(m_title);

    auto* options = new QHBoxLayout;
    m_space = new QComboBox(this);
    m_space->setObjectName("transformSpace");
    m_space->addItem(tr("World"));
    m_space->addItem(tr("Local"));
    m_space->setToolTip(tr("World: the scene's axes. Local: the parent joint's axes (the values the guide file keeps)"));
    m_relative = new QCheckBox(tr("Relative"), this);
    m_relative->setObjectName("transformRelative");
    m_relative->setToolTip(tr("Type an offset: it moves or turns the selected joints by that much, then the field goes back to 0"));
    options->addWidget(m_space);
    options->addWidget(m_relative);
    options->addStretch(1);
    layout->addLayout(options);

    auto* grid = new QGridLayout;
    const QString rows[] = {tr("Translate (m)"), tr("Rotate (\u00B0)")};
    const char* axes[] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 3; ++axis)
        grid->addWidget(new QLabel(axes[axis], this), 0, axis + 1, Qt::AlignHCenter);
    for (int row = 0; row < 2; ++row) {
        grid->addWidget(new QLabel(rows[row], this), row + 1, 0);
        for (int axis = 0; axis < 3; ++axis) {
            auto* box = new QDoubleSpinBox(this);
            box->setObjectName(QString("transform:%1%2").arg(row == 0 ? "t" : "r").arg(QChar('x' + axis)));
            box->setDecimals(row == 0 ? 4 : 2);
            box->setRange(-kLimit, kLimit);
            box->setSingleStep(row == 0 ? 0.01 : 5.0);
            box->setKeyboardTracking(false); // one edit per entered value
            // Narrow enough for a dock beside the channel box: the dock's width, not the range's digits, sizes it.
            box->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
            box->setMinimumWidth(56);
            connect(box, &QDoubleSpinBox::valueChanged, this, [this, row, axis] { fieldEntered(row, axis); });
            grid->addWidget(box, row + 1, axis + 1);
            m_fields[std::size_t(row)][std::size_t(axis)] = box;
        }
    }
    layout->addLayout(grid);
    layout->addStretch(1);
    connect(m_space, &QComboBox::currentIndexChanged, this, [this] { showValues(); });
    connect(m_relative, &QCheckBox::toggled, this, [this] { showValues(); });
    guardWheel(this);
    clear();
}

QDoubleSpinBox* TransformPanel::field(int row, int axis) const { return m_fields[std::size_t(row)][std::size_t(axis)]; }
TransformPanel::Space TransformPanel::space() const { return m_space->currentIndex() == 0 ? Space::World : Space::Local; }
void TransformPanel::setSpace(Space space) { m_space->setCurrentIndex(space == Space::World ? 0 : 1); }
bool TransformPanel::isRelative() const { return m_relative->isChecked(); }
void TransformPanel::setRelative(bool relative) { m_relative->setChecked(relative); }

void TransformPanel::showJoint(const QString& title, const Transform& world, const Transform& local)
{
    m_hasJoint = true;
    m_world = world;
    m_local = local;
    m_title->setText(title);
    showValues();
}

void TransformPanel::clear(const QString& why)
{
    m_hasJoint = false;
    m_title->setText(why.isEmpty() ? tr("Select guide joints to type their position and rotation") : why);
    showValues();
}

void TransformPanel::showValues()
{
    const Transform& shown = space() == Space::World ? m_world : m_local;
    m_updating = true;
    for (int row = 0; row < 2; ++row)
        for (int axis = 0; axis < 3; ++axis) {
            QDoubleSpinBox* box = field(row, axis);
            box->setEnabled(m_hasJoint);
            if (!box->hasFocus() || isRelative() || !m_hasJoint) // not under a value being typed
                box->setValue(!m_hasJoint || isRelative() ? 0.0 : (row == 0 ? shown.translate : shown.rotateDegrees)[axis]);
        }
    m_updating = false;
}

void TransformPanel::fieldEntered(int row, int axis)
{
    if (m_updating || !m_hasJoint)
        return;
    const double value = field(row, axis)->value();
    Transform out = space() == Space::World ? m_world : m_local;
    if (isRelative()) {
        if (value == 0.0)
            return;
        out = Transform{Vec3(0.0), Vec3(0.0), Vec3(1.0)};
        (row == 0 ? out.translate : out.rotateDegrees)[axis] = value;
        m_updating = true;
        field(row, axis)->setValue(0.0); // an offset is applied once
        m_updating = false;
    } else {
        (row == 0 ? out.translate : out.rotateDegrees)[axis] = value;
    }
    emit transformEdited(int(space()), out, isRelative());
}

} // namespace rs::widgets
