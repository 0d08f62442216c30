#pragma once
// AlarmPanel: the "Alarms and events" dock's content: the AlarmList (the whole height, 5+ rows
// at 1280x720) with "Acknowledge selected" and "Acknowledge all" on its right.
// Thread rules: GUI thread only.

#include <QWidget>

class QPushButton;

namespace hsmu::gui {

class AlarmList;

class AlarmPanel : public QWidget {
    Q_OBJECT
public:
    explicit AlarmPanel(QWidget* parent = nullptr);
    AlarmList* list() const { return m_list; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();

    AlarmList* m_list = nullptr;
    QPushButton* m_ackSelected = nullptr;
    QPushButton* m_ackAll = nullptr;
};

} // namespace hsmu::gui
