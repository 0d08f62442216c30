#include "core/record/RecordChecksum.h"

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace hsmu {

namespace {

struct Fnv {
    std::uint64_t h = 1469598103934665603ull;
    void bytes(const void* p, std::size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) {
            h ^= b[i];
            h *= 1099511628211ull;
        }
    }
    void text(const std::string& s) { // length-prefixed: "ab","c" differs from "a","bc"
        const std::uint64_t n = s.size();
        bytes(&n, sizeof n);
        bytes(s.data(), s.size());
    }
    void number(double x) { bytes(&x, sizeof x); }
};

} // namespace

std::string recordMetadataChecksum(const RecordMetadata& m, const RunLayout& l) {
    Fnv f;
    for (const std::string* s : {&m.program, &m.programVersion, &m.startTime, &m.configuration,
                                 &m.configName, &m.operatorNotes, &m.run, &m.numerics})
        f.text(*s);
    f.number(m.dt);
    for (const std::string& n : l.dofNames)
        f.text(n);
    for (const ElementInfo& e : l.elements) {
        f.text(e.name);
        f.text(e.type);
        f.text(e.units.deformation);
        f.text(e.units.force);
        f.number(e.experimental ? 1.0 : 0.0);
        f.number(e.nonlinear ? 1.0 : 0.0);
    }
    for (const ElementChannel& c : l.channels) {
        f.text(c.element);
        f.text(c.name);
        f.text(c.unit);
    }
    if (l.updating) {
        f.text(l.updating->specimen);
        f.text(l.updating->method);
        for (const std::string& p : l.updating->parameters)
            f.text(p);
        f.text(l.updating->units.deformation);
        f.text(l.updating->units.force);
        if (!l.updating->basicDof.empty()) // records without it keep their checksum
            f.text(l.updating->basicDof);
    }
    if (!m.dofRecording.full()) { // records of every DOF at every step keep their checksum
        f.text("dofs");
        for (const int k : m.dofRecording.dofs)
            f.number(double(k));
        f.number(double(m.dofRecording.every));
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(f.h));
    return buf;
}

} // namespace hsmu
