#include "core/record/RthsRecord.h"

#include <filesystem>
#include <limits>
#include <stdexcept>

namespace hsmu::rths {

Alarm rthsHoldAlarm(const RthsRun& run, bool deadlineMiss)
{
    const bool console = run.hold.rfind("console hold", 0) == 0 || run.hold.rfind("emergency hold", 0) == 0;
    const AlarmKind kind = deadlineMiss ? AlarmKind::ControlFault
                           : console    ? AlarmKind::OperatorHold
                                        : AlarmKind::LimitExceeded;
    const int last = run.time.empty() ? 0 : int(run.time.size()) - 1;
    return Alarm(run.time.empty() ? 0.0 : run.time.back(), last, AlarmSeverity::Critical, kind, run.hold);
}

RunLayout rthsLayout(int floors)
{
    RunLayout layout;
    for (int i = 1; i <= floors; ++i)
        layout.dofNames.push_back("floor " + std::to_string(i));
    for (int i = 1; i <= floors; ++i)
        layout.dofNames.push_back("reference floor " + std::to_string(i));
    ElementInfo specimen;
    specimen.name = "specimen";
    specimen.type = "servoHydraulic";
    specimen.experimental = true;
    specimen.nonlinear = false;
    specimen.units = ElementUnits{"m", "N"};
    layout.elements.push_back(specimen);
    return layout;
}

RthsRecordFeed::RthsRecordFeed(StepObserver& sink, const GroundMotion& groundMotion, int floors,
                               RecordWriter* notes)
    : m_sink(sink), m_notes(notes), m_ag(groundMotion), m_floors(floors)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    m_row.u = Eigen::VectorXd::Zero(2 * floors);
    m_row.v = Eigen::VectorXd::Constant(2 * floors, nan);
    m_row.a = m_row.v;
    m_row.elements.resize(1);
}

void RthsRecordFeed::onUpdate(long k, const UpdateEvent& event)
{
    if (m_notes)
        m_notes->addNote(event.time, int(k), describeTwinUpdate(event));
}

void RthsRecordFeed::onResume(long k, double t, const std::string& note)
{
    if (m_notes)
        m_notes->addNote(t, int(k), note);
}

void RthsRecordFeed::onTick(long k, const RthsTick& tick,
                            const Eigen::Ref<const Eigen::RowVectorXd, 0, Eigen::InnerStride<>>& reference)
{
    m_row.step = int(k);
    m_row.time = tick.time;
    m_row.groundAcceleration = m_ag.at(tick.time);
    m_row.u.head(m_floors) = tick.floors;
    m_row.u.tail(m_floors) = reference.transpose();
    ElementSample& e = m_row.elements.front();
    e.deformation = tick.measured;
    e.force = tick.force;
    e.commanded = tick.desired;
    e.actuator.commanded = tick.command;
    e.actuator.measured = tick.measured;
    m_sink.onStep(m_row);
}

std::string firstFreeRecordPath(const std::string& dir)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec)
        throw std::runtime_error("cannot create the record folder " + dir + ": " + ec.message());
    for (int n = 1;; ++n) {
        const fs::path p = fs::path(dir) / (n == 1 ? std::string("record.h5") : "record-" + std::to_string(n) + ".h5");
        if (!fs::exists(p, ec))
            return p.string();
    }
}

RthsRecording::RthsRecording(const std::string& dir, const RecordStart& start, const GroundMotion& groundMotion,
                             int floors)
    : m_path(firstFreeRecordPath(dir)), m_writer(m_path, rthsLayout(floors), start),
      m_feed(m_writer, groundMotion, floors, &m_writer)
{
}

bool RthsRecording::held(const RthsRun& run, bool deadlineMiss)
{
    if (run.hold.empty() || run.hold == m_holdWritten)
        return m_writer.flush();
    m_holds.push_back(rthsHoldAlarm(run, deadlineMiss)); // writeAlarms takes a growing vector
    m_writer.writeAlarms(m_holds);
    m_holdWritten = run.hold;
    return m_writer.flush();
}

bool RthsRecording::finish(const RthsRun& run, bool deadlineMiss)
{
    if (!run.hold.empty() && run.hold != m_holdWritten) {
        m_holds.push_back(rthsHoldAlarm(run, deadlineMiss));
        m_writer.writeAlarms(m_holds);
    }
    return m_writer.finish();
}

} // namespace hsmu::rths
