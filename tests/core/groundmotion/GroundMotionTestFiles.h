#pragma once
// Helpers for the ground-motion reader tests: write a file into a temporary folder and capture
// the message of the error a reader throws.

#include "core/groundmotion/GroundMotionError.h"

#include <QDir>
#include <QFile>
#include <QString>

#include <initializer_list>
#include <stdexcept>
#include <string>

namespace hsmu::test {

/// Write `content` verbatim to dir/name and return the path.
inline std::string writeFile(const QString& dir, const QString& name, const std::string& content) {
    const QString path = QDir(dir).filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write(content.data(), static_cast<qint64>(content.size()));
    return path.toStdString();
}

/// The what() of the GroundMotionError `call` throws; "NO ERROR" or "WRONG TYPE: ..." otherwise.
template <class Call> std::string errorOf(Call&& call) {
    try {
        call();
    } catch (const GroundMotionError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("WRONG TYPE: ") + e.what();
    }
    return "NO ERROR";
}

/// True if `message` contains every part.
inline bool containsAll(const std::string& message, std::initializer_list<const char*> parts) {
    for (const char* part : parts) {
        if (message.find(part) == std::string::npos)
            return false;
    }
    return true;
}

} // namespace hsmu::test
