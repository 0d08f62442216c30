// libFuzzer target for the OpenFresco parsers a client's bytes reach (comms/openfresco): the
// 44-byte sizes header (decodeSizes, problem, describe, the index arithmetic of valid sizes),
// a frame of the header's dataSize (decodeFrame, actionOf, startsWithCode), an init line
// (decodeInitLine) and its log form (logText, which must come out printable and bounded).
#include "comms/LogText.h"
#include "comms/openfresco/OfFrame.h"
#include "comms/openfresco/OfSizes.h"

#include <cstdlib>
#include <cstring>
#include <vector>

using namespace hsmu::comms;
using namespace hsmu::comms::of;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < kSizesBytes)
        return 0;
    const OfSizes s = decodeSizes(data);
    const auto problem = s.problem();
    (void)s.describe();
    if (!problem) {
        if (encodeSizes(s) != [&] {
                std::array<std::uint8_t, kSizesBytes> a{};
                std::memcpy(a.data(), data, a.size());
                return a;
            }())
            std::abort(); // a valid header round-trips
        for (Resp r : {Resp::Disp, Resp::Vel, Resp::Accel, Resp::Force, Resp::Time})
            if (s.daqIndex(r) < 0 || s.daqIndex(r) + s.daqSize(r) > s.dataSize)
                std::abort(); // every index of a valid header is inside its frame
    }
    data += kSizesBytes;
    size -= kSizesBytes;
    if (!problem && size >= static_cast<std::size_t>(s.dataSize) * 8) {
        std::vector<double> frame;
        decodeFrame(data, s.dataSize, frame);
        if (actionOf(frame[0]) && !startsWithCode(data))
            std::abort(); // every known action is a code
    }
    if (size >= 8)
        (void)startsWithCode(data);
    std::vector<std::uint8_t> line(kInitLineBytes, 0);
    std::memcpy(line.data(), data, std::min(size, kInitLineBytes));
    const std::string text = decodeInitLine(line.data());
    const std::string logged = logText(text);
    for (const char c : logged)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)
            std::abort(); // the log line is printable
    if (logged.size() > 4 * 200 + 32)
        std::abort(); // and bounded
    return 0;
}
