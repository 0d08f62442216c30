#include "gui/app/AlarmPanel.h"

#include "gui/app/AlarmList.h"

#include <QBoxLayout>
#include <QEvent>
#include <QHeaderView>
#include <QPushButton>

namespace hsmu::gui {

AlarmPanel::AlarmPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QBoxLayout(QBoxLayout::LeftToRight, this);
    layout->setContentsMargins(2, 2, 2, 2);
    m_list = new AlarmList(this);
    m_ackSelected = new QPushButton(this);
    m_ackAll = new QPushButton(this);
    layout->addWidget(m_list, 1);
    auto* buttons = new QVBoxLayout;
    buttons->addWidget(m_ackSelected);
    buttons->addWidget(m_ackAll);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    m_list->setMinimumHeight(m_list->header()->sizeHint().height() +
                             5 * (m_list->fontMetrics().height() + 4));
    connect(m_ackSelected, &QPushButton::clicked, m_list, &AlarmList::acknowledgeSelected);
    connect(m_ackAll, &QPushButton::clicked, m_list, &AlarmList::acknowledgeAll);
    retranslateUi();
}

void AlarmPanel::retranslateUi() {
    m_ackSelected->setText(tr("Acknowledge selected"));
    m_ackAll->setText(tr("Acknowledge all"));
    const QString help = tr("Critical alarms stay red until acknowledged (double-click or "
                            "the buttons).");
    m_ackSelected->setToolTip(help);
    m_ackAll->setToolTip(help);
    m_list->setToolTip(help);
}

void AlarmPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

} // namespace hsmu::gui
