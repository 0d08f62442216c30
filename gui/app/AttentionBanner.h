#pragma once
// AttentionBanner: the red strip over the live plots while critical alarms are not
// acknowledged: "N critical alarm(s) not acknowledged. Latest: ..." (cut to the width, the
// full text in the tooltip, so a long message never widens the window) and an
// "Acknowledge all" button. Hidden while the count is 0.
// Thread rules: GUI thread only.

#include <QWidget>

class QLabel;
class QPushButton;

namespace hsmu::gui {

class AttentionBanner : public QWidget {
    Q_OBJECT
public:
    explicit AttentionBanner(QWidget* parent = nullptr);

    /// count: unacknowledged critical alarms (0 hides the banner); latest: the newest text.
    void setAttention(int count, const QString& latest);

signals:
    void acknowledgeAllRequested();

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();

    QLabel* m_text = nullptr;
    QPushButton* m_ack = nullptr;
    int m_count = 0;
    QString m_latest;
};

} // namespace hsmu::gui
