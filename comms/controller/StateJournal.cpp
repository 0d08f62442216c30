#include "comms/controller/StateJournal.h"

#include <cinttypes>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace hsmu::comms {

namespace {

constexpr const char* kMagic = "hsmu-controller-state 1";

std::string hex(std::uint64_t v) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016" PRIx64, v);
    return buf;
}

bool parseDouble(std::istringstream& in, double& v) {
    std::string word;
    if (!(in >> word))
        return false;
    char* end = nullptr;
    v = std::strtod(word.c_str(), &end);
    return end && *end == '\0';
}

bool parseRecord(const std::string& line, JournalRecord& r) {
    std::istringstream in(line);
    std::string kind;
    if (!(in >> kind >> r.element) || r.element < 0)
        return false;
    if (kind == "configure") {
        r.kind = JournalRecord::Kind::Configure;
        return parseDouble(in, r.dt) && r.dt > 0.0;
    }
    if (kind == "commit") {
        r.kind = JournalRecord::Kind::Commit;
        return static_cast<bool>(in >> r.step) && parseDouble(in, r.target) &&
               parseDouble(in, r.achieved) && parseDouble(in, r.deformation) &&
               parseDouble(in, r.force);
    }
    if (kind == "commits") {
        r.kind = JournalRecord::Kind::Commit;
        std::size_t n = 0;
        if (!(in >> r.step >> n) || n < 2 || n > 1000)
            return false;
        r.channels.resize(n);
        for (JournalChannel& c : r.channels)
            if (!parseDouble(in, c.target) || !parseDouble(in, c.achieved) ||
                !parseDouble(in, c.stroke) || !parseDouble(in, c.force))
                return false;
        return true;
    }
    if (kind == "reset") {
        r.kind = JournalRecord::Kind::Reset;
        return true;
    }
    return false;
}

} // namespace

std::uint64_t StateJournal::fingerprint(const std::string& text) {
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char c : text) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

StateJournal::~StateJournal() {
    if (m_file)
        std::fclose(m_file);
}

bool StateJournal::open(const std::string& path, const std::vector<JournalElement>& elements,
                        std::vector<JournalRecord>& records, std::string& error) {
    records.clear();
    m_path = path;
    std::vector<std::string> header{kMagic};
    for (std::size_t i = 0; i < elements.size(); ++i)
        header.push_back("element " + std::to_string(i) + " " + hex(elements[i].fingerprint) + " " +
                         elements[i].name);

    std::error_code ec;
    const bool exists =
        std::filesystem::exists(path, ec) && std::filesystem::file_size(path, ec) > 0;
    if (exists) {
        std::ifstream in(path, std::ios::binary);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (!in.good() && !in.eof()) {
            error = path + ": cannot read the state file";
            return false;
        }
        // Drop an unfinished last line (the process died while writing it).
        const std::size_t complete =
            text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
        if (complete < text.size()) {
            text.resize(complete);
            std::filesystem::resize_file(path, complete, ec);
            if (ec) {
                error = path + ": cannot cut the unfinished last line: " + ec.message();
                return false;
            }
        }
        std::istringstream lines(text);
        std::string line;
        std::size_t n = 0;
        while (std::getline(lines, line)) {
            ++n;
            if (n <= header.size()) {
                if (line != header[n - 1]) {
                    error = path + ": line " + std::to_string(n) +
                            ": this state file belongs to other specimens (expected '" +
                            header[n - 1] + "'); use another --state file";
                    return false;
                }
                continue;
            }
            JournalRecord r;
            if (!parseRecord(line, r) || r.element >= static_cast<int>(elements.size())) {
                error = path + ": line " + std::to_string(n) + ": unreadable record '" + line + "'";
                return false;
            }
            records.push_back(r);
        }
        if (n < header.size()) {
            error = path + ": the state file's header is incomplete";
            return false;
        }
    }
    m_file = std::fopen(path.c_str(), exists ? "ab" : "wb");
    if (!m_file) {
        error = path + ": cannot open the state file for writing";
        return false;
    }
    if (!exists) {
        for (const auto& h : header)
            std::fprintf(m_file, "%s\n", h.c_str());
        if (std::fflush(m_file) != 0) {
            error = path + ": cannot write the state file";
            return false;
        }
    }
    return true;
}

bool StateJournal::append(const JournalRecord& r, std::string& error) {
    if (!m_file) {
        error = "no state file is open";
        return false;
    }
    int written = 0;
    switch (r.kind) {
    case JournalRecord::Kind::Configure:
        written = std::fprintf(m_file, "configure %d %.17g\n", r.element, r.dt);
        break;
    case JournalRecord::Kind::Commit:
        if (r.channels.empty()) {
            written = std::fprintf(m_file, "commit %d %" PRIu64 " %.17g %.17g %.17g %.17g\n",
                                   r.element, r.step, r.target, r.achieved, r.deformation, r.force);
            break;
        }
        written = std::fprintf(m_file, "commits %d %" PRIu64 " %zu", r.element, r.step,
                               r.channels.size());
        for (const JournalChannel& c : r.channels)
            if (written >= 0)
                written = std::fprintf(m_file, " %.17g %.17g %.17g %.17g", c.target, c.achieved,
                                       c.stroke, c.force);
        if (written >= 0)
            written = std::fprintf(m_file, "\n");
        break;
    case JournalRecord::Kind::Reset:
        written = std::fprintf(m_file, "reset %d\n", r.element);
        break;
    }
    if (written < 0 || std::fflush(m_file) != 0) {
        error = m_path + ": cannot write the state file";
        return false;
    }
    return true;
}

} // namespace hsmu::comms
