#pragma once
// The channel box's Limit... dialog: a minimum and a maximum for the selected
// channels; OK is enabled only while min <= max.
#include <QDialog>

class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;

namespace rs::widgets {

class LimitDialog : public QDialog {
    Q_OBJECT
public:
    LimitDialog(const QString& channels, double min, double max, QWidget* parent = nullptr);
    double minimum() const;
    double maximum() const;
    void setRange(double min, double max);

private:
    void check();

    QDoubleSpinBox* m_min;
    QDoubleSpinBox* m_max;
    QLabel* m_problem;
    QDialogButtonBox* m_buttons;
};

} // namespace rs::widgets
