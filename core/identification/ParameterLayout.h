#pragma once
// ParameterLayout: the fixed, named order of a parameter vector (docs/method.md, "Parameters by
// position"). An identifier owns one for its lifetime: its estimate, standard deviations and
// bounds are vectors in this order, and so are the values the Reporter offers and the Inspector
// checks. Names are resolved to positions only at the edges (configuration, console edits and
// tables, command-line output, record attributes), once, with indexOf().
// Copies are cheap (the names are shared and never change).

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hsmu {

class ParameterLayout {
public:
    ParameterLayout();
    explicit ParameterLayout(std::vector<std::string> names);

    std::size_t size() const { return m_names->size(); }
    bool empty() const { return m_names->empty(); }
    const std::vector<std::string>& names() const { return *m_names; }
    /// Precondition: i < size().
    const std::string& name(std::size_t i) const { return (*m_names)[i]; }
    /// Position of `name`; nullopt if the layout has no such parameter.
    std::optional<std::size_t> find(std::string_view name) const;
    /// Position of `name`; throws std::invalid_argument "WHAT: unknown parameter 'NAME'
    /// (expected a, b, ...)" if the layout has no such parameter.
    std::size_t indexOf(std::string_view name, std::string_view what) const;

    bool operator==(const ParameterLayout& other) const { return names() == other.names(); }

private:
    std::shared_ptr<const std::vector<std::string>> m_names;
};

} // namespace hsmu
