// RecordReader's logs: the alarm list, the updating's events and the notes, read as they grow
// (docs/recording.md). RecordReaderImpl.h holds the reader's inside.
#include "core/record/RecordReaderImpl.h"

#include <algorithm>

namespace hsmu {

using recordreader::appendRows;

namespace {

AlarmSeverity severityFromName(const std::string& s) {
    for (auto v : {AlarmSeverity::Info, AlarmSeverity::Warning, AlarmSeverity::Critical})
        if (s == alarmSeverityName(v))
            return v;
    return AlarmSeverity::Warning;
}

AlarmKind kindFromName(const std::string& s) {
    for (int i = 0; i <= int(AlarmKind::ModelUpdate); ++i)
        if (s == alarmKindName(AlarmKind(i)))
            return AlarmKind(i);
    return AlarmKind::ElementFault;
}

std::vector<std::string> readFixedStrings(const Column& c, hsize_t r0, hsize_t r1,
                                          const std::string& w) {
    const h5::Id type = h5::check(H5Dget_type(c.dset.get()), w, "damaged record (alarm type)");
    const std::size_t size = H5Tget_size(type.get());
    if (H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) > 0 || size == 0)
        throw RecordError(w + ": damaged record (" + c.name + " is not a fixed string)");
    std::vector<char> buf(size * (r1 - r0));
    c.read(r0, r1, type.get(), buf.data(), w);
    std::vector<std::string> out;
    for (hsize_t i = 0; i < r1 - r0; ++i) {
        const char* s = buf.data() + i * size;
        out.emplace_back(s, std::find(s, s + size, '\0'));
    }
    return out;
}

} // namespace

void RecordReader::Impl::readNewAlarms() {
    hsize_t n = alarmTime.rows();
    for (const Column* c : {&alarmStep, &alarmSeverity, &alarmKind, &alarmMessage})
        n = std::min(n, c->rows());
    if (alarmCode.dset.valid())
        n = std::min(n, alarmCode.rows());
    const hsize_t r0 = data.alarms.size();
    if (n <= r0)
        return;
    std::vector<double> t(n - r0);
    std::vector<int> s(n - r0);
    alarmTime.read(r0, n, H5T_NATIVE_DOUBLE, t.data(), path);
    alarmStep.read(r0, n, H5T_NATIVE_INT, s.data(), path);
    const auto sev = readFixedStrings(alarmSeverity, r0, n, path);
    const auto kind = readFixedStrings(alarmKind, r0, n, path);
    const auto msg = readFixedStrings(alarmMessage, r0, n, path);
    const auto code = alarmCode.dset.valid() ? readFixedStrings(alarmCode, r0, n, path)
                                             : std::vector<std::string>(n - r0);
    for (std::size_t i = 0; i < t.size(); ++i)
        data.alarms.push_back(
            {t[i], s[i], severityFromName(sev[i]), kindFromName(kind[i]), msg[i], code[i], {}});
}

void RecordReader::Impl::readNewEvents() {
    if (!v2 || !data.layout.updating)
        return;
    hsize_t n = eventStep.rows();
    const bool decisions = eventDecision.dset.valid();
    for (const Column* c : {&eventTime, &eventElement, &eventValues})
        n = std::min(n, c->rows());
    if (decisions)
        n = std::min({n, eventDecision.rows(), eventProposal.rows()});
    const hsize_t r0 = data.updateEvents.size();
    if (n <= r0)
        return;
    std::vector<int> s(n - r0);
    std::vector<double> t(n - r0);
    Eigen::MatrixXd values;
    eventStep.read(r0, n, H5T_NATIVE_INT, s.data(), path);
    eventTime.read(r0, n, H5T_NATIVE_DOUBLE, t.data(), path);
    std::vector<int> element(n - r0);
    eventElement.read(r0, n, H5T_NATIVE_INT, element.data(), path);
    appendRows(values, eventValues, 0, n - r0, path, r0);
    std::vector<int> decision(n - r0, 0), proposal(n - r0, 0);
    if (decisions) {
        eventDecision.read(r0, n, H5T_NATIVE_INT, decision.data(), path);
        eventProposal.read(r0, n, H5T_NATIVE_INT, proposal.data(), path);
    }
    for (std::size_t i = 0; i < s.size(); ++i) {
        std::vector<double> row(std::size_t(values.cols()));
        for (Eigen::Index j = 0; j < values.cols(); ++j)
            row[std::size_t(j)] = values(Eigen::Index(i), j);
        const auto& elements = data.layout.elements;
        const bool known = element[i] >= 0 && std::size_t(element[i]) < elements.size();
        const auto code = std::size_t(decision[i]);
        data.updateEvents.push_back(
            {s[i], t[i], known ? elements[std::size_t(element[i])].name : "", std::move(row),
             code < decisionCodes.size() ? decisionCodes[code] : std::string("applied"),
             proposal[i]});
    }
}

void RecordReader::Impl::readNewNotes() {
    if (!v2)
        return;
    hsize_t n = std::min({noteTime.rows(), noteStep.rows(), noteText.rows()});
    const hsize_t r0 = data.notes.size();
    if (n <= r0)
        return;
    std::vector<double> t(n - r0);
    std::vector<int> s(n - r0);
    noteTime.read(r0, n, H5T_NATIVE_DOUBLE, t.data(), path);
    noteStep.read(r0, n, H5T_NATIVE_INT, s.data(), path);
    const auto text = readFixedStrings(noteText, r0, n, path);
    for (std::size_t i = 0; i < t.size(); ++i)
        data.notes.push_back({t[i], s[i], text[i]});
}

} // namespace hsmu
