#pragma once
// WheelGuard: the mouse wheel edits a value only in the field the operator is working in.
// install(root) gives every spin box, combo box and slider under root Qt::StrongFocus (no
// focus by the wheel) and filters its wheel events: unless the widget has the keyboard focus
// the event is ignored and so passes on to the parent (the scroll area scrolls instead).
// Widgets added to root later need another install(). Thread rules: GUI thread only.

#include <QObject>

class QWidget;

namespace hsmu::gui {

class WheelGuard : public QObject {
    Q_OBJECT
public:
    /// Guard every QAbstractSpinBox, QComboBox and QAbstractSlider under root (root included).
    /// One guard per root, parented to it; installing again only adds the new widgets.
    static void install(QWidget* root);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    explicit WheelGuard(QObject* parent) : QObject(parent) {}
};

} // namespace hsmu::gui
