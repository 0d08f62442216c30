#pragma once
// GroundMotionError: why a ground-motion file could not be read. what() is a complete
// sentence for the operator: "<file name> line <n>: <problem>" or "<file name>: <problem>",
// e.g. "elcentro.AT2 line 4: expected 'NPTS=..., DT=...' header, found 'xyz'".

#include <stdexcept>
#include <string>

namespace hsmu {

class GroundMotionError : public std::runtime_error {
public:
    /// file: the name shown to the user (usually the file name without its folder);
    /// line: 1-based line number, 0 when the problem is not tied to a line.
    GroundMotionError(const std::string& file, int line, const std::string& problem)
        : std::runtime_error(compose(file, line, problem)), m_file(file), m_line(line) {}

    const std::string& file() const { return m_file; }
    int line() const { return m_line; } ///< 0 if not tied to a line

private:
    static std::string compose(const std::string& file, int line, const std::string& problem) {
        if (line > 0)
            return file + " line " + std::to_string(line) + ": " + problem;
        return file + ": " + problem;
    }

    std::string m_file;
    int m_line = 0;
};

} // namespace hsmu
