#pragma once
// JsonCursor: typed access to a JSON document that remembers where it is, so that every
// error names the file, the field path and what was expected:
//   "paper.json: structure.elements[1].material.k0: expected a number, found a string"
// Unknown keys are errors too (a typo must not silently fall back to a default).

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <stdexcept>
#include <string>

namespace hsmu {

class ConfigError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class JsonCursor {
public:
    JsonCursor(const nlohmann::json& node, std::string file, std::string path = {});

    const nlohmann::json& node() const { return m_node; }
    const std::string& path() const { return m_path; }
    bool has(const std::string& key) const;
    JsonCursor child(const std::string& key) const; ///< required object member
    JsonCursor at(std::size_t index) const;         ///< array element
    std::size_t size() const;                       ///< array length (requires an array)

    double number(const std::string& key) const;
    double number(const std::string& key, double fallback) const;
    /// An int; a JSON integer outside int's range is an error (never truncated).
    int integer(const std::string& key, int fallback) const;
    /// An int in [min, max] (when present), else an error naming the field.
    int integer(const std::string& key, int fallback, int min, int max) const;
    /// v (the value at key, e.g. an array element) as an int in [min, max], else an error.
    int checkedInteger(const nlohmann::json& v, const std::string& key, int min, int max) const;
    std::string string(const std::string& key) const;
    std::string string(const std::string& key, const std::string& fallback) const;
    bool boolean(const std::string& key, bool fallback) const;

    void requireObject() const;
    void requireArray() const;
    /// Throw if the object has a key not in `allowed`.
    void allowOnly(std::initializer_list<const char*> allowed) const;
    [[noreturn]] void fail(const std::string& key, const std::string& expected) const;

private:
    std::string fieldPath(const std::string& key) const;
    const nlohmann::json& m_node;
    std::string m_file;
    std::string m_path;
};

} // namespace hsmu
