#pragma once
// StateJournal: the controller's state file: an append-only text journal of what each
// specimen has lived through, written (and flushed to the OS) before a commit is
// acknowledged, so a controller killed at any instant and restarted with the same file
// rebuilds every specimen exactly: it replays the journaled commits through a fresh
// specimen of the same configuration and checks each replayed measurement bit for bit.
//
//   hsmu-controller-state 1
//   element <index> <fingerprint, 16 hex digits> <name>      one per specimen, in order
//   configure <index> <dt [s]>
//   commit <index> <step> <target> <achieved> <measured deformation> <measured force>
//   commits <index> <step> <n> n x (<target> <achieved> <measured stroke> <measured force>)
//                                                  a specimen of n >= 2 actuator channels
//   reset <index>
//
// Numbers are written with 17 significant digits (exact round trip of binary64). The
// fingerprint is FNV-1a 64 of the specimen section's JSON text; a file written for other
// specimens is refused. A last line without its newline (a crash during the write) is
// dropped and cut off; any other unreadable line is an error.
// Thread rules: one thread.

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace hsmu::comms {

/// One actuator channel of a journaled step (units: the channel's; stroke [m], force [kN]).
struct JournalChannel {
    double target = 0.0, achieved = 0.0, stroke = 0.0, force = 0.0;
};

struct JournalRecord {
    enum class Kind { Configure, Commit, Reset };
    Kind kind = Kind::Commit;
    int element = 0;
    double dt = 0.0;                                                     ///< Configure
    std::uint64_t step = 0;                                              ///< Commit
    double target = 0.0, achieved = 0.0, deformation = 0.0, force = 0.0; ///< Commit
    std::vector<JournalChannel> channels; ///< Commit of N >= 2 channels (then the above are 0)
};

struct JournalElement {
    std::string name;
    std::uint64_t fingerprint = 0;
};

class StateJournal {
public:
    StateJournal() = default;
    ~StateJournal();
    StateJournal(const StateJournal&) = delete;
    StateJournal& operator=(const StateJournal&) = delete;

    /// Open (create when absent or empty) for these specimens; the records already in the
    /// file are returned in `records`. False with a sentence in `error` otherwise.
    bool open(const std::string& path, const std::vector<JournalElement>& elements,
              std::vector<JournalRecord>& records, std::string& error);
    /// Append one record and flush it to the OS (survives the death of the process).
    bool append(const JournalRecord& r, std::string& error);
    bool isOpen() const { return m_file != nullptr; }
    const std::string& path() const { return m_path; }

    /// FNV-1a 64-bit hash of text.
    static std::uint64_t fingerprint(const std::string& text);

private:
    std::FILE* m_file = nullptr;
    std::string m_path;
};

} // namespace hsmu::comms
