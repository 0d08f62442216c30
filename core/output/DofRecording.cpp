#include "core/output/DofRecording.h"

#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace hsmu {

namespace {

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    const auto e = s.find_last_not_of(" \t");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

/// The whole text as a non-negative index (digits only), else -1 (too large: -2).
long indexOf(const std::string& s) {
    if (s.empty() || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return -1;
    long v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && end == s.data() + s.size() ? v : -2;
}

} // namespace

std::vector<int> parseDofList(const std::string& text, const std::vector<std::string>& dofNames,
                              const std::vector<std::string>& specimenNames) {
    const long n = long(dofNames.size());
    const std::string range = "0.." + std::to_string(n - 1);
    const auto inRange = [&](long i, const std::string& item) {
        if (i < 0 || i >= n)
            throw std::invalid_argument("DOF index '" + item + "' out of range " + range);
        return int(i);
    };
    if (trim(text).empty())
        throw std::invalid_argument("empty DOF list (expected DOF indices " + range +
                                    ", ranges such as 0-9 or DOF names, separated by commas)");
    std::vector<int> out;
    std::size_t at = 0;
    for (;;) {
        const std::size_t comma = text.find(',', at);
        const std::string item = trim(text.substr(at, comma - at));
        if (item.empty())
            throw std::invalid_argument("empty item in '" + text +
                                        "' (expected DOF indices, ranges A-B or DOF names "
                                        "separated by commas)");
        const std::size_t dash = item.find('-');
        const long single = indexOf(item);
        const long from = dash == std::string::npos ? -1 : indexOf(trim(item.substr(0, dash)));
        const long to = dash == std::string::npos ? -1 : indexOf(trim(item.substr(dash + 1)));
        if (single != -1) {
            out.push_back(inRange(single, item));
        } else if (from != -1 && to != -1) {
            const int a = inRange(from, item), b = inRange(to, item);
            if (a > b)
                throw std::invalid_argument("DOF range '" + item + "' runs backwards");
            for (int i = a; i <= b; ++i)
                out.push_back(i);
        } else if (const auto it = std::find(dofNames.begin(), dofNames.end(), item);
                   it != dofNames.end()) {
            out.push_back(int(it - dofNames.begin()));
        } else if (std::find(specimenNames.begin(), specimenNames.end(), item) !=
                   specimenNames.end()) {
            throw std::invalid_argument(
                "'" + item +
                "' is a specimen (an experimental element): its channels (commanded, measured, "
                "force, actuators, basic DOFs) are always recorded in full at every step; only "
                "numerical DOFs can be chosen");
        } else {
            throw std::invalid_argument("no DOF named '" + item + "' (expected DOF indices " +
                                        range + ", ranges such as 0-9 or DOF names)");
        }
        if (comma == std::string::npos)
            break;
        at = comma + 1;
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    if (long(out.size()) == n)
        out.clear(); // every DOF: the default record
    return out;
}

bool DofRecording::validFor(std::size_t nDofs) const {
    for (std::size_t j = 0; j < dofs.size(); ++j)
        if (dofs[j] < 0 || std::size_t(dofs[j]) >= nDofs || (j > 0 && dofs[j] <= dofs[j - 1]))
            return false;
    return every >= 1;
}

std::string describeDofList(const std::vector<int>& dofs) {
    if (dofs.empty())
        return "all";
    std::string out;
    for (std::size_t i = 0; i < dofs.size();) {
        std::size_t j = i;
        while (j + 1 < dofs.size() && dofs[j + 1] == dofs[j] + 1)
            ++j;
        if (!out.empty())
            out += ',';
        out += std::to_string(dofs[i]);
        if (j > i)
            out += '-' + std::to_string(dofs[j]);
        i = j + 1;
    }
    return out;
}

} // namespace hsmu
