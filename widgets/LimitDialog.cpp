#include "LimitDialog.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>

namespace rs::widgets {

LimitDialog::LimitDialog(const QString& channels, double min, double max, QWidget* parent) : QDialog(parent)
{
    setObjectName("limitDialog");
    setWindowTitle(tr("Limit %1").arg(channels));
    auto* form = new QFormLayout(this);
    auto spin = [this](const char* name) {
        auto* s = new QDoubleSpinBox(this);
        s->setObjectName(name);
        s->setRange(-1e6, 1e6);
        s->setDecimals(3);
        return s;
    };
    m_min = spin("limitMin");
    m_max = spin("limitMax");
    form->addRow(tr("Minimum"), m_min);
    form->addRow(tr("Maximum"), m_max);
    m_problem = new QLabel(this);
    m_problem->setStyleSheet("color: #d06040");
    form->addRow(m_problem);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    form->addRow(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_min, &QDoubleSpinBox::valueChanged, this, &LimitDialog::check);
    connect(m_max, &QDoubleSpinBox::valueChanged, this, &LimitDialog::check);
    setRange(min, max);
}

double LimitDialog::minimum() const { return m_min->value(); }
double LimitDialog::maximum() const { return m_max->value(); }

void LimitDialog::setRange(double min, double max)
{
    m_min->setValue(min);
    m_max->setValue(max);
    check();
}

void LimitDialog::check()
{
    const bool ok = m_min->value() <= m_max->value();
    m_problem->setText(ok ? QString() : tr("The minimum is above the maximum"));
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(ok);
}

} // namespace rs::widgets
