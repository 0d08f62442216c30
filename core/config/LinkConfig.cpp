#include "core/config/LinkConfig.h"

#include "core/config/JsonCursor.h"

#include <filesystem>
#include <fstream>

namespace hsmu {

namespace {

std::array<int, 5> parseSizes(const JsonCursor& c, std::array<int, 5> sizes) {
    c.requireObject();
    c.allowOnly({"disp", "vel", "accel", "force", "time"});
    const char* names[5] = {"disp", "vel", "accel", "force", "time"};
    for (std::size_t i = 0; i < 5; ++i) {
        sizes[i] = c.has(names[i]) ? c.integer(names[i], 0) : 0;
        if (sizes[i] < 0 || sizes[i] > 65536)
            c.fail(names[i], "expected a size in 0..65536");
    }
    return sizes;
}

} // namespace

LinkSpec parseLinkSpec(const JsonCursor& root, const std::string& baseDir) {
    LinkSpec s;
    if (root.has("tls"))
        s.tls = parseTlsSpec(root.child("tls"), baseDir);
    if (!root.has("controller"))
        return s;
    const JsonCursor c = root.child("controller");
    c.requireObject();
    return parseLinkFields(c, baseDir, s);
}

LinkSpec parseLinkFields(const JsonCursor& c, const std::string& baseDir, LinkSpec s) {
    s.protocol = c.string("protocol", s.protocol);
    if (s.protocol != "native" && s.protocol != "simapp" && s.protocol != "generictcp")
        c.fail("protocol", std::string("expected ") + kLinkProtocols);
    for (const char* field : {"connectTimeout", "stepDeadline"}) {
        if (!c.has(field))
            continue;
        const double v = c.number(field, 0.0);
        if (!(v > 0.0 && v <= 600.0))
            c.fail(field, "expected a time in (0, 600] s");
        (std::string(field) == "connectTimeout" ? s.connectTimeout : s.stepDeadline) = v;
    }
    s.dataSize = c.integer("dataSize", s.dataSize);
    if (s.dataSize < 1 || s.dataSize > (1 << 20))
        c.fail("dataSize", "expected a number of doubles in 1..1048576");
    if (c.has("ctrlSizes"))
        s.ctrlSizes = parseSizes(c.child("ctrlSizes"), s.ctrlSizes);
    if (c.has("daqSizes"))
        s.daqSizes = parseSizes(c.child("daqSizes"), s.daqSizes);
    if (s.ctrlSizes[0] < 1 || s.daqSizes[0] < 1 || s.daqSizes[3] < 1)
        c.fail("ctrlSizes", "expected ctrlSizes.disp, daqSizes.disp and daqSizes.force >= 1");
    int ctrl = 1, daq = 0;
    for (std::size_t i = 0; i < 5; ++i) {
        ctrl += s.ctrlSizes[i];
        daq += s.daqSizes[i];
    }
    if (ctrl > s.dataSize || daq > s.dataSize)
        c.fail("dataSize", "expected at least 1 + the ctrl sizes (" + std::to_string(ctrl) +
                               ") and the daq sizes (" + std::to_string(daq) + ")");
    if (c.has("initFile")) {
        if (s.protocol != "generictcp")
            c.fail("initFile", "only used with \"protocol\": \"generictcp\"");
        std::filesystem::path p = c.string("initFile");
        if (p.is_relative() && !baseDir.empty())
            p = std::filesystem::path(baseDir) / p;
        s.initFile = p.string();
        std::ifstream in(p);
        if (!in)
            c.fail("initFile", "a readable text file (cannot open " + s.initFile + ")");
        for (std::string line; std::getline(in, line);) {
            if (!line.empty() && line.back() == '\r')
                line.pop_back();
            if (line.size() > 16384)
                c.fail("initFile", "lines of at most 16384 bytes");
            s.initLines.push_back(line);
        }
    }
    return s;
}

} // namespace hsmu
