// libFuzzer target for the native protocol's frame decoder (comms/protocol/FrameDecoder.h).
// The input is split into chunks by its first byte (chunking must not matter), fed to a
// decoder, and every decoded frame is re-encoded and decoded again: it must give the same
// message. Any crash, sanitizer report, unbounded buffer or mismatch is a finding.
//
// Built by tests/fuzz/CMakeLists.txt (clang + libFuzzer); run: scripts/fuzz.sh (docs/security.md).
#include "comms/protocol/FrameDecoder.h"

#include <cstdlib>

using namespace hsmu::comms;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0)
        return 0;
    const std::size_t chunk = 1 + data[0] % 64;
    ++data;
    --size;
    FrameDecoder d;
    for (std::size_t at = 0; at < size; at += chunk) {
        d.append(data + at, std::min(chunk, size - at));
        if (d.buffered() > kHeaderSize + kMaxPayload + chunk)
            std::abort(); // the buffer must stay bounded
        Frame f;
        for (;;) {
            const auto st = d.next(f);
            if (st != FrameDecoder::Status::Frame)
                break;
            std::vector<std::uint8_t> again;
            encodeFrame(f.message, 1, again); // a fresh decoder's first frame carries 1
            FrameDecoder d2;
            d2.append(again.data(), again.size());
            Frame g;
            if (d2.next(g) != FrameDecoder::Status::Frame || g.message.index() != f.message.index())
                std::abort(); // what was accepted must encode to something acceptable
            std::vector<std::uint8_t> third;
            encodeFrame(g.message, g.sequence, third);
            if (third != again)
                std::abort(); // and round-trip exactly
        }
        if (d.failed())
            break;
    }
    return 0;
}
