#pragma once
// LiveText: live language switching for widgets built in code (the retranslateUi pattern
// without a .ui file). bind(owner, apply) runs apply() now and again whenever owner receives
// QEvent::LanguageChange (Translations::install() installs a new catalogue: Qt then sends it
// to every widget), so apply() sets every user-visible text of that piece with tr().
// Texts that carry data (a status, a count) are re-made by their owner from the data it kept.
// Thread rules: GUI thread only.

#include <functional>

class QObject;

namespace hsmu::gui {

struct LiveText {
    /// apply() now and on each LanguageChange of owner (for as long as owner lives).
    static void bind(QObject* owner, std::function<void()> apply);
};

} // namespace hsmu::gui
