#include "gui/plots/PlotElementPicker.h"

#include "gui/app/LiveText.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>

#include <algorithm>

namespace hsmu::gui {

PlotElementPicker::PlotElementPicker(QWidget* parent) : QWidget(parent) {
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(4, 0, 4, 0);
    row->setSpacing(4);
    m_label = new QLabel(this);
    m_combo = new QComboBox(this);
    m_combo->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    // The plot under it sets the width: the row may be cut at its right end, never widen it.
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_label->setBuddy(m_combo);
    row->addWidget(m_label);
    row->addWidget(m_combo);
    row->addStretch(1);
    LiveText::bind(this, [this] { retranslate(); }); // now and at each language change
    connect(m_combo, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (m_filling || i < 0)
            return;
        m_element = m_combo->itemData(i).toInt();
        m_picked = m_combo->itemText(i);
        emit elementPicked(m_element);
    });
    hide();
}

int PlotElementPicker::setChoices(const RunLayout& layout, const std::vector<int>& candidates,
                                  int fallback) {
    m_filling = true;
    m_combo->clear();
    int shown = -1;
    for (const int i : candidates) {
        const QString name = QString::fromStdString(layout.elements[std::size_t(i)].name);
        m_combo->addItem(name, i);
        if (!m_picked.isEmpty() && name == m_picked)
            shown = i;
    }
    if (shown < 0) { // no pick, or its element is gone: the default view
        m_picked.clear();
        shown = std::find(candidates.begin(), candidates.end(), fallback) != candidates.end()
                    ? fallback
                    : (candidates.empty() ? -1 : candidates.front());
    }
    m_element = shown;
    m_combo->setCurrentIndex(m_combo->findData(shown));
    m_filling = false;
    setVisible(candidates.size() > 1);
    return shown;
}

QString PlotElementPicker::elementName() const {
    return m_element < 0 ? QString() : m_combo->currentText();
}

void PlotElementPicker::retranslate() {
    m_label->setText(tr("Element:"));
    m_combo->setToolTip(tr("The element this plot shows"));
}

} // namespace hsmu::gui
