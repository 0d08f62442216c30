#include "python/PyLaw.h"

#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/BoucWenPinching.h"
#include "core/hysteresis/HysteresisLaw.h"
#include "core/hysteresis/LawFactory.h"
#include "core/hysteresis/MaterialDriver.h"
#include "core/hysteresis/MrDamper.h"
#include "python/PyArrays.h"

#include <pybind11/stl.h>

#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <vector>

namespace py = pybind11;

namespace hsmu::python {

namespace {

/// Bouc-Wen's committed hysteretic variable z, or nothing for a law without one.
std::optional<double> committedZ(const HysteresisLaw& law) {
    if (const auto* bw = dynamic_cast<const BoucWen*>(&law))
        return bw->committedState().z;
    if (const auto* pinching = dynamic_cast<const BoucWenPinching*>(&law))
        return pinching->committedState().z;
    if (const auto* mr = dynamic_cast<const MrDamper*>(&law))
        return mr->committedState().z;
    return std::nullopt;
}

std::map<std::string, double> parameterMap(const py::kwargs& kwargs) {
    std::map<std::string, double> params;
    for (const auto& [key, value] : kwargs) {
        const std::string name = py::cast<std::string>(key);
        if (py::isinstance<py::bool_>(value) ||
            (!py::isinstance<py::float_>(value) && !py::isinstance<py::int_>(value)))
            throw py::type_error("parameter '" + name + "': expected a number, got " +
                                 std::string(py::str(py::type::of(value).attr("__name__"))));
        params[name] = py::cast<double>(value);
    }
    return params;
}

class Law {
public:
    Law(const std::string& name, const py::kwargs& kwargs)
        : m_law(makeLaw(name, parameterMap(kwargs))) {}
    explicit Law(std::unique_ptr<HysteresisLaw> law) : m_law(std::move(law)) {}

    std::string name() const { return m_law->lawName(); }

    py::dict parameters() const {
        py::dict d;
        const auto names = m_law->parameterNames();
        for (std::size_t i = 0; i < names.size(); ++i)
            d[py::str(names[i])] = m_law->parameterValue(int(i));
        return d;
    }

    void setParameters(const py::kwargs& kwargs) {
        const auto params = parameterMap(kwargs);
        std::vector<int> indices;
        std::vector<double> values;
        std::vector<std::string> names;
        for (const auto& [name, value] : params) {
            const int index = m_law->parameterIndex(name);
            if (index < 0) {
                std::string known;
                for (const auto& n : m_law->parameterNames())
                    known += (known.empty() ? "" : ", ") + n;
                throw py::value_error(name_() + ": unknown parameter '" + name +
                                      "' (expected one of " + known + ")");
            }
            indices.push_back(index);
            values.push_back(value);
            names.push_back(name);
        }
        const int refused = m_law->setParameterValues(indices, values, true);
        if (refused >= 0)
            throw py::value_error(name_() +
                                  ": the parameter set is not admissible (first "
                                  "refused: '" +
                                  names[std::size_t(refused)] + "')");
    }

    py::object drive(py::handle deformation, py::handle time, bool withTangent, bool withZ) {
        const RealArray d = realVector(deformation, "deformation");
        const std::size_t n = std::size_t(d.size());
        const RealArray t0 = time.is_none() ? newVector(0) : realVector(time, "time");
        if (!time.is_none() && std::size_t(t0.size()) != n)
            throw py::value_error("time: expected " + std::to_string(n) +
                                  " values (one per deformation), got " +
                                  std::to_string(t0.size()));
        for (py::ssize_t i = 1; i < t0.size(); ++i)
            if (!(t0.data()[i] > t0.data()[i - 1]))
                throw py::value_error("time: the time does not increase at point " +
                                      std::to_string(i) + " (time " +
                                      std::string(py::repr(py::float_(t0.data()[i]))) + ")");
        if (time.is_none() && m_law->isRateDependent())
            throw py::value_error(name_() + " is rate-dependent: give time= (one time per "
                                            "point [s]), as a time column for hsmu material");
        if (withZ && !committedZ(*m_law))
            throw py::value_error(name_() + ": this law has no hysteretic variable z");
        RealArray force = newVector(n);
        RealArray tangent = withTangent ? newVector(n) : newVector(0);
        RealArray z = withZ ? newVector(n) : newVector(0);
        const std::span<const double> in(d.data(), n);
        const std::span<double> f(force.mutable_data(), n);
        const std::span<double> t(tangent.mutable_data(), withTangent ? n : 0);
        double* zOut = withZ ? z.mutable_data() : nullptr;
        std::function<void(std::size_t)> afterCommit;
        if (withZ)
            afterCommit = [this, zOut](std::size_t i) { zOut[i] = *committedZ(*m_law); };
        {
            std::unique_lock lock(m_busy, std::try_to_lock);
            if (!lock.owns_lock())
                throw py::value_error(name_() + ": this Law is being driven by another thread");
            py::gil_scoped_release release;
            driveLawInto(*m_law, in, std::span<const double>(t0.data(), std::size_t(t0.size())), f,
                         t, afterCommit);
        }
        if (!withTangent && !withZ)
            return force;
        py::list out;
        out.append(force);
        if (withTangent)
            out.append(tangent);
        if (withZ)
            out.append(z);
        return py::tuple(out);
    }

    void reset() { m_law->revertToStart(); }
    bool rateDependent() const { return m_law->isRateDependent(); }
    std::unique_ptr<Law> copy() const { return std::make_unique<Law>(m_law->clone()); }
    double deformation() const { return m_law->committedDeformation(); }
    double force() const { return m_law->committedForce(); }
    double initialTangent() const { return m_law->initialTangent(); }
    py::object z() const {
        const auto value = committedZ(*m_law);
        return value ? py::object(py::float_(*value)) : py::object(py::none());
    }

    std::string repr() const {
        std::string text = "hsmu.Law('" + name() + "'";
        const auto names = m_law->parameterNames();
        for (std::size_t i = 0; i < names.size(); ++i)
            text += ", " + names[i] + "=" +
                    std::string(py::repr(py::float_(m_law->parameterValue(int(i)))));
        return text + ")";
    }

private:
    std::string name_() const { return m_law->lawName(); }
    std::unique_ptr<HysteresisLaw> m_law;
    std::mutex m_busy;
};

} // namespace

void bindLaw(py::module_& m) {
    m.def("laws", &knownLaws, "The law names hsmu.Law accepts (those of `hsmu material`).");
    py::class_<Law>(m, "Law", R"doc(A uniaxial hysteresis law, as driven by `hsmu material`.

Law(name, **parameters): name is one of hsmu.laws() (case-insensitive; "bouc-wen" also
works); parameters are the law's own (Law(name).parameters lists them with their defaults);
unspecified ones take the defaults. Units are the law's: deformation in its deformation unit
(m or rad), force in its force unit (kN or kN m); Bouc-Wen's uRef and fRef scale them.
Raises ValueError for an unknown law or parameter or an inadmissible value, with the message
`hsmu material` prints; TypeError for a parameter that is not a number.

Example:
    law = hsmu.Law("boucWen", k0=1.0, alpha=0.05)
    force = law.drive(numpy.sin(numpy.linspace(0, 20, 2001)))
)doc")
        .def(py::init<const std::string&, const py::kwargs&>(), py::arg("name"))
        .def_property_readonly("name", &Law::name, "The law's canonical name, e.g. 'boucWen'.")
        .def_property_readonly("parameters", &Law::parameters,
                               "The parameters as a dict {name: value}, in the law's order.")
        .def("set_parameters", &Law::setParameters,
             R"doc(Set parameters by name (judged together: all are applied or none).

The committed state (deformation, z) is kept. Raises ValueError for an unknown name or an
inadmissible set, TypeError for a value that is not a number.)doc")
        .def("drive", &Law::drive, py::arg("deformation"), py::kw_only(),
             py::arg("time") = py::none(), py::arg("tangent") = false, py::arg("z") = false,
             R"doc(Drive the law through a deformation history, point by point (trial, commit),
from its current committed state, exactly as `hsmu material --history` does.

deformation: 1-D array of real numbers [the law's deformation unit], all finite.
time: None or a 1-D array of the same length [s], increasing: required by a rate-dependent
law (rate_dependent; the MR damper), which gets each point's time increment as the time
column of `hsmu material --history` gives it; ignored by the others.
Returns force [the law's force unit] as a float64 array of the same length; with tangent=True
and/or z=True a tuple (force[, tangent][, z]): tangent dF/du [force unit per deformation
unit], z Bouc-Wen's hysteretic variable after each point (normalised deformation units;
ValueError for a law without z). The law stays at the last point (call reset() to start
again). The GIL is released while the law is driven.
Raises TypeError for a non-real dtype, ValueError for a shape other than 1-D or a value that
is not finite, RuntimeError if the law fails to converge (the points before are committed).)doc")
        .def("reset", &Law::reset, "Return to the virgin state (zero deformation and force).")
        .def("copy", &Law::copy, "A deep copy, including the current state.")
        .def("__copy__", &Law::copy)
        .def(
            "__deepcopy__", [](const Law& l, py::handle) { return l.copy(); }, py::arg("memo"))
        .def_property_readonly("deformation", &Law::deformation,
                               "The committed deformation [deformation unit].")
        .def_property_readonly("force", &Law::force, "The committed force [force unit].")
        .def_property_readonly("z", &Law::z,
                               "Bouc-Wen's committed hysteretic variable z, None for other laws.")
        .def_property_readonly(
            "rate_dependent", [](const Law& l) { return l.rateDependent(); },
            "Whether the law needs times (drive(..., time=...)).")
        .def_property_readonly("initial_tangent", &Law::initialTangent,
                               "Tangent of the virgin law at zero deformation [force/deformation].")
        .def("__repr__", &Law::repr);
}

} // namespace hsmu::python
