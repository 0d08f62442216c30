#pragma once
// OfSizes: the 11-int32 sizes header that opens every OpenFresco SimApp / GenericTCP
// connection (ARCHITECTURE.md "OpenFresco compatibility", docs/openfresco.md):
//
//   [ctrl disp, ctrl vel, ctrl accel, ctrl force, ctrl time,
//    daq disp,  daq vel,  daq accel,  daq force,  daq time,   dataSize]
//
// int32 in native order (little-endian on every platform we build for), 44 bytes, sent by the
// client once right after connecting, never answered. The ctrl sizes lay out a trial frame
// [3, ctrl disp..., ctrl vel..., ctrl accel..., ctrl force..., ctrl time...] and the daq sizes
// the reply to getDaqResponse (6), which starts at index 0; every frame is dataSize doubles.
// No sockets here.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace hsmu::comms::of {

/// The five response kinds, in header order.
enum class Resp { Disp = 0, Vel = 1, Accel = 2, Force = 3, Time = 4 };

constexpr int kSizesCount = 11;
constexpr std::size_t kSizesBytes = kSizesCount * 4;
constexpr int kDefaultDataSize = 256;
/// Upper bound we accept for dataSize (doubles): 1 Mi doubles = 8 MiB per frame. A header
/// asking for more is taken as garbage, not allocated.
constexpr int kMaxDataSize = 1 << 20;

struct OfSizes {
    std::array<int, 5> ctrl{1, 0, 0, 0, 0}; ///< disp, vel, accel, force, time
    std::array<int, 5> daq{1, 0, 0, 1, 0};  ///< disp, vel, accel, force, time
    int dataSize = kDefaultDataSize;        ///< doubles per frame

    int ctrlTotal() const;
    int daqTotal() const;
    /// Index of the first ctrl value of kind r inside a trial frame (after the action code).
    int ctrlIndex(Resp r) const;
    /// Index of the first daq value of kind r inside a getDaqResponse reply.
    int daqIndex(Resp r) const;
    int ctrlSize(Resp r) const { return ctrl[static_cast<std::size_t>(r)]; }
    int daqSize(Resp r) const { return daq[static_cast<std::size_t>(r)]; }

    /// Why these sizes cannot be used (negative size, dataSize outside 1..kMaxDataSize, a
    /// trial 1 + ctrlTotal() or a reply daqTotal() longer than dataSize), or nullopt.
    std::optional<std::string> problem() const;
    /// "ctrl [disp 1, vel 0, accel 0, force 0, time 0], daq [disp 1, ..., force 1, time 0],
    /// dataSize 256" for logs and error messages.
    std::string describe() const;

    bool operator==(const OfSizes&) const = default;
};

/// The 44-byte header.
std::array<std::uint8_t, kSizesBytes> encodeSizes(const OfSizes& s);
/// The header as sent (no validation: call problem()).
OfSizes decodeSizes(const std::uint8_t* bytes);

} // namespace hsmu::comms::of
