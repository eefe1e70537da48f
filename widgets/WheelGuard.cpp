#include "WheelGuard.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QScrollBar>
#include <QWidget>

namespace rs::widgets {

namespace {

class WheelFilter : public QObject {
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        auto* field = qobject_cast<QWidget*>(watched);
        if (event->type() != QEvent::Wheel || !field || field->hasFocus())
            return false;
        // Handed to the parent: Qt passes an ignored wheel event on up to the
        // scroll area, which scrolls the panel.
        event->ignore();
        if (QWidget* parent = field->parentWidget())
            QCoreApplication::sendEvent(parent, event);
        return true;
    }
};

WheelFilter* filter()
{
    static auto* instance = new WheelFilter(QCoreApplication::instance());
    return instance;
}

} // namespace

void guardWheel(QWidget* root)
{
    auto guard = [](QWidget* field) {
        field->setFocusPolicy(Qt::StrongFocus); // not Qt::WheelFocus
        field->installEventFilter(filter());
    };
    for (auto* w : root->findChildren<QAbstractSpinBox*>()) guard(w);
    for (auto* w : root->findChildren<QComboBox*>()) guard(w);
    for (auto* w : root->findChildren<QAbstractSlider*>())
        if (!qobject_cast<QScrollBar*>(w)) // a scroll area's own bars keep the wheel
            guard(w);
}

} // namespace rs::widgets
