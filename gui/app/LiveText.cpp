#include "gui/app/LiveText.h"

#include <QEvent>
#include <QObject>

namespace hsmu::gui {

namespace {
class LanguageFilter : public QObject {
public:
    LanguageFilter(QObject* owner, std::function<void()> apply)
        : QObject(owner), m_apply(std::move(apply)) {
        owner->installEventFilter(this);
    }
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (watched == parent() && event->type() == QEvent::LanguageChange)
            m_apply();
        return false; // the owner still sees it
    }

private:
    std::function<void()> m_apply;
};
} // namespace

void LiveText::bind(QObject* owner, std::function<void()> apply) {
    apply();
    new LanguageFilter(owner, std::move(apply));
}

} // namespace hsmu::gui
