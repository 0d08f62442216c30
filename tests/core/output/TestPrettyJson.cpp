// PrettyJson: writePrettyJson writes the bytes nlohmann's dump(2) writes for the same document
// (the reference: nlohmann itself, building the streamed objects as a DOM), for names that
// sort differently as numbers and as strings, repeated names, escapes, UTF-8, non-finite
// values, empty objects and arrays, and streamed objects missing from the document.

#include "core/output/PrettyJson.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <sstream>

using namespace hsmu;

namespace {

nlohmann::json domOf(const NamedValues& v) {
    nlohmann::json o = nlohmann::json::object();
    for (std::size_t i = 0; i < v.names.size(); ++i) {
        const double x = v.values[i];
        const nlohmann::json value = std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
        o[v.names[i]] = v.units.empty() ? value : nlohmann::json{{"value", value}, {"unit", v.units[i]}};
    }
    return o;
}

std::string streamed(const nlohmann::json& j, const std::map<std::string, NamedValues>& blocks) {
    std::ostringstream out;
    writePrettyJson(out, j, blocks);
    return out.str();
}

} // namespace

class TestPrettyJson : public QObject {
    Q_OBJECT
private slots:
    void plainDocumentsEqualDump2() {
        const nlohmann::json docs[] = {
            nlohmann::json::object(),
            nlohmann::json::array(),
            nlohmann::json(nullptr),
            nlohmann::json(0.1),
            nlohmann::json{{"b", {1, 2.5, "x", nullptr, true}}, {"a", nlohmann::json::object()},
                           {"c", {{"z", nlohmann::json::array()}, {"y", {{"q", -1e-300}}}}},
                           {"d", "tab\t \"quoted\" \\ ü 中"}},
            nlohmann::json::array({nlohmann::json::array({1, 2}), nlohmann::json{{"k", 3}}}),
        };
        for (const nlohmann::json& d : docs)
            QCOMPARE(QString::fromStdString(streamed(d, {})), QString::fromStdString(d.dump(2)));
    }

    void streamedObjectsEqualTheirDom() {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        NamedValues bare{{"S2", "S10", "S1", "S2", "ü\"x", "a/b"}, {1.0, -2.5e-7, nan, 4.0, 1e300, inf}, {}};
        NamedValues withUnits{{"storey 10", "storey 9", "storey 1"}, {3.0, nan, 0.125},
                              {"kN", "kN m", "m"}};
        NamedValues empty{{}, {}, {}};
        nlohmann::json base = {{"final", {{"step", 7}, {"time_s", 0.007}}},
                               {"alarms", nlohmann::json::array()},
                               {"zeta", {{"x", 1}}},
                               {"peak_ground_acceleration_m_s2", 2.5}};
        const std::map<std::string, NamedValues> blocks = {{"/final/displacement_m", bare},
                                                           {"/final/force", withUnits},
                                                           {"/peak_force", withUnits},
                                                           {"/empty", empty}};
        nlohmann::json dom = base;
        for (const auto& [pointer, block] : blocks)
            dom[nlohmann::json::json_pointer(pointer)] = domOf(block);
        // Repeated names: the last value wins, as in the DOM (S2 -> 4.0, not 1.0).
        QCOMPARE(dom.at("final").at("displacement_m").at("S2").get<double>(), 4.0);
        QCOMPARE(QString::fromStdString(streamed(base, blocks)), QString::fromStdString(dom.dump(2)));
        // A streamed pointer that the document already holds is written from its block.
        QCOMPARE(QString::fromStdString(streamed(dom, blocks)), QString::fromStdString(dom.dump(2)));
    }
};

QTEST_APPLESS_MAIN(TestPrettyJson)
#include "TestPrettyJson.moc"
