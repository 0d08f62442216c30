#pragma once
// OfFrame: the OpenFresco data frame and init line (ARCHITECTURE.md "OpenFresco
// compatibility", docs/openfresco.md). A frame is exactly dataSize doubles in native order
// (8 * dataSize bytes), no header. A request carries its action code in element 0 and its
// values from element 1; a reply carries no code, its values start at element 0. The rest is
// padded with zeros. GenericTCP may send init-file lines first: each a fixed 16385-byte
// message holding the line's text and NUL padding. No sockets here.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace hsmu::comms::of {

enum class Action : int {
    Open = 1,
    Setup = 2,
    SetTrialResponse = 3,
    Execute = 4,
    CommitState = 5,
    GetDaqResponse = 6,
    GetDisp = 7,
    GetVel = 8,
    GetAccel = 9,
    GetForce = 10,
    GetTime = 11,
    GetInitialStiff = 12,
    GetTangentStiff = 13,
    GetDamp = 14,
    GetMass = 15,
    Terminate = 99,
};

const char* actionName(Action a);
/// The action of a frame's element 0: an integral value that is one of the codes above.
std::optional<Action> actionOf(double code);

constexpr std::size_t kInitLineBytes = 16385;

/// hsmu-controller's mark (docs/openfresco.md "The server's mark"): its reply to a
/// getDaqResponse that comes before the session's first trial (only the console's connect probe
/// does that) carries in its last element, when the frame has room beyond the values, which
/// kind of server answers. OpenFresco's clients read only their sizes and never see it. The
/// console's GenericTCP client refuses a SimApp server (it would never commit its specimens).
constexpr double kMarkSimAppServer = 4.8534e300;     ///< needs commits (SimApp element / site)
constexpr double kMarkGenericTcpServer = 4.8535e300; ///< commits each trial when the next comes

/// values (at most dataSize of them) padded with zeros to a dataSize-double frame; false with
/// a sentence in error when they do not fit or dataSize is not positive.
bool encodeFrame(std::span<const double> values, int dataSize, std::vector<std::uint8_t>& out,
                 std::string& error);
/// A request: [action, values..., 0...].
bool encodeRequest(Action a, std::span<const double> values, int dataSize,
                   std::vector<std::uint8_t>& out, std::string& error);
/// The dataSize doubles of a frame of 8 * dataSize bytes.
void decodeFrame(const std::uint8_t* bytes, int dataSize, std::vector<double>& out);

/// One init line as its 16385-byte message; false if the text (without a newline) has more
/// than 16384 bytes or holds a NUL.
bool encodeInitLine(const std::string& line, std::vector<std::uint8_t>& out, std::string& error);
/// The text of a 16385-byte init message (up to its first NUL).
std::string decodeInitLine(const std::uint8_t* bytes);
/// True when the first 8 bytes of a message are a double holding a valid action code: a data
/// frame, not an init line (text never starts with the bytes of such a double).
bool startsWithAction(const std::uint8_t* first8);
/// True when the first 8 bytes of a message are a double holding a whole, nonzero number of
/// magnitude below 2^31, known code or not: a data frame (an unknown code is refused as such),
/// never an init line. A line's text starts with a non-NUL byte, which as the lowest byte of
/// a double makes it either fractional or >= 2^52; an empty line is all zeros (0.0).
bool startsWithCode(const std::uint8_t* first8);

} // namespace hsmu::comms::of
