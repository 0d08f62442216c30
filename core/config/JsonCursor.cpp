#include "core/config/JsonCursor.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace hsmu {

namespace {
const char* typeWord(const nlohmann::json& j)
{
    switch (j.type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::string: return "a string";
    case nlohmann::json::value_t::boolean: return "a boolean";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float: return "a number";
    default: return "something else";
    }
}
} // namespace

JsonCursor::JsonCursor(const nlohmann::json& node, std::string file, std::string path)
    : m_node(node), m_file(std::move(file)), m_path(std::move(path))
{
}

std::string JsonCursor::fieldPath(const std::string& key) const
{
    if (key.empty())
        return m_path.empty() ? "(top level)" : m_path;
    return m_path.empty() ? key : m_path + "." + key;
}

void JsonCursor::fail(const std::string& key, const std::string& expected) const
{
    throw ConfigError(m_file + ": " + fieldPath(key) + ": " + expected);
}

void JsonCursor::requireObject() const
{
    if (!m_node.is_object())
        fail("", std::string("expected an object, found ") + typeWord(m_node));
}

void JsonCursor::requireArray() const
{
    if (!m_node.is_array())
        fail("", std::string("expected an array, found ") + typeWord(m_node));
}

bool JsonCursor::has(const std::string& key) const
{
    return m_node.is_object() && m_node.contains(key) && !m_node.at(key).is_null();
}

JsonCursor JsonCursor::child(const std::string& key) const
{
    requireObject();
    if (!has(key))
        fail(key, "missing (required)");
    return JsonCursor(m_node.at(key), m_file, fieldPath(key));
}

JsonCursor JsonCursor::at(std::size_t index) const
{
    requireArray();
    if (index >= m_node.size())
        fail("", "index " + std::to_string(index) + " out of range");
    return JsonCursor(m_node.at(index), m_file, m_path + "[" + std::to_string(index) + "]");
}

std::size_t JsonCursor::size() const
{
    requireArray();
    return m_node.size();
}

double JsonCursor::number(const std::string& key) const
{
    requireObject();
    if (!has(key))
        fail(key, "missing (expected a number)");
    const auto& v = m_node.at(key);
    if (!v.is_number())
        fail(key, std::string("expected a number, found ") + typeWord(v));
    const double x = v.get<double>();
    if (!std::isfinite(x))
        fail(key, "expected a finite number");
    return x;
}

double JsonCursor::number(const std::string& key, double fallback) const
{
    return has(key) ? number(key) : fallback;
}

int JsonCursor::integer(const std::string& key, int fallback) const
{
    if (!has(key))
        return fallback;
    const auto& v = m_node.at(key);
    if (!v.is_number_integer())
        fail(key, std::string("expected an integer, found ") + typeWord(v));
    // No silent truncation: 4294967297 is not 1.
    const bool fits = v.is_number_unsigned()
                          ? v.get<std::uint64_t>() <= std::uint64_t(std::numeric_limits<int>::max())
                          : v.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
                                v.get<std::int64_t>() <= std::numeric_limits<int>::max();
    if (!fits)
        fail(key, "integer " + v.dump() + " out of range (at most " +
                      std::to_string(std::numeric_limits<int>::max()) + ")");
    return v.get<int>();
}

int JsonCursor::integer(const std::string& key, int fallback, int min, int max) const
{
    const int i = integer(key, fallback);
    if (has(key) && (i < min || i > max))
        fail(key, "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
                      "], found " + std::to_string(i));
    return i;
}

int JsonCursor::checkedInteger(const nlohmann::json& v, const std::string& key, int min,
                               int max) const
{
    if (!v.is_number_integer())
        fail(key, std::string("expected an integer, found ") + typeWord(v));
    const bool fits = v.is_number_unsigned() ? v.get<std::uint64_t>() <= std::uint64_t(max)
                                             : v.get<std::int64_t>() >= min &&
                                                   v.get<std::int64_t>() <= max;
    if (!fits)
        fail(key, "integer " + v.dump() + " out of range [" + std::to_string(min) + ", " +
                      std::to_string(max) + "]");
    return v.get<int>();
}

std::string JsonCursor::string(const std::string& key) const
{
    requireObject();
    if (!has(key))
        fail(key, "missing (expected a string)");
    const auto& v = m_node.at(key);
    if (!v.is_string())
        fail(key, std::string("expected a string, found ") + typeWord(v));
    return v.get<std::string>();
}

std::string JsonCursor::string(const std::string& key, const std::string& fallback) const
{
    return has(key) ? string(key) : fallback;
}

bool JsonCursor::boolean(const std::string& key, bool fallback) const
{
    if (!has(key))
        return fallback;
    const auto& v = m_node.at(key);
    if (!v.is_boolean())
        fail(key, std::string("expected true or false, found ") + typeWord(v));
    return v.get<bool>();
}

void JsonCursor::allowOnly(std::initializer_list<const char*> allowed) const
{
    requireObject();
    for (auto it = m_node.begin(); it != m_node.end(); ++it) {
        bool ok = false;
        for (const char* a : allowed)
            ok = ok || it.key() == a;
        if (!ok) {
            std::string list;
            for (const char* a : allowed)
                list += (list.empty() ? "" : ", ") + std::string(a);
            fail(it.key(), "unknown field (expected one of: " + list + ")");
        }
    }
}

} // namespace hsmu
