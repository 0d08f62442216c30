#include "core/config/SetupConfig.h"

#include "core/experimental/setup/SetupScript.h"

#include <charconv>
#include <vector>

namespace hsmu {

namespace {

struct SetupType {
    const char* type;
    std::vector<const char*> lengths; ///< in OpenFresco's order
    const char* side;                 ///< "posAct", "posAct1" or "" (none)
};

const std::vector<SetupType>& planarTypes() {
    static const std::vector<const char*> three{"La1", "La2", "La3", "L1", "L2"};
    static const std::vector<const char*> jntOff{"La1", "La2", "La3", "L1", "L2",
                                                 "L3",  "L4",  "L5",  "L6"};
    static const std::vector<SetupType> types{
        {"TwoActuators2d", {"La1", "La2", "L"}, "posAct"},
        {"ThreeActuators2d", three, "posAct1"},
        {"InvertedVBrace2d", three, "posAct1"},
        {"ChevronBrace2d", three, "posAct1"},
        {"ThreeActuatorsJntOff2d", jntOff, "posAct1"},
        {"InvertedVBraceJntOff2d", jntOff, "posAct1"},
        {"FourActuators3d",
         {"L1", "L2", "L3", "L4", "a1", "a2", "a3", "a4", "h", "h1", "h2", "arlN", "arlS", "LrodN",
          "LrodS", "Hbeam"},
         ""},
    };
    return types;
}

std::string word(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v); // shortest that reads back the same
    return std::string(buf, r.ptr);
}

void allowOnly(const JsonCursor& c, const std::vector<std::string>& keys) {
    for (const auto& [key, value] : c.node().items()) {
        bool known = false;
        for (const std::string& k : keys)
            known = known || k == key;
        if (!known) {
            std::string list;
            for (const std::string& k : keys)
                list += (list.empty() ? "" : ", ") + k;
            c.fail(key, c.string("type") + ": unknown parameter (known: " + list + ")");
        }
    }
}

// The line of a setup that is not an Aggregator, without "expSetup <type> <tag>".
std::string leafWords(const JsonCursor& c, const std::string& type,
                      std::vector<std::string>& keys) {
    std::string w;
    for (const SetupType& t : planarTypes()) {
        if (type != t.type)
            continue;
        for (const char* k : t.lengths) {
            if (!c.has(k))
                c.fail(k, type + ": " + k + " missing");
            w.append(1, ' ').append(word(c.number(k)));
            keys.push_back(k);
        }
        if (c.boolean("nlGeom", false))
            w += " -nlGeom";
        if (*t.side && c.has(t.side))
            w += std::string(" -") + t.side + " " + c.string(t.side);
        if (c.has("phiLocX"))
            w += " -phiLocX " + word(c.number("phiLocX"));
        keys.insert(keys.end(), {"nlGeom", "phiLocX"});
        if (*t.side)
            keys.push_back(t.side);
        return w;
    }
    if (type != "OneActuator" && type != "NoTransformation")
        c.fail("type", "unknown experimental setup type '" + type +
                           "' (known: TwoActuators2d, ThreeActuators2d, ThreeActuatorsJntOff2d, "
                           "InvertedVBrace2d, InvertedVBraceJntOff2d, ChevronBrace2d, "
                           "FourActuators3d, OneActuator, NoTransformation, Aggregator)");
    keys.insert(keys.end(), {"dir", "sizeTrial"});
    for (const char* k : {"sizeTrial", "dir"})
        if (!c.has(k))
            c.fail(k, type + ": " + k + " missing");
    const int size = c.integer("sizeTrial", 0, 1, 1000);
    if (type == "OneActuator") {
        w += " " + std::to_string(c.integer("dir", 0, 1, size));
    } else {
        const JsonCursor d = c.child("dir");
        d.requireArray();
        w += " -dir";
        for (std::size_t i = 0; i < d.size(); ++i)
            w.append(1, ' ').append(std::to_string(d.checkedInteger(d.node()[i], "", 1, size)));
    }
    return w + " -sizeTrialOut " + std::to_string(size) + " " + std::to_string(size);
}

// The script's error "line N: <type>: <parameter> ..." on the field it names (else "type").
[[noreturn]] void failOn(const JsonCursor& c, const std::string& type, std::string error,
                         const std::vector<std::string>& keys) {
    if (error.rfind("line ", 0) == 0 && error.find(": ") != std::string::npos)
        error.erase(0, error.find(": ") + 2);
    std::string field = "type";
    if (error.rfind(type + ": ", 0) == 0) {
        const std::string rest = error.substr(type.size() + 2);
        const std::string first = rest.substr(0, rest.find_first_of(" :,"));
        for (const std::string& k : keys)
            if (first == k || first == "-" + k)
                field = k;
    }
    c.fail(field, error);
}

// Appends c's line(s) to script with tags from nextTag on; returns c's tag and sets its size.
int appendSetup(const JsonCursor& c, std::string& script, int& nextTag, int& basicSize) {
    c.requireObject();
    const std::string type = c.string("type");
    std::vector<std::string> keys{"type"};
    std::string words;
    if (type == "Aggregator") {
        keys.push_back("setups");
        allowOnly(c, keys);
        const JsonCursor parts = c.child("setups");
        parts.requireArray();
        if (parts.size() == 0)
            c.fail("setups", "Aggregator: no setups");
        std::string tags;
        basicSize = 0;
        for (std::size_t i = 0; i < parts.size(); ++i) {
            int size = 0;
            tags.append(1, ' ').append(
                std::to_string(appendSetup(parts.at(i), script, nextTag, size)));
            basicSize += size;
        }
        words = " -setup" + tags + " -sizeTrialOut " + std::to_string(basicSize) + " " +
                std::to_string(basicSize);
    } else {
        words = leafWords(c, type, keys);
        allowOnly(c, keys);
    }
    const int tag = nextTag++;
    const std::string line = "expSetup " + type + " " + std::to_string(tag) + words + "\n";
    SetupsByTag built;
    std::string error;
    if (!parseSetupScript(script + line, built, error))
        failOn(c, type, error, keys);
    basicSize = built.at(tag)->basicSize();
    script += line;
    return tag;
}

} // namespace

std::string setupScriptOf(const JsonCursor& c) {
    std::string script;
    int nextTag = 1, size = 0;
    appendSetup(c, script, nextTag, size);
    return script;
}

} // namespace hsmu
