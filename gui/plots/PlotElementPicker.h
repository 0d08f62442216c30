#pragma once
// PlotElementPicker: the "Element:" combo in the header of a per-element plot (hysteresis,
// force history, tracking; LivePlotsPanel), so that the operator can look at any element's
// loop, e.g. Bearing C's when the UKF identifies Bearing D (two labs, issue 25 item 15).
// Choices: indices into a RunLayout with their element names. setChoices() keeps the
// operator's own pick (by name) when the new layout still has that element, else it shows
// `fallback` (LivePlotsPanel passes the element the Parameters dock identifies, so the default
// views agree) and forgets the pick. Hidden with fewer than two choices. Like every combo box
// of the console it changes only on a click or the keyboard, never on the wheel (WheelGuard).
// Thread rules: GUI thread only.

#include "core/output/RunLayout.h"

#include <QString>
#include <QWidget>

#include <vector>

class QComboBox;
class QLabel;

namespace hsmu::gui {

class PlotElementPicker : public QWidget {
    Q_OBJECT
public:
    explicit PlotElementPicker(QWidget* parent = nullptr);

    /// Offer `candidates` (indices into layout) and return the element now shown: the
    /// operator's pick if it is still among them, else `fallback` (-1 with no candidates).
    int setChoices(const RunLayout& layout, const std::vector<int>& candidates, int fallback);
    /// The element shown (index into the layout given to setChoices()), -1 if none.
    int element() const { return m_element; }
    /// Its name ("" if none).
    QString elementName() const;
    QComboBox* comboBox() const { return m_combo; }

signals:
    /// The operator picked another element (index into the layout).
    void elementPicked(int element);

private:
    void retranslate();

    QLabel* m_label = nullptr;
    QComboBox* m_combo = nullptr;
    int m_element = -1;
    QString m_picked; ///< the operator's own pick, by name ("" = follow the fallback)
    bool m_filling = false;
};

} // namespace hsmu::gui
