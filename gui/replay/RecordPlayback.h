#pragma once
// RecordPlayback: the position of a replay in a run record (RecordData, docs/recording.md) and
// the rows to show, independent of any widget or timer:
//   shown()            rows shown so far (0 .. rows()); row i is StepRecord rowAt(i)
//   advance(wallS)     play: test time moves by speed x wallS seconds; returns the new rows
//   seek(n)            scrub: show exactly n rows; returns the rows to append, or sets
//                      *restart when the plots must be cleared and refilled from row 0
// Speed: test seconds per wall second (> 0). Time of row i: RecordData::time[i] [s].
// Thread rules: one thread (the GUI's).

#include "core/record/RecordData.h"
#include "core/experiment/StepRecord.h"

#include <memory>
#include <vector>

namespace hsmu::gui {

class RecordPlayback {
public:
    explicit RecordPlayback(std::shared_ptr<const RecordData> data);

    /// Row i of the record as the StepRecord the live test produced (updating and the multi-DOF
    /// elements' channels filled when the record has them; u, v, a of every DOF, NaN for a DOF
    /// or a step the record did not keep: docs/recording.md "Chosen and decimated DOFs").
    /// Precondition: 0 <= i < rows().
    static StepRecord rowAt(const RecordData& data, int i);

    const RecordData& data() const { return *m_data; }
    int rows() const { return m_data->rows(); }
    int shown() const { return m_shown; }
    bool atEnd() const { return m_shown >= rows(); }
    /// Test time of the last row shown [s] (0 before the first).
    double time() const;
    /// Step index of the last row shown (-1 before the first).
    int step() const;

    void setSpeed(double testSecondsPerWallSecond);
    double speed() const { return m_speed; }

    /// Move forward by wallSeconds of play; returns the rows now due (oldest first).
    std::vector<StepRecord> advance(double wallSeconds);
    /// Show exactly n rows (clamped to 0 .. rows()). Forward: the rows to append; backward:
    /// *restart = true and every row 0 .. n-1 (the caller clears the plots first).
    std::vector<StepRecord> seek(int n, bool* restart);

private:
    std::vector<StepRecord> take(int from, int to) const;

    std::shared_ptr<const RecordData> m_data;
    int m_shown = 0;
    double m_speed = 1.0;
    double m_playTime = 0.0; ///< test time the play has reached [s]
};

} // namespace hsmu::gui
