#include "gui/app/WheelGuard.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QScrollBar>
#include <QWidget>

namespace hsmu::gui {

namespace {
bool guarded(const QObject* w) {
    // Not scroll bars: a scroll area hands its wheel events to them, so guarding them would
    // stop the panel from scrolling under the wheel (the very thing the guard protects).
    return qobject_cast<const QAbstractSpinBox*>(w) || qobject_cast<const QComboBox*>(w) ||
           (qobject_cast<const QAbstractSlider*>(w) && !qobject_cast<const QScrollBar*>(w));
}

// The guarded widget w is, or is part of (a spin box's line edit), or nullptr.
const QWidget* guardedOwner(const QWidget* w) {
    for (; w; w = w->isWindow() ? nullptr : w->parentWidget())
        if (guarded(w))
            return w;
    return nullptr;
}

void strongFocus(QWidget* w) {
    if (w->focusPolicy() & Qt::WheelFocus)
        w->setFocusPolicy(Qt::StrongFocus);
}
} // namespace

void WheelGuard::install() {
    QCoreApplication* app = QCoreApplication::instance();
    if (!app || app->findChild<WheelGuard*>(QString(), Qt::FindDirectChildrenOnly))
        return;
    auto* guard = new WheelGuard(app);
    app->installEventFilter(guard);
    for (QWidget* w : QApplication::allWidgets())
        if (guarded(w))
            strongFocus(w);
}

bool WheelGuard::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Polish && guarded(watched)) {
        strongFocus(static_cast<QWidget*>(watched));
    } else if (event->type() == QEvent::Wheel && watched->isWidgetType()) {
        const auto* w = static_cast<const QWidget*>(watched);
        const QWidget* owner = guardedOwner(w);
        if (!owner) { // something else takes the wheel: a panel, a list, a plot scrolls
            m_scrolled.start();
            return false;
        }
        if (owner != w)
            return false; // the field's inner part: the event goes on to the field itself
        const bool scrolling = m_scrolled.isValid() && m_scrolled.elapsed() < kScrollGestureMs;
        if (qobject_cast<const QComboBox*>(w) || !w->hasFocus() || scrolling) {
            m_scrolled.start(); // the wheel goes on scrolling the panel
            event->ignore();    // not accepted: QApplication passes it on to the parent
            return true;
        }
    }
    return QObject::eventFilter(watched, event);
}

} // namespace hsmu::gui
