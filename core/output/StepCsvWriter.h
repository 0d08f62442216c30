#pragma once
// StepCsvWriter: a StepObserver writing one CSV row per committed step to a file.
//
// Header (units in the column names, element units from ElementUnits):
//   time_s,ag_m_s2,<dof>_u_m,<dof>_v_m_s,<dof>_a_m_s2 (per DOF),
//   <element>_deformation_<unit>,<element>_force_<unit> (per element),
//   <element>_commanded_<unit> (specimens only, after their force column)
// e.g. "Element 1_deformation_rad,Element 1_force_kNm,Element 1_commanded_rad".
// With online model updating (RunLayout::updating) the row continues with
//   param_<name> (per identified parameter, the law's own units: normalized for Bouc-Wen),
//   std_<name> (their standard deviations, same units; 0 where the method has none),
//   aux_force_<unit> (the auxiliary model's force, the specimen's force unit),
//   fit_error (the inspector's normalized RMS error [-]),
// e.g. "param_k0,...,std_k0,...,aux_force_kNm,fit_error"; a record without updating data
// writes NaN there.
// Last, with multi-DOF elements (RunLayout::channels, core/experiment/ElementChannels.h), one
// column per basic DOF and actuator channel: <element>_<channel>_<unit>, blanks as '_', e.g.
// "Column_L_shear_force_kN,...,Column_L_vertical_stroke_m".
// Values are written like "%.10g" with a '.' decimal point whatever the locale (writeTenDigits).
// Rows are formatted into a buffer of the writer's own, handed to the file once it holds
// kBufferBytes (one write of many rows, not a stream call per value or row), and the file
// is flushed every kFlushInterval rows and by finish() / the destructor, so an interrupted
// run keeps (almost) every committed step: at most the last kFlushInterval - 1 rows are lost.
//
// Thread rules: onStep() runs on the test's thread; construct, finish and destroy on the same
// thread or after the test has stopped stepping.

#include "core/experiment/StepRecord.h"
#include "core/output/RunLayout.h"

#include <fstream>
#include <string>
#include <vector>

namespace hsmu {

class StepCsvWriter final : public StepObserver {
public:
    static constexpr int kFlushInterval = 1000;
    /// Formatted rows kept before they are written to the file (between two flushes).
    static constexpr std::size_t kBufferBytes = 64 * 1024;
    /// Rows wider than this are not worth writing as text during a run (a 1,000-DOF model:
    /// 5,002 values, 54 kB and more time than the step itself per step; issue 27); `hsmu run`
    /// then skips steps.csv unless `--csv all` (the HDF5 record keeps every column; `hsmu
    /// export` writes CSV from it), docs/cli.md. 200: the paper's frames and buildings up to
    /// 39 storeys keep their steps.csv.
    static constexpr std::size_t kMaxColumns = 200;
    /// Values per row of a layout (time and ground acceleration included).
    static std::size_t columnCount(const RunLayout& layout);

    /// Opens (truncates) path and writes the header. Throws std::runtime_error naming the file
    /// if it cannot be opened.
    StepCsvWriter(const std::string& path, const RunLayout& layout);
    ~StepCsvWriter() override;
    StepCsvWriter(const StepCsvWriter&) = delete;
    StepCsvWriter& operator=(const StepCsvWriter&) = delete;

    /// The header line (without the newline) for a layout: columnNames() joined by commas.
    static std::string header(const RunLayout& layout);
    /// The columns' names, in order (columnCount(layout) of them).
    static std::vector<std::string> columnNames(const RunLayout& layout);
    /// One row's values, in columnNames() order, as full doubles (the file rounds them to 10
    /// digits): the one ordering for the file and for the Python module's hsmu.run arrays.
    static void rowValues(const RunLayout& layout, const StepRecord& record,
                          std::vector<double>& out);

    void onStep(const StepRecord& record) override;
    /// Flush and close. False if any write failed (disk full, ...).
    bool finish();

    int rowsWritten() const { return m_rows; }
    const std::string& path() const { return m_path; }

private:
    /// The updating part of a row (param_, std_, aux_force_, fit_error).
    static void appendUpdating(const RunLayout& layout, const StepRecord& record,
                               std::vector<double>& out);
    std::string m_path;
    RunLayout m_layout;
    /// Hands the buffered rows to the file; with `flush`, flushes it too.
    void writeBuffered(bool flush);
    std::ofstream m_out;
    std::vector<char> m_buffer; // formatted rows not yet written, m_used bytes of it
    std::size_t m_used = 0;
    std::vector<double> m_values;
    int m_rows = 0;
    bool m_failed = false;
};

} // namespace hsmu
