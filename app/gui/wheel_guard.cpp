#include "wheel_guard.h"

#include <QAbstractScrollArea>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QScrollBar>
#include <QWheelEvent>

namespace rung::app {

namespace {

class WheelGuard final : public QObject {
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override {
        if (event->type() != QEvent::Wheel)
            return false;
        auto *widget = qobject_cast<QWidget *>(watched);
        if (!widget)
            return false;
        if (auto *spin = qobject_cast<QAbstractSpinBox *>(widget); spin && spin->hasFocus())
            return false; // clicked into: the wheel is the user's way of changing it
        // An open combo box's list is a window of its own: it gets its wheel directly.
        // The scroll area around the field scrolls, as the wheel over a label would.
        for (QWidget *up = widget->parentWidget(); up; up = up->parentWidget())
            if (auto *area = qobject_cast<QAbstractScrollArea *>(up)) {
                QScrollBar *bar = static_cast<QWheelEvent *>(event)->angleDelta().y() != 0
                                      ? area->verticalScrollBar()
                                      : area->horizontalScrollBar();
                QCoreApplication::sendEvent(bar, event);
                return true;
            }
        event->ignore(); // nothing scrolls: the wheel does nothing here
        return true;
    }
};

} // namespace

void guardWheel(QWidget *root) {
    auto *guard = new WheelGuard(root);
    const auto guardOne = [guard](QWidget *field) {
        // Not focused by the wheel either (Qt::WheelFocus): a second turn would change it.
        field->setFocusPolicy(Qt::StrongFocus);
        field->installEventFilter(guard);
    };
    for (QComboBox *combo : root->findChildren<QComboBox *>())
        guardOne(combo);
    for (QAbstractSpinBox *spin : root->findChildren<QAbstractSpinBox *>())
        guardOne(spin);
}

} // namespace rung::app
