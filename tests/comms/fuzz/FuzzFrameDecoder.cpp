// libFuzzer target for the native protocol's frame decoder (comms/protocol/FrameDecoder.h).
// The input is split into chunks by its first byte (chunking must not matter), fed to a
// decoder, and every decoded frame is re-encoded and decoded again: it must give the same
// message. Any crash, sanitizer report, unbounded buffer or mismatch is a finding.
//
// Build and run (clang; only the three protocol sources are needed), either with CMake
//   (-DCMAKE_CXX_COMPILER=clang++ -DHSMU_BUILD_FUZZERS=ON, target fuzz_frame_decoder) or:
//   clang++ -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -I. -o fuzz_frames
//       comms/protocol/Protocol.cpp comms/protocol/FrameCodec.cpp
//       comms/protocol/FrameDecoder.cpp tests/comms/fuzz/FuzzFrameDecoder.cpp
//   (one command, from the repository root)
//   mkdir -p /tmp/fuzz-corpus
//   ./fuzz_frames -max_total_time=600 -max_len=9000 -use_value_profile=1 /tmp/fuzz-corpus
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
            encodeFrame(f.message, f.sequence, again);
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
