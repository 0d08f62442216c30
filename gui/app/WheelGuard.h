#pragma once
// WheelGuard: the mouse wheel edits a value only in the field the operator is working in.
// One application-wide event filter (install(), idempotent) covers every window, dialog and
// widget created later (a table's cell editor, the pre-flight dialog):
//   - every spin box, combo box and slider gets Qt::StrongFocus when it is polished (the
//     wheel never gives it the focus);
//   - a combo box never changes with the wheel: a choice (the controller, the integrator, the
//     policy) is made by a click or the keyboard; the wheel over it scrolls the panel;
//   - a spin box or slider takes the wheel only when it has the keyboard focus and no
//     scrolling is under way (a wheel event that scrolled something else less than
//     kScrollGestureMs ago): a focused field that passes under the pointer while the
//     operator scrolls the panel keeps its value;
// an event the guard refuses is ignored and so passes on to the parent (the scroll area
// scrolls instead). Thread rules: GUI thread only.

#include <QElapsedTimer>
#include <QObject>

class QWidget;

namespace hsmu::gui {

class WheelGuard : public QObject {
    Q_OBJECT
public:
    static constexpr int kScrollGestureMs = 600;
    /// Guard every QAbstractSpinBox, QComboBox and QAbstractSlider of the application (the
    /// existing ones and every one created later). The guard is a child of the application.
    static void install();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    explicit WheelGuard(QObject* parent) : QObject(parent) {}
    QElapsedTimer m_scrolled; ///< since a wheel event last went to something else
};

} // namespace hsmu::gui
