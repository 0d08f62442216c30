#pragma once
// SessionOptions: how a TestSession drives its hybrid test (docs/configuration.md, "Timeouts
// and reconnection"). The link timeouts are LinkTimeouts (core/config/LinkConfig.h), one set
// for every front end.

#include "core/record/RecordWriter.h"

#include <string>

namespace hsmu {

/// Automatic resumes after a control fault (lost link, timeout, a controller fault). Other
/// holds (limits, the operator, the estimator) are never resumed automatically.
/// Attempt k (1-based) waits delayBefore(k) = min(firstDelay * 2^(k-1), maxDelay) seconds of
/// wall time before it resumes; the count restarts once the test advances again.
struct ReconnectPolicy {
    int attempts = 0;        ///< resumes in a row; 0: the operator decides (no automatic resume)
    double firstDelay = 0.5; ///< [s] before the first attempt
    double maxDelay = 8.0;   ///< [s] cap of the doubling backoff

    double delayBefore(int attempt) const;
};

struct SessionOptions {
    /// Test seconds per wall second (1 = real time); <= 0: as fast as possible.
    double speed = 0.0;
    ReconnectPolicy reconnect;
    /// The HDF5 record (docs/recording.md); "" records nothing. Its folder is created by
    /// TestSession::openRecord().
    std::string recordPath;
    RecordStart recordStart;
};

} // namespace hsmu
