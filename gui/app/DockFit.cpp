#include "gui/app/DockFit.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QScrollArea>
#include <QScrollBar>
#include <QTimer>

#include <algorithm>

namespace hsmu::gui {

void fitDockToForm(QMainWindow& window, QDockWidget& dock, QScrollArea& scroll) {
    const auto fit = [&window, &dock, &scroll] { // once its layout is polished
        const QWidget& form = *scroll.widget();
        const int wanted = std::max(form.sizeHint().width(), form.minimumSizeHint().width()) +
                           scroll.verticalScrollBar()->sizeHint().width() +
                           2 * scroll.frameWidth() + 8;
        window.resizeDocks({&dock}, {std::min(wanted, window.width() / 2)}, Qt::Horizontal);
        scroll.horizontalScrollBar()->setValue(0);
    };
    QObject::connect(&dock, &QDockWidget::visibilityChanged, &window, [&, fit](bool visible) {
        if (visible && !dock.isFloating() && scroll.widget())
            QTimer::singleShot(0, &window, fit);
    });
}

} // namespace hsmu::gui
