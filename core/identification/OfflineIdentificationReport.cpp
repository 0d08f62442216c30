#include "core/identification/OfflineIdentificationReport.h"

#include "core/record/CsvFile.h"
#include "core/record/CsvText.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace hsmu {

namespace {

void writeCsv(const std::string& path, const SpecimenHistory& h,
              const OfflineIdentificationResult& r, std::vector<std::string>& written) {
    using csvtext::number;
    CsvFile f(path, written);
    f.column("time", "s");
    f.column("deformation", h.deformationUnits);
    f.column("force", h.forceUnits);
    f.column("auxiliary_force", h.forceUnits);
    f.column("fit_error", "-");
    for (const auto& p : r.parameterNames)
        f.column(p, "-");
    for (const auto& p : r.parameterNames)
        f.column("stddev " + p, "-");
    f.endHeader();
    for (Eigen::Index k = 0; k < r.parameters.rows(); ++k) {
        const auto i = std::size_t(k);
        std::vector<std::string> row{number(h.time[i]), number(h.deformation[i]),
                                     number(h.force[i]), number(r.auxiliaryForce[k]),
                                     number(r.fitError[k])};
        for (const Eigen::MatrixXd* m : {&r.parameters, &r.stddev})
            for (Eigen::Index j = 0; j < m->cols(); ++j)
                row.push_back(number((*m)(k, j)));
        f.line(row);
    }
    f.close();
}

} // namespace

std::vector<std::string> writeIdentificationReport(const std::string& dir,
                                                   const SpecimenHistory& history,
                                                   const IdentificationSettings& settings,
                                                   const OfflineIdentificationResult& result,
                                                   const ParameterValues& online) {
    std::vector<std::string> written;
    const std::filesystem::path d(dir);
    writeCsv((d / "parameters.csv").string(), history, result, written);

    nlohmann::json j;
    j["source"] = history.source;
    j["specimen"] = settings.specimen;
    j["method"] = result.method;
    j["samples"] = history.size();
    j["dt"] = settings.dt;
    j["units"] = {{"deformation", history.deformationUnits}, {"force", history.forceUnits}};
    nlohmann::json model = {{"law", settings.model.law}};
    for (const auto& [name, v] : settings.model.params)
        model[name] = v;
    j["model"] = model;
    j["updating"] = settings.updatingDocument;
    nlohmann::json params = nlohmann::json::object();
    for (const auto& name : result.parameterNames) {
        nlohmann::json p = {{"initial", result.initial.at(name)},
                            {"final", result.finalEstimate.at(name)},
                            {"stddev", result.finalStddev.at(name)}};
        if (const auto it = online.find(name); it != online.end())
            p["online"] = it->second;
        params[name] = p;
    }
    j["parameters"] = params;
    j["finalRmsError"] = result.finalRmsError;
    j["finalNrmse"] = result.finalNrmse;
    j["finalFitError"] = result.fitError.size() ? result.fitError[result.fitError.size() - 1] : 0.0;
    j["refits"] = result.refits;
    j["estimatorWarnings"] = result.estimatorWarnings;
    j["messages"] = result.messages;
    const std::string path = (d / "summary.json").string();
    std::ofstream out(path);
    out << j.dump(2) << '\n';
    out.close();
    if (!out)
        throw std::runtime_error(path + ": cannot be written");
    written.push_back(path);
    return written;
}

} // namespace hsmu
