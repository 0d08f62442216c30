#include "core/output/PrettyJson.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hsmu {

namespace {

using Streamed = std::map<std::string, NamedValues>;

void indent(std::ostream& out, int n) {
    for (int i = 0; i < n; ++i)
        out.put(' ');
}

/// nlohmann's own serializer, made once per object: json(x).dump() makes one per value (a
/// string, a locale query), 6,000 instructions an entry of a 10,000-DOF summary.
class Scalars {
public:
    explicit Scalars(std::ostream& out) : m_out(out), m_s(nlohmann::detail::output_adapter<char>(out), ' ') {}
    Scalars& quoted(const std::string& text) {
        *m_text.get_ptr<std::string*>() = text; // reuses the string's capacity
        m_s.dump(m_text, false, false, 0);
        return *this;
    }
    Scalars& number(double x) {
        if (std::isfinite(x)) {
            *m_number.get_ptr<double*>() = x;
            m_s.dump(m_number, false, false, 0);
        } else {
            m_out << "null";
        }
        return *this;
    }

private:
    std::ostream& m_out;
    nlohmann::detail::serializer<nlohmann::json> m_s;
    nlohmann::json m_text = "", m_number = 0.0;
};

std::string quoted(const std::string& s) {
    return nlohmann::json(s).dump();
}

void writeNamed(std::ostream& out, const NamedValues& v, int at) {
    const std::vector<std::string>& names = v.names;
    std::vector<std::size_t> order(names.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return names[a] < names[b]; });
    // Of equal names keep the last (stable sort: the last of a run of equals).
    std::vector<std::size_t> kept;
    kept.reserve(order.size());
    for (std::size_t k = 0; k < order.size(); ++k)
        if (k + 1 == order.size() || names[order[k + 1]] != names[order[k]])
            kept.push_back(order[k]);
    if (kept.empty()) {
        out << "{}";
        return;
    }
    Scalars scalars(out);
    out << "{\n";
    for (std::size_t k = 0; k < kept.size(); ++k) {
        const std::size_t i = kept[k];
        indent(out, at + 2);
        scalars.quoted(names[i]);
        out << ": ";
        if (v.units.empty()) {
            scalars.number(v.values[i]);
        } else {
            out << "{\n";
            indent(out, at + 4);
            out << "\"unit\": ";
            scalars.quoted(v.units[i]);
            out << ",\n";
            indent(out, at + 4);
            out << "\"value\": ";
            scalars.number(v.values[i]);
            out << '\n';
            indent(out, at + 2);
            out << '}';
        }
        out << (k + 1 < kept.size() ? ",\n" : "\n");
    }
    indent(out, at);
    out << '}';
}

void write(std::ostream& out, const nlohmann::json& j, int at, const std::string& path,
           const Streamed& streamed) {
    if (const auto s = streamed.find(path); s != streamed.end()) {
        writeNamed(out, s->second, at);
        return;
    }
    if (j.is_object()) {
        // The object's keys plus the streamed children it lacks, in std::string order.
        std::map<std::string, const nlohmann::json*> items;
        for (auto it = j.begin(); it != j.end(); ++it)
            items.emplace(it.key(), &it.value());
        const std::string prefix = path + '/';
        for (auto s = streamed.lower_bound(prefix); s != streamed.end(); ++s) {
            if (s->first.compare(0, prefix.size(), prefix) != 0)
                break;
            const std::string child = s->first.substr(prefix.size());
            if (child.find('/') == std::string::npos)
                items.emplace(child, nullptr);
        }
        if (items.empty()) {
            out << "{}";
            return;
        }
        out << "{\n";
        std::size_t k = 0;
        static const nlohmann::json none;
        for (const auto& [key, value] : items) {
            indent(out, at + 2);
            out << quoted(key) << ": ";
            write(out, value ? *value : none, at + 2, prefix + key, streamed);
            out << (++k < items.size() ? ",\n" : "\n");
        }
        indent(out, at);
        out << '}';
    } else if (j.is_array() && !j.empty()) {
        out << "[\n";
        for (std::size_t k = 0; k < j.size(); ++k) {
            indent(out, at + 2);
            write(out, j[k], at + 2, path + '/' + std::to_string(k), streamed);
            out << (k + 1 < j.size() ? ",\n" : "\n");
        }
        indent(out, at);
        out << ']';
    } else {
        out << j.dump();
    }
}

} // namespace

void writePrettyJson(std::ostream& out, const nlohmann::json& j, const Streamed& streamed) {
    write(out, j, 0, "", streamed);
}

} // namespace hsmu
