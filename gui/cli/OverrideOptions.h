#pragma once
// OverrideOptions: the command-line options shared by `hsmu run` and `hsmu compare` that
// change the configuration before it is built (ConfigOverrides):
//   --ground-motion FILE   a record file (format and units detected)
//   --record-dt DT         the record's own sample step [s], > 0: needed by a one-column file
//   --scale S              ground-motion scale factor [-]
//   --dt DT                integration step [s], > 0
//   --duration T           test duration [s], > 0
// Thread rules: main thread (command-line parsing).

#include "gui/ConfigOverrides.h"

#include <QCommandLineOption>
#include <QCoreApplication>

#include <optional>

class QCommandLineParser;

namespace hsmu::gui {

class OverrideOptions {
    Q_DECLARE_TR_FUNCTIONS(OverrideOptions)
public:
    OverrideOptions();

    /// Add the five options to p.
    void addTo(QCommandLineParser& p) const;
    /// Read them from a parsed p into overrides; a message if a number is malformed.
    std::optional<QString> read(const QCommandLineParser& p, ConfigOverrides& overrides) const;

    /// Read option o as a finite number (> 0 if positive) into target when it is set; a
    /// message naming the option and the text otherwise.
    static std::optional<QString> number(const QCommandLineParser& p, const QCommandLineOption& o,
                                         std::optional<double>& target, bool positive);

private:
    QCommandLineOption m_groundMotion, m_recordDt, m_scale, m_dt, m_duration;
};

} // namespace hsmu::gui
