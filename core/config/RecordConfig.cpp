#include "core/config/RecordConfig.h"

#include "core/config/TestConfig.h"

#include <stdexcept>

namespace hsmu {

std::vector<int> configDofList(const TestConfig& cfg, const std::string& list) {
    std::vector<std::string> dofs, specimens;
    for (const DofSpec& d : cfg.dofs)
        dofs.push_back(d.name);
    for (const ElementSpec& e : cfg.elements)
        if (e.experimental)
            specimens.push_back(e.name);
    return parseDofList(list, dofs, specimens);
}

DofRecording parseRecordSection(const JsonCursor& root, const TestConfig& cfg) {
    DofRecording r;
    if (!root.has("record"))
        return r;
    const JsonCursor c = root.child("record");
    c.requireObject();
    for (const char* key : {"elements", "specimens", "channels", "actuators", "updating", "alarms"})
        if (c.has(key))
            c.fail(key, "not accepted: a specimen's channels (every experimental element's "
                        "commanded, measured and force columns, its actuators and basic DOFs), "
                        "the updating, alarms and holds are always recorded in full at every "
                        "step; \"dofs\" and \"every\" choose and decimate numerical DOFs only");
    c.allowOnly({"dofs", "every"});
    if (c.has("dofs")) {
        const nlohmann::json& v = c.node().at("dofs");
        std::string list;
        if (v.is_string()) {
            list = v.get<std::string>();
        } else if (v.is_array()) {
            for (const nlohmann::json& item : v) {
                if (!item.is_string() && !item.is_number_integer())
                    c.fail("dofs", "expected DOF indices, ranges (\"0-9\") or DOF names");
                list += (list.empty() ? "" : ",") +
                        (item.is_string() ? item.get<std::string>() : item.dump());
            }
        } else {
            c.fail("dofs", "expected a list such as \"0-99,200\" or [0, \"5-9\", \"Roof\"]");
        }
        try {
            r.dofs = configDofList(cfg, list);
        } catch (const std::invalid_argument& e) {
            c.fail("dofs", e.what());
        }
    }
    r.every = c.integer("every", 1, 1, kMaxRecordEvery);
    return r;
}

} // namespace hsmu
