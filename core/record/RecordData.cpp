#include "core/record/RecordData.h"

#include <algorithm>

namespace hsmu {

int RecordData::dofColumn(int dof) const {
    const auto& kept = meta.dofRecording.dofs;
    if (dof < 0 || std::size_t(dof) >= layout.dofNames.size())
        return -1;
    if (kept.empty())
        return dof;
    const auto it = std::lower_bound(kept.begin(), kept.end(), dof);
    return it != kept.end() && *it == dof ? int(it - kept.begin()) : -1;
}

int RecordData::dofRowOf(int row) const {
    if (row < 0 || row >= rows())
        return -1;
    if (dofSteps.empty())
        return row < u.rows() ? row : -1;
    const int step = steps[std::size_t(row)];
    const auto it = std::lower_bound(dofSteps.begin(), dofSteps.end(), step);
    return it != dofSteps.end() && *it == step ? int(it - dofSteps.begin()) : -1;
}

std::string RecordData::dofNotRecorded(int dof) const {
    const bool named = dof >= 0 && std::size_t(dof) < layout.dofNames.size();
    const DofRecording& r = meta.dofRecording;
    return "DOF '" + (named ? layout.dofNames[std::size_t(dof)] : std::string("?")) + "' (index " +
           std::to_string(dof) + ") was not recorded: the run kept DOFs " +
           describeDofList(r.dofs) + " every " + std::to_string(r.every) +
           " step(s) (hsmu run --record-dofs / --record-every, the configuration's record.dofs "
           "/ record.every)";
}

} // namespace hsmu
