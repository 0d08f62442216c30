#include "gui/app/AttentionBanner.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace hsmu::gui {

AttentionBanner::AttentionBanner(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("attentionBanner"));
    // A plain QWidget paints a style sheet's background only with WA_StyledBackground (without
    // it the banner's white text stood on the window's grey).
    setAttribute(Qt::WA_StyledBackground, true);
    setAutoFillBackground(true);
    setStyleSheet(QStringLiteral("#attentionBanner { background: #c62828; }"
                                 " QLabel { color: white; font-weight: bold; }"));
    auto* layout = new QHBoxLayout(this);
    m_text = new QLabel(this);
    m_text->setObjectName(QStringLiteral("attentionText"));
    m_text->setWordWrap(true);
    // A long message (a long path) must not widen the window: cut, the full text in the tip.
    m_text->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_text->setMinimumWidth(1);
    m_ack = new QPushButton(this);
    layout->addWidget(m_text, 1);
    layout->addWidget(m_ack);
    connect(m_ack, &QPushButton::clicked, this, &AttentionBanner::acknowledgeAllRequested);
    retranslateUi();
    hide();
}

void AttentionBanner::setAttention(int count, const QString& latest) {
    m_count = count;
    m_latest = latest;
    setVisible(count > 0);
    retranslateUi();
}

void AttentionBanner::retranslateUi() {
    m_ack->setText(tr("Acknowledge all"));
    if (m_count == 0)
        return;
    m_text->setText(
        tr("%n critical alarm(s) not acknowledged. Latest: %1", nullptr, m_count).arg(m_latest));
    m_text->setToolTip(m_text->text());
}

void AttentionBanner::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

} // namespace hsmu::gui
