#include "python/PyRecord.h"

#include "core/record/RecordColumns.h"
#include "core/record/RecordReader.h"
#include "python/PyArrays.h"
#include "python/PyJson.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <memory>

namespace py = pybind11;

namespace hsmu::python {

namespace {

/// Every per-step dataset once: step, time, then the columns of `hsmu export --csv`'s tables
/// (core/record/RecordColumns.h), with their names and units.
std::vector<RecordColumn> columnsOf(const RecordData& r) {
    std::vector<RecordColumn> c{stepColumn(), timeColumn()};
    for (RecordTable& table : recordTables(r))
        for (RecordColumn& column : table.columns)
            c.push_back(std::move(column));
    return c;
}

class Record {
public:
    explicit Record(const std::filesystem::path& path) {
        py::gil_scoped_release release;
        m_reader = std::make_unique<RecordReader>(path.string());
        m_columns = columnsOf(m_reader->data());
    }

    const RecordData& d() const { return m_reader->data(); }

    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const RecordColumn& c : m_columns)
            out.push_back(c.name);
        return out;
    }

    py::dict units() const {
        py::dict out;
        for (const RecordColumn& c : m_columns)
            out[py::str(c.name)] = c.unit;
        return out;
    }

    RealArray column(const std::string& name) const {
        for (const RecordColumn& c : m_columns) {
            if (c.name != name)
                continue;
            const auto n = std::size_t(c.dofRows ? d().dofRows() : d().rows());
            RealArray a = newVector(n);
            double* out = a.mutable_data();
            py::gil_scoped_release release; // the values are the reader's, not Python's
            for (std::size_t i = 0; i < n; ++i)
                out[i] = c.value(d(), Eigen::Index(i));
            return a;
        }
        const auto& dofs = d().layout.dofNames; // a DOF the run chose not to record
        for (const char* kind : {"u ", "v ", "a "})
            if (name.rfind(kind, 0) == 0)
                if (const auto it = std::find(dofs.begin(), dofs.end(), name.substr(2));
                    it != dofs.end())
                    throw py::key_error(m_reader->path() + ": '" + name +
                                        "': " + d().dofNotRecorded(int(it - dofs.begin())));
        throw py::key_error(m_reader->path() + ": no dataset '" + name +
                            "' (Record.names lists them)");
    }

    /// The step or time of each row of the DOF datasets (those of every row unless the run
    /// chose or decimated its DOFs).
    RealArray dofRowValues(bool time) const {
        RealArray a = newVector(std::size_t(d().dofRows()));
        double* out = a.mutable_data();
        for (int k = 0; k < d().dofRows(); ++k)
            out[k] = time ? d().dofTime(k) : double(d().dofStep(k));
        return a;
    }

    std::vector<std::string> recordedDofs() const {
        std::vector<std::string> out;
        for (Eigen::Index j = 0; j < d().u.cols(); ++j)
            out.push_back(d().layout.dofNames[std::size_t(d().dofIndex(int(j)))]);
        return out;
    }

    py::dict data() const {
        py::dict out;
        for (const RecordColumn& c : m_columns)
            out[py::str(c.name)] = column(c.name);
        return out;
    }

    py::dict metadata() const {
        const RecordMetadata& m = d().meta;
        py::dict out;
        out["schema_version"] = m.schemaVersion;
        out["program"] = m.program;
        out["program_version"] = m.programVersion;
        out["start_time"] = m.startTime;
        out["config_name"] = m.configName;
        out["operator_notes"] = m.operatorNotes;
        out["dt"] = m.dt;
        out["run"] = m.run;
        out["numerics"] = m.numerics;
        return out;
    }

    py::object configuration() const {
        try {
            return toPython(nlohmann::json::parse(d().meta.configuration));
        } catch (const nlohmann::json::exception& e) {
            throw py::value_error(m_reader->path() + ": the recorded configuration is not JSON (" +
                                  e.what() + ")");
        }
    }

    py::list alarms() const {
        py::list out;
        for (const Alarm& a : d().alarms) {
            py::dict x;
            x["time"] = a.time;
            x["step"] = a.step;
            x["severity"] = alarmSeverityName(a.severity);
            x["kind"] = alarmKindName(a.kind);
            x["message"] = a.message;
            x["code"] = a.code;
            x["args"] = a.args;
            out.append(x);
        }
        return out;
    }

    py::list events() const {
        py::list out;
        const std::vector<std::string> params =
            d().layout.updating ? d().layout.updating->parameters : std::vector<std::string>{};
        for (const RecordedUpdate& u : d().updateEvents) {
            py::dict x, values;
            x["step"] = u.step;
            x["time"] = u.time;
            x["element"] = u.element;
            for (std::size_t j = 0; j < u.values.size() && j < params.size(); ++j)
                values[py::str(params[j])] = u.values[j];
            x["values"] = values;
            x["decision"] = u.decision;
            x["proposal"] = u.proposal;
            out.append(x);
        }
        return out;
    }

    py::list notes() const {
        py::list out;
        for (const RecordNote& n : d().notes) {
            py::dict x;
            x["time"] = n.time;
            x["step"] = n.step;
            x["text"] = n.text;
            out.append(x);
        }
        return out;
    }

    py::list elements() const {
        py::list out;
        for (const ElementInfo& e : d().layout.elements) {
            py::dict x;
            x["name"] = e.name;
            x["type"] = e.type;
            x["experimental"] = e.experimental;
            x["nonlinear"] = e.nonlinear;
            x["deformation_unit"] = e.units.deformation;
            x["force_unit"] = e.units.force;
            out.append(x);
        }
        return out;
    }

    py::object updating() const {
        if (!d().layout.updating)
            return py::none();
        const UpdatingInfo& u = *d().layout.updating;
        py::dict x;
        x["specimen"] = u.specimen;
        x["method"] = u.method;
        x["parameters"] = u.parameters;
        return x;
    }

    int refresh() {
        int added = 0;
        {
            py::gil_scoped_release release;
            added = m_reader->refresh();
        }
        m_columns = columnsOf(d());
        return added;
    }

    int rows() const { return d().rows(); }
    bool swmr() const { return m_reader->swmr(); }
    std::string path() const { return m_reader->path(); }
    std::vector<std::string> sites() const { return d().layout.sites; }
    /// {site: security} (the record's /sites `security`); None for each site of a record
    /// written before it was kept.
    py::dict siteSecurity() const {
        const auto& sites = d().layout.sites;
        const auto& security = d().meta.siteSecurity;
        py::dict out;
        for (std::size_t i = 0; i < sites.size(); ++i)
            out[py::str(sites[i])] = i < security.size() && !security[i].empty()
                                         ? py::object(py::str(security[i]))
                                         : py::object(py::none());
        return out;
    }
    std::vector<std::string> dofs() const { return d().layout.dofNames; }

private:
    std::unique_ptr<RecordReader> m_reader;
    std::vector<RecordColumn> m_columns;
};

} // namespace

void bindRecord(py::module_& m) {
    py::class_<Record>(m, "Record", R"doc(A run record (record.h5, docs/recording.md), read with the
program's own reader: no h5py needed. A record that a running test is still writing is opened
in SWMR mode and refresh() reads the rows flushed since.

Per-step datasets are 1-D float64 arrays named as `hsmu export --csv` names its columns:
"step", "time", "ground_acceleration", "u <dof>", "v <dof>", "a <dof>", "<element>
deformation", "<element> force", "<element> commanded", "<specimen> actuator commanded" ...,
"<site> round trip", and with online updating "<parameter>", "stddev <parameter>",
"auxiliary_force", "fit_error", ... Record.names lists them, Record.units gives each one's
unit ("[-]" dimensionless: "-"; "" for counts), record[name] returns one, record.data all.
Raises OSError with the program's message for a missing, foreign or damaged file. A run
that chose or decimated its numerical DOFs (hsmu run --record-dofs / --record-every, the
configuration's "record" block) has "u/v/a <dof>" datasets of the DOFs it kept only, one
value per row of dof_steps / dof_time; a DOF it did not keep raises KeyError naming the DOF
and the option.

Example:
    rec = hsmu.Record("out/paper-condition-3/record.h5")
    t, F = rec["time"], rec["specimen force"]
)doc")
        .def(py::init<const std::filesystem::path&>(), py::arg("path"))
        .def_property_readonly("path", &Record::path, "The file.")
        .def_property_readonly("rows", &Record::rows, "Rows read (row 0: the initial state).")
        .def("__len__", &Record::rows)
        .def_property_readonly("swmr", &Record::swmr, "Whether the file was opened in SWMR mode.")
        .def_property_readonly("names", &Record::names, "The per-step datasets' names, in order.")
        .def_property_readonly("units", &Record::units, "{name: unit} of every dataset.")
        .def("__getitem__", &Record::column, py::arg("name"),
             "One dataset as a float64 array of `rows` values; KeyError naming the file if absent.")
        .def("__contains__",
             [](const Record& r, const std::string& name) {
                 const auto n = r.names();
                 return std::find(n.begin(), n.end(), name) != n.end();
             })
        .def_property_readonly("data", &Record::data, "Every dataset: {name: array}.")
        .def_property_readonly("metadata", &Record::metadata,
                               "Run metadata: schema_version, program, program_version, "
                               "start_time, config_name, operator_notes, dt [s], run, numerics.")
        .def_property_readonly("configuration", &Record::configuration,
                               "The run's configuration as a dict (its JSON shape).")
        .def_property_readonly("alarms", &Record::alarms,
                               "Alarms in the order raised: dicts of time [s], step, severity, "
                               "kind, message, code, args.")
        .def_property_readonly("events", &Record::events,
                               "Update events (/updating/events): dicts of step, time [s], "
                               "element, values {parameter: value}, decision, proposal.")
        .def_property_readonly("notes", &Record::notes,
                               "Operator notes: dicts of time [s], step, text.")
        .def_property_readonly("elements", &Record::elements,
                               "Elements: dicts of name, type, experimental, nonlinear, "
                               "deformation_unit, force_unit.")
        .def_property_readonly("sites", &Record::sites, "The sites of the experimental elements.")
        .def_property_readonly("site_security", &Record::siteSecurity,
                               "How the console reached each site: {site: \"tls\", "
                               "\"plaintext-loopback\", \"insecure-plaintext\" or \"builtin\"}; "
                               "None for a site of a record written before it was kept "
                               "(docs/security.md).")
        .def_property_readonly("dofs", &Record::dofs, "The DOF names.")
        .def_property_readonly("recorded_dofs", &Record::recordedDofs,
                               "The DOFs whose u, v, a the record holds (all of `dofs` unless "
                               "the run chose some: hsmu run --record-dofs, record.dofs).")
        .def_property_readonly(
            "record_every", [](const Record& r) { return r.d().meta.dofRecording.every; },
            "The stride of the DOF datasets' rows (1: every step; hsmu run --record-every).")
        .def_property_readonly(
            "dof_steps", [](const Record& r) { return r.dofRowValues(false); },
            "The step of each row of the \"u/v/a <dof>\" datasets (float64; the \"step\" "
            "dataset's unless the run decimated its DOFs).")
        .def_property_readonly(
            "dof_time", [](const Record& r) { return r.dofRowValues(true); },
            "The test time [s] of each row of the \"u/v/a <dof>\" datasets.")
        .def_property_readonly("updating", &Record::updating,
                               "None, or {specimen, method, parameters} of online updating.")
        .def("refresh", &Record::refresh,
             "Read rows and alarms a running test flushed since; returns the number of new rows.")
        .def("__repr__", [](const Record& r) {
            return "hsmu.Record('" + r.path() + "', rows=" + std::to_string(r.rows()) + ")";
        });
}

} // namespace hsmu::python
