#include "gui/app/EndConfirmation.h"

#include <QCoreApplication>
#include <QMessageBox>
#include <QPushButton>

namespace hsmu::gui {

QMessageBox* EndConfirmation::open(QWidget* parent, const QString& objectName,
                                   const QString& question, const QString& yes,
                                   QAction* emergencyHold,
                                   std::function<void(bool confirmed)> done) {
    auto* box = new QMessageBox(QMessageBox::Warning,
                                QCoreApplication::translate("hsmu::gui::MainWindow",
                                                            "A test is running"),
                                question, QMessageBox::NoButton, parent);
    box->setObjectName(objectName);
    box->setAttribute(Qt::WA_DeleteOnClose);
    if (emergencyHold)
        box->addAction(emergencyHold);
    QPushButton* end = box->addButton(yes, QMessageBox::AcceptRole);
    end->setObjectName(QStringLiteral("confirmEnd"));
    QPushButton* keep = box->addButton(
        QCoreApplication::translate("hsmu::gui::MainWindow", "Continue the test"),
        QMessageBox::RejectRole);
    keep->setObjectName(QStringLiteral("continueTest"));
    box->setDefaultButton(keep); // Enter does not end a test
    QObject::connect(box, &QMessageBox::finished, box, [box, end, done = std::move(done)](int) {
        done(box->clickedButton() == end);
    });
    box->open();
    return box;
}

} // namespace hsmu::gui
