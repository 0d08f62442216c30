#include "core/identification/ParameterLayout.h"

#include <stdexcept>

namespace hsmu {

ParameterLayout::ParameterLayout() : m_names(std::make_shared<const std::vector<std::string>>()) {}

ParameterLayout::ParameterLayout(std::vector<std::string> names)
    : m_names(std::make_shared<const std::vector<std::string>>(std::move(names)))
{
}

std::optional<std::size_t> ParameterLayout::find(std::string_view name) const
{
    for (std::size_t i = 0; i < m_names->size(); ++i)
        if ((*m_names)[i] == name)
            return i;
    return std::nullopt;
}

std::size_t ParameterLayout::indexOf(std::string_view name, std::string_view what) const
{
    if (const auto i = find(name))
        return *i;
    std::string expected;
    for (const std::string& n : *m_names)
        expected += (expected.empty() ? "" : ", ") + n;
    throw std::invalid_argument(std::string(what) + ": unknown parameter '" + std::string(name) +
                                "' (expected " + (expected.empty() ? "none" : expected) + ")");
}

} // namespace hsmu
