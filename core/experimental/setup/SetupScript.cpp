#include "core/experimental/setup/SetupScript.h"

#include "core/experimental/setup/Aggregator.h"
#include "core/experimental/setup/FourActuators3d.h"
#include "core/experimental/setup/NoTransformation.h"
#include "core/experimental/setup/PlanarSetups.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

namespace hsmu {

namespace {

// The words of one `expSetup` line after the type, read front to back.
class Words {
public:
    Words(std::vector<std::string> w, std::string type)
        : m_w(std::move(w)), m_type(std::move(type)) {}
    bool done() const { return m_i >= m_w.size(); }
    const std::string& peek() const { return m_w[m_i]; }
    std::string next() { return m_w[m_i++]; }
    const std::string& type() const { return m_type; }
    std::string error;

    bool number(const char* name, double& v) {
        if (done())
            return fail(std::string(name) + " missing");
        const std::string& t = m_w[m_i];
        const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
        if (r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v))
            return fail(std::string(name) + ": '" + t + "' is not a number");
        ++m_i;
        return true;
    }
    bool integer(const char* name, int& v) {
        if (done())
            return fail(std::string(name) + " missing");
        const std::string& t = m_w[m_i];
        const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
        if (r.ec != std::errc() || r.ptr != t.data() + t.size())
            return fail(std::string(name) + ": '" + t + "' is not an integer");
        ++m_i;
        return true;
    }
    /// `-control $tag` / `-ctrl $tag` right after the setup tag: accepted, not used.
    bool optionalControl() {
        if (!done() && (peek() == "-control" || peek() == "-ctrl")) {
            ++m_i;
            int tag = 0;
            return integer("-control tag", tag);
        }
        return true;
    }
    bool fail(const std::string& what) {
        error = m_type + ": " + what;
        return false;
    }

private:
    std::vector<std::string> m_w;
    std::string m_type;
    std::size_t m_i = 0;
};

// -nlGeom, -posAct / -posAct1 (sideOption; "" when the type has none), -phiLocX
bool planarOptions(Words& w, const char* sideOption, SetupGeometry& g, bool& right, double& phi) {
    while (!w.done()) {
        const std::string o = w.next();
        if (o == "-nlGeom") {
            g = SetupGeometry::Exact;
        } else if (*sideOption && o == sideOption) {
            if (w.done() || !parseActuatorSide(w.next(), right))
                return w.fail(o + " wants left, right, l or r");
        } else if (o == "-phiLocX") {
            if (!w.number("-phiLocX", phi))
                return false;
        } else {
            std::string known = std::string("-nlGeom, ") + (*sideOption ? sideOption : "") +
                                (*sideOption ? ", " : "") + "-phiLocX";
            return w.fail("unknown option '" + o + "' (known: " + known + ")");
        }
    }
    return true;
}

bool sizeTrialOut(Words& w, int& size) {
    if (w.done() || w.next() != "-sizeTrialOut")
        return w.fail("-sizeTrialOut $sizeTrial $sizeOut wanted");
    int out = 0;
    if (!w.integer("sizeTrial", size) || !w.integer("sizeOut", out))
        return false;
    if (out != size)
        return w.fail("sizeOut " + std::to_string(out) + " != sizeTrial " + std::to_string(size) +
                      " (HSMU's setups give back as many basic values as they take)");
    return true;
}

std::unique_ptr<ExperimentalSetup> build(Words& w, SetupsByTag& defined) {
    const std::string& type = w.type();
    auto refuse = [&](const std::string& what) {
        w.fail(what);
        return std::unique_ptr<ExperimentalSetup>();
    };
    std::string e;
    std::unique_ptr<ExperimentalSetup> made;
    if (type == "TwoActuators2d") {
        TwoActuators2dParams p;
        if (!w.number("La1", p.La1) || !w.number("La2", p.La2) || !w.number("L", p.L) ||
            !planarOptions(w, "-posAct", p.geometry, p.actuatorsRight, p.phiLocX))
            return nullptr;
        made = makeTwoActuators2d(p, e);
    } else if (type == "ThreeActuators2d" || type == "InvertedVBrace2d" ||
               type == "ChevronBrace2d") {
        ThreeActuators2dParams p;
        if (!w.number("La1", p.La1) || !w.number("La2", p.La2) || !w.number("La3", p.La3) ||
            !w.number("L1", p.L1) || !w.number("L2", p.L2) ||
            !planarOptions(w, "-posAct1", p.geometry, p.horizontalRight, p.phiLocX))
            return nullptr;
        made = makeThreeActuators2d(p, e, type);
    } else if (type == "ThreeActuatorsJntOff2d" || type == "InvertedVBraceJntOff2d") {
        ThreeActuatorsJntOff2dParams p;
        double* L[] = {&p.L1, &p.L2, &p.L3, &p.L4, &p.L5, &p.L6};
        const char* names[] = {"L1", "L2", "L3", "L4", "L5", "L6"};
        if (!w.number("La1", p.La1) || !w.number("La2", p.La2) || !w.number("La3", p.La3))
            return nullptr;
        for (int k = 0; k < 6; ++k)
            if (!w.number(names[k], *L[k]))
                return nullptr;
        if (!planarOptions(w, "-posAct1", p.geometry, p.horizontalRight, p.phiLocX))
            return nullptr;
        made = makeThreeActuatorsJntOff2d(p, e, type);
    } else if (type == "FourActuators3d") {
        FourActuators3dParams p;
        double* v[] = {&p.L1, &p.L2, &p.L3, &p.L4,   &p.a1,   &p.a2,    &p.a3,    &p.a4,
                       &p.h,  &p.h1, &p.h2, &p.arlN, &p.arlS, &p.LrodN, &p.LrodS, &p.Hbeam};
        const char* names[] = {"L1", "L2", "L3", "L4",   "a1",   "a2",    "a3",    "a4",
                               "h",  "h1", "h2", "arlN", "arlS", "LrodN", "LrodS", "Hbeam"};
        for (int k = 0; k < 16; ++k)
            if (!w.number(names[k], *v[k]))
                return nullptr;
        bool unused = false;
        if (!planarOptions(w, "", p.geometry, unused, p.phiLocX))
            return nullptr;
        made = FourActuators3d::create(p, e);
    } else if (type == "OneActuator") {
        int dir = 0, size = 0;
        if (!w.integer("dir", dir) || !sizeTrialOut(w, size))
            return nullptr;
        if (!w.done())
            return refuse("unknown option '" + w.next() + "'");
        made = OneActuator::create(dir, size, e);
    } else if (type == "NoTransformation") {
        if (w.done() || (w.peek() != "-dir" && w.peek() != "-dof"))
            return refuse("-dir $dirs wanted");
        w.next();
        std::vector<int> dirs;
        while (!w.done() && w.peek() != "-sizeTrialOut") {
            int dir = 0;
            if (!w.integer("dir", dir))
                return nullptr;
            dirs.push_back(dir);
        }
        int size = 0;
        if (!sizeTrialOut(w, size))
            return nullptr;
        if (!w.done())
            return refuse("unknown option '" + w.next() + "'");
        made = NoTransformation::create(dirs, size, e);
    } else if (type == "Aggregator") {
        if (w.done() || w.next() != "-setup")
            return refuse("-setup $tags wanted");
        std::vector<int> tags;
        while (!w.done() && w.peek() != "-sizeTrialOut") {
            int tag = 0;
            if (!w.integer("-setup tag", tag))
                return nullptr;
            if (!defined.count(tag))
                return refuse("-setup " + std::to_string(tag) + ": no such setup above");
            tags.push_back(tag);
        }
        int size = 0;
        if (!sizeTrialOut(w, size))
            return nullptr;
        if (!w.done())
            return refuse("unknown option '" + w.next() + "'");
        int sum = 0;
        for (int t : tags)
            sum += defined.at(t)->basicSize();
        if (sum != size)
            return refuse("-sizeTrialOut " + std::to_string(size) + " != " + std::to_string(sum) +
                          ", the sum of the setups' basic sizes");
        std::vector<std::unique_ptr<ExperimentalSetup>> parts;
        for (int t : tags) {
            if (!defined.at(t))
                return refuse("-setup " + std::to_string(t) + " is already in an Aggregator");
            parts.push_back(std::move(defined.at(t)));
        }
        made = Aggregator::create(std::move(parts), e);
    } else {
        return refuse("unknown experimental setup type");
    }
    if (!made)
        w.error = e;
    return made;
}

} // namespace

bool parseSetupScript(const std::string& script, SetupsByTag& out, std::string& error) {
    SetupsByTag defined;
    std::istringstream in(script);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        std::istringstream words(line);
        std::vector<std::string> w;
        for (std::string t; words >> t;)
            w.push_back(t);
        if (w.empty() || w[0][0] == '#')
            continue;
        const std::string where = "line " + std::to_string(number) + ": ";
        if (w[0] != "expSetup" || w.size() < 3) {
            error = where + "'expSetup $type $tag ...' wanted";
            return false;
        }
        Words rest(std::vector<std::string>(w.begin() + 2, w.end()), w[1]);
        int tag = 0;
        {
            Words tagWord({w[2]}, w[1]);
            if (!tagWord.integer("tag", tag)) {
                error = where + tagWord.error;
                return false;
            }
        }
        rest.next(); // the tag
        if (defined.count(tag)) {
            error = where + w[1] + ": tag " + std::to_string(tag) + " already defined";
            return false;
        }
        if (!rest.optionalControl()) {
            error = where + rest.error;
            return false;
        }
        auto setup = build(rest, defined);
        if (!setup) {
            error = where + rest.error;
            return false;
        }
        defined[tag] = std::move(setup);
    }
    for (auto& [tag, setup] : defined)
        if (setup)
            out[tag] = std::move(setup);
    error.clear();
    return true;
}

} // namespace hsmu
