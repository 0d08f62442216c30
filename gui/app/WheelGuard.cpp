#include "gui/app/WheelGuard.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QEvent>
#include <QScrollBar>
#include <QWidget>

namespace hsmu::gui {

namespace {
bool guarded(const QWidget* w) {
    // Not scroll bars: a scroll area hands its wheel events to them, so guarding them would
    // stop the panel from scrolling under the wheel (the very thing the guard protects).
    return qobject_cast<const QAbstractSpinBox*>(w) || qobject_cast<const QComboBox*>(w) ||
           (qobject_cast<const QAbstractSlider*>(w) && !qobject_cast<const QScrollBar*>(w));
}
} // namespace

void WheelGuard::install(QWidget* root) {
    auto* guard = root->findChild<WheelGuard*>(QString(), Qt::FindDirectChildrenOnly);
    if (!guard)
        guard = new WheelGuard(root);
    QList<QWidget*> widgets = root->findChildren<QWidget*>();
    widgets.prepend(root);
    for (QWidget* w : widgets) {
        if (!guarded(w) || w->property("hsmuWheelGuard").toBool())
            continue;
        w->setFocusPolicy(Qt::StrongFocus);
        w->installEventFilter(guard);
        w->setProperty("hsmuWheelGuard", true);
    }
}

bool WheelGuard::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Wheel) {
        const auto* w = qobject_cast<QWidget*>(watched);
        if (w && !w->hasFocus()) {
            event->ignore(); // not accepted: QApplication passes it on to the parent
            return true;
        }
    }
    return QObject::eventFilter(watched, event);
}

} // namespace hsmu::gui
