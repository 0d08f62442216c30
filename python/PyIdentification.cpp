#include "python/PyIdentification.h"

#include "core/config/ConfigLoader.h"
#include "core/identification/CalibrationDefaults.h"
#include "core/offline/IdentificationSettings.h"
#include "core/offline/MeasuredDataCsv.h"
#include "core/offline/OfflineIdentification.h"
#include "core/offline/OfflineIdentificationReport.h"
#include "core/record/RecordReader.h"
#include "python/PyArrays.h"
#include "python/PyInterrupt.h"
#include "python/PyJson.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>

namespace py = pybind11;

namespace hsmu::python {

namespace {

constexpr const char* kSource = "arrays";

MeasuredDataUnits unitsOf(py::handle units) {
    if (py::isinstance<py::str>(units))
        return parseMeasuredDataUnits(units.cast<std::string>());
    if (py::isinstance<py::tuple>(units) || py::isinstance<py::list>(units)) {
        const auto parts = units.cast<std::vector<py::object>>();
        if (parts.size() == 3 && std::all_of(parts.begin(), parts.end(), [](const py::object& p) {
                return py::isinstance<py::str>(p);
            }))
            return {parts[0].cast<std::string>(), parts[1].cast<std::string>(),
                    parts[2].cast<std::string>()};
    }
    throw py::type_error("units: expected 'TIME,DEFORMATION,FORCE' such as 's,mm,kN' or a tuple "
                         "of three strings");
}

SpecimenHistory historyOf(py::handle time, py::handle deformation, py::handle force,
                          py::handle units) {
    const RealArray t = realVector(time, "time");
    const RealArray d = realVector(deformation, "deformation");
    const RealArray f = realVector(force, "force");
    if (t.size() != d.size() || t.size() != f.size())
        throw py::value_error("time, deformation and force must have the same length (" +
                              std::to_string(t.size()) + ", " + std::to_string(d.size()) + ", " +
                              std::to_string(f.size()) + ")");
    const MeasuredDataScales s = measuredDataScales(unitsOf(units));
    SpecimenHistory h;
    h.source = kSource;
    h.deformationUnits = s.deformationUnits;
    h.forceUnits = s.forceUnits;
    const auto n = std::size_t(t.size());
    h.time.resize(n);
    h.deformation.resize(n);
    h.force.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        h.time[i] = t.data()[i] * s.time;
        h.deformation[i] = d.data()[i] * s.deformation;
        h.force[i] = f.data()[i] * s.force;
    }
    if (const std::string why = h.problem(); !why.empty())
        throw py::value_error(h.source + ": " + why);
    return h;
}

/// The settings of `hsmu replay --import DATA --config OVERRIDE --method METHOD`: the defaults
/// for imported data with the override {"model": {"law": law, **model}, "updating": ...}.
IdentificationSettings settingsOf(const SpecimenHistory& h, const std::optional<std::string>& law,
                                  py::handle model, py::handle updating,
                                  const std::string& method) {
    nlohmann::json override = nlohmann::json::object();
    if (law || !model.is_none()) {
        nlohmann::json m = model.is_none() ? nlohmann::json::object() : toJson(model, "model");
        if (!m.is_object())
            throw py::type_error("model: expected a dict of initial parameters");
        if (law)
            m["law"] = *law;
        else if (!m.contains("law")) // model alone: the default law's initial parameters
            m["law"] = defaultIdentificationSettings().model.law;
        override["model"] = m;
    }
    if (!updating.is_none())
        override["updating"] = toJson(updating, "updating");
    IdentificationSettings s =
        withOverride(defaultIdentificationSettings(), override, "hsmu (Python)", method);
    s.dt = h.meanStep() > 0.0 ? h.meanStep() : s.dt;
    s.online = method != "calibration";
    return s;
}

OfflineIdentificationResult identify(const SpecimenHistory& h, IdentificationSettings s,
                                     py::handle progress) {
    std::atomic<bool> cancel{false};
    s.cancel = &cancel;
    OfflineProgressCallback tell;
    if (!progress.is_none()) {
        py::function callback = progress.cast<py::function>();
        tell = [callback](const OfflineProgress& p) {
            py::gil_scoped_acquire acquire;
            py::dict d;
            d["phase"] = p.phase;
            d["samples_done"] = p.samplesDone;
            d["samples"] = p.samples;
            d["refits"] = p.refits;
            d["rejected"] = p.rejected;
            d["elapsed_s"] = p.elapsedSeconds;
            callback(d);
        };
    }
    OfflineIdentificationResult r;
    runInterruptible(
        [&] {
            const auto started = std::chrono::steady_clock::now();
            r = identifyOffline(h, s, tell);
            if (tell) { // the end, so that a progress bar reaches 100 %
                OfflineProgress p;
                p.phase = "done";
                p.samplesDone = p.samples = h.size();
                p.refits = r.refits;
                p.rejected = r.estimatorWarnings;
                p.elapsedSeconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - started)
                        .count();
                tell(p);
            }
        },
        [&] { cancel = true; });
    return r;
}

py::dict unitsDict(const SpecimenHistory& h, const IdentificationSettings& s,
                   const std::vector<std::string>& names) {
    py::dict units;
    units["time"] = "s";
    units["deformation"] = h.deformationUnits;
    units["force"] = h.forceUnits;
    for (const auto& name : names)
        units[py::str(name)] = parameterUnit(s.model.law, name, h.deformationUnits, h.forceUnits);
    return units;
}

py::dict calibrate(py::handle time, py::handle deformation, py::handle force, py::handle units,
                   const std::optional<std::string>& law, py::handle model, py::handle progress,
                   const std::string& offsets) {
    const auto mode = calibrationOffsetsFromName(offsets);
    if (!mode) // `hsmu replay --offsets`'s message
        throw py::value_error("offsets: expected auto, on or off, found '" + offsets + "'");
    const SpecimenHistory h = historyOf(time, deformation, force, units);
    IdentificationSettings s = settingsOf(h, law, model, py::none(), "calibration");
    s.offsets = *mode;
    const OfflineIdentificationResult r = identify(h, s, progress);
    py::dict out = toPython(calibrationJson(*r.calibration));
    out["law"] = s.model.law;
    out["verdict"] = r.verdict;
    out["units"] = unitsDict(h, s, r.parameterNames);
    // The offsets kept, each as its parameter (value, stddev, ci95) with its unit.
    if (out.contains("offsets") && out["offsets"]["used"].cast<bool>()) {
        py::dict parameters = out["parameters"];
        py::dict unitsOut = out["units"];
        for (const char* name : {"deformationOffset", "forceOffset"})
            if (parameters.contains(name)) {
                py::dict p = parameters[name].attr("copy")();
                p["unit"] = unitsOut.contains(name) ? unitsOut[name] : py::str("");
                out["offsets"][name] = p;
            }
    }
    return out;
}

py::dict resultDict(const SpecimenHistory& h, const IdentificationSettings& s,
                    const OfflineIdentificationResult& r) {
    const auto n = std::size_t(h.size());
    const auto column = [n](const Eigen::MatrixXd& m, Eigen::Index j) {
        RealArray a = newVector(n);
        for (std::size_t k = 0; k < n; ++k)
            a.mutable_data()[k] = m(Eigen::Index(k), j);
        return a;
    };
    const auto vector = [n](const std::vector<double>& v) {
        RealArray a = newVector(n);
        std::copy(v.begin(), v.end(), a.mutable_data());
        return a;
    };
    py::dict out;
    out["method"] = r.method;
    out["law"] = s.model.law;
    out["time"] = vector(h.time);
    out["deformation"] = vector(h.deformation);
    out["force"] = vector(h.force);
    RealArray aux = newVector(n), fit = newVector(n);
    std::copy(r.auxiliaryForce.data(), r.auxiliaryForce.data() + n, aux.mutable_data());
    std::copy(r.fitError.data(), r.fitError.data() + n, fit.mutable_data());
    out["auxiliary_force"] = aux;
    out["fit_error"] = fit;
    py::dict params, stddev;
    for (std::size_t j = 0; j < r.parameterNames.size(); ++j) {
        params[py::str(r.parameterNames[j])] = column(r.parameters, Eigen::Index(j));
        stddev[py::str(r.parameterNames[j])] = column(r.stddev, Eigen::Index(j));
    }
    out["parameters"] = params;
    out["stddev"] = stddev;
    out["initial"] = r.initial;
    out["final"] = r.finalEstimate;
    out["final_stddev"] = r.finalStddev;
    out["final_nrmse"] = r.finalNrmse;
    out["initial_nrmse"] = r.initialNrmse;
    out["auxiliary_nrmse"] = r.auxiliaryNrmse;
    out["refits"] = r.refits;
    out["estimator_warnings"] = r.estimatorWarnings;
    out["messages"] = r.messages;
    out["calibration"] = r.calibration && r.calibration->ok
                             ? py::object(toPython(calibrationJson(*r.calibration)))
                             : py::object(py::none());
    out["verdict"] = r.verdict;
    out["units"] = unitsDict(h, s, r.parameterNames);
    return out;
}

py::dict identifyArrays(py::handle time, py::handle deformation, py::handle force, py::handle units,
                        const std::string& method, const std::optional<std::string>& law,
                        py::handle model, py::handle updating, py::handle progress) {
    const SpecimenHistory h = historyOf(time, deformation, force, units);
    const IdentificationSettings s = settingsOf(h, law, model, updating, method);
    return resultDict(h, s, identify(h, s, progress));
}

/// `hsmu replay FILE.h5 --identify [--method M] [--specimen S] [--config OVERRIDE]`.
py::dict identifyRecord(const std::filesystem::path& path, const std::string& method,
                        const std::string& specimen, py::handle model, py::handle updating,
                        py::handle progress) {
    const std::string source = path.string();
    std::unique_ptr<RecordReader> opened;
    {
        py::gil_scoped_release release;
        opened = std::make_unique<RecordReader>(source);
    }
    const RecordReader& reader = *opened;
    const TestConfig cfg =
        parseConfig(nlohmann::json::parse(reader.data().meta.configuration), source);
    IdentificationSettings s = identificationSettingsFrom(cfg, specimen);
    const SpecimenHistory h = historyFromRecord(reader.data(), s.specimen, source);
    nlohmann::json override = nlohmann::json::object();
    if (!model.is_none())
        override["model"] = toJson(model, "model");
    if (!updating.is_none())
        override["updating"] = toJson(updating, "updating");
    if (!override.empty())
        s = withOverride(s, override, "hsmu (Python)", method);
    else if (!method.empty())
        s = withMethod(s, method);
    s.online = !(method == "calibration" || (method.empty() && calibrationOnlyByDefault(s)));
    return resultDict(h, s, identify(h, s, progress));
}

py::dict readMeasured(const std::filesystem::path& path, py::handle units, py::handle columns) {
    MeasuredDataOptions o;
    if (!units.is_none())
        o.units = unitsOf(units);
    if (!columns.is_none())
        o.columns = parseMeasuredDataColumns(columns.cast<std::string>());
    SpecimenHistory h;
    {
        py::gil_scoped_release release;
        h = readMeasuredDataCsv(path.string(), o);
    }
    py::dict out;
    const auto n = std::size_t(h.size());
    for (const auto& [key, v] :
         {std::pair{"time", &h.time}, std::pair{"deformation", &h.deformation},
          std::pair{"force", &h.force}}) {
        RealArray a = newVector(n);
        std::copy(v->begin(), v->end(), a.mutable_data());
        out[key] = a;
    }
    out["units"] = py::make_tuple("s", h.deformationUnits, h.forceUnits);
    out["source"] = h.source;
    return out;
}

} // namespace

void bindIdentification(py::module_& m) {
    m.def("calibrate", &calibrate, py::arg("time"), py::arg("deformation"), py::arg("force"),
          py::kw_only(), py::arg("units") = "s,m,kN", py::arg("law") = py::none(),
          py::arg("model") = py::none(), py::arg("progress") = py::none(),
          py::arg("offsets") = "auto",
          R"doc(Fit a hysteresis law to a measured history over the whole history, as
`hsmu replay --import DATA --units U --method calibration --offsets OFFSETS` does (the same
code).

time, deformation, force: 1-D arrays of equal length, finite, time increasing; in `units`
("TIME,DEFORMATION,FORCE", e.g. "s,mm,kN", or a tuple of three strings; time s, ms or step
for a sample index; deformation m, cm, mm, in, ft, rad, mrad, deg; force N, kN, MN, lbf, kip,
kgf, tonf, g, or a moment such as kN*m with a rotation). They are converted to the console's
units (s; m or rad; kN or kN m) as a CSV import is.
law: "boucWen" (the default), "boucWenPinching", "mrDamper", "bilinear" or "elastic"; model: a dict of
initial parameters (e.g. {"uRef": 0.02, "fRef": 40}), as the "model" of --config.

Returns a dict shaped like summary.json's "calibration": "parameters" {name: {"value",
"onBound", "stddev", "ci95": [lo, hi] (95 % interval), "correlation" {name: r}}}, "model"
(every parameter of the fitted law), "nrmse", "rmsError" [force unit], "starts", "replays",
"seconds"; plus "law", "verdict" ("" or why the law cannot represent the specimen) and
"units" (of the data and of each parameter; Bouc-Wen's are normalised by uRef / fRef).
offsets: "auto" (the default, as the command's: a deformation and a force offset fitted and
kept when the data ask for them, docs/method.md "Offsets"), "on" (always kept) or "off" (not
fitted); any other value raises ValueError. When the offset fit ran, "offsets" holds "used",
"nrmseWithout", "nrmseWith", "branches" and "criterion", and when kept also
"deformationOffset" and "forceOffset" ({"value", "stddev", "ci95", "onBound", "unit"}; they
are among "parameters" and "model" too).
progress: None or a callable given a dict {"phase", "samples_done", "samples", "refits",
"rejected", "elapsed_s"} (from a worker thread, with the GIL held) before each phase and
every 64 samples of an online pass, and once with phase "done" at the end; an exception it
raises ends the call with it.
The GIL is released; Ctrl+C stops the calibration and raises KeyboardInterrupt.
Raises ValueError for bad arrays or units (the messages of `hsmu replay`), TypeError for a
wrong dtype.)doc");
    m.def("identify", &identifyArrays, py::arg("time"), py::arg("deformation"), py::arg("force"),
          py::kw_only(), py::arg("units") = "s,m,kN", py::arg("method") = "ukf",
          py::arg("law") = py::none(), py::arg("model") = py::none(),
          py::arg("updating") = py::none(), py::arg("progress") = py::none(),
          R"doc(Identify a law sample by sample as the online identifier would, as
`hsmu replay --import DATA --units U --method METHOD` does (the same code).

Arguments as hsmu.calibrate; method "ukf" or "nelder-mead"; updating: a dict merged into the
default updating section (bounds, ukf, nelderMead, inspector; docs/configuration.md).
Returns a dict: "time", "deformation", "force" (console units), "parameters" and "stddev"
({name: array}, the estimate after each sample), "auxiliary_force" (the prediction with the
estimate known before each sample) and "fit_error" (arrays); "initial", "final",
"final_stddev" ({name: value}); "final_nrmse", "initial_nrmse", "auxiliary_nrmse", "refits",
"estimator_warnings", "messages", "calibration" (as hsmu.calibrate's, or None), "verdict",
"method", "law", "units". The GIL is released; Ctrl+C stops and raises KeyboardInterrupt.)doc");
    m.def("identify_record", &identifyRecord, py::arg("path"), py::kw_only(),
          py::arg("method") = "", py::arg("specimen") = "", py::arg("model") = py::none(),
          py::arg("updating") = py::none(), py::arg("progress") = py::none(),
          R"doc(Identify a recorded specimen again, as `hsmu replay FILE.h5 --identify
[--method M] [--specimen S]` does (the same code): the record's configuration gives the
model and the updating settings; model / updating (dicts) override them as --config does.
method: "" (the record's own; only the calibration for a pinching model without one), "ukf",
"nelder-mead" or "calibration". specimen: "" for the updating specimen (else the only
experimental element). Returns the dict of hsmu.identify. Raises OSError for a bad record,
ValueError for settings the method cannot use.)doc");
    m.def("read_measured", &readMeasured, py::arg("path"), py::kw_only(),
          py::arg("units") = py::none(), py::arg("columns") = py::none(),
          R"doc(Read a measured history file as `hsmu replay --import` does (CSV or text with a
header naming the columns and their units, docs/units.md): {"time", "deformation", "force"}
as arrays in the console's units, "units" (s, m or rad, kN or kN m) and "source".
units: "TIME,DEFORMATION,FORCE" replacing the header's; columns: "T,D,F" positions from 1.
Raises ValueError with the program's message (file and line) for bad content.)doc");
}

} // namespace hsmu::python
