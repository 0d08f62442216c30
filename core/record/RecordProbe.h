#pragma once
// RecordProbe: reads a record once in a child process (fork) under a wall-clock deadline, so
// that a damaged file can never hang the caller: HDF5 may loop forever on corrupted metadata
// (docs/recording.md, "Damaged records"), and a thread cannot be cancelled inside it.
//
//   probeRecord(path, 5.0, read)  forks; the child runs read(path) (which throws RecordError
//                                 or anything else on failure) and exits; the parent waits at
//                                 most `deadline` seconds, then SIGKILLs the child.
// Result: nullopt when the child read the file; else the error, starting with the path:
//   "FILE: <the reader's own message>"                        a failure the reader reported
//   "FILE: damaged record (reading it did not finish within 5 s)"    a hang, killed
//   "FILE: damaged record (the reader crashed with signal 11)"       a crash inside HDF5
// The caller then reads the file itself, knowing that a read of it finishes.
// Thread rules: any thread. The child only runs `read` and _exits (no atexit handlers, no
// Qt); a lock another thread of the parent holds at the fork (e.g. HDF5's, while a run
// writes its record) can make the child wait: it then fails by the deadline, never hangs.

#include <functional>
#include <optional>
#include <string>

namespace hsmu {

/// [s] the deadline RecordReader uses.
inline constexpr double kRecordOpenDeadline = 5.0;

std::optional<std::string> probeRecord(const std::string& path, double deadline,
                                       const std::function<void(const std::string&)>& read);

} // namespace hsmu
