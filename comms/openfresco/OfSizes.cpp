#include "comms/openfresco/OfSizes.h"

#include <bit>
#include <cstring>

namespace hsmu::comms::of {

static_assert(std::endian::native == std::endian::little,
              "the OpenFresco wire format is native order; this code assumes little-endian");

namespace {
const char* const kNames[5] = {"disp", "vel", "accel", "force", "time"};

std::string list(const std::array<int, 5>& a) {
    std::string s = "[";
    for (std::size_t i = 0; i < a.size(); ++i)
        s += (i ? ", " : "") + std::string(kNames[i]) + " " + std::to_string(a[i]);
    return s + "]";
}

long long sum(const std::array<int, 5>& a) {
    long long t = 0;
    for (int v : a)
        t += v;
    return t;
}
} // namespace

int OfSizes::ctrlTotal() const {
    return static_cast<int>(sum(ctrl));
}

int OfSizes::daqTotal() const {
    return static_cast<int>(sum(daq));
}

int OfSizes::ctrlIndex(Resp r) const {
    int i = 1;
    for (int k = 0; k < static_cast<int>(r); ++k)
        i += ctrl[static_cast<std::size_t>(k)];
    return i;
}

int OfSizes::daqIndex(Resp r) const {
    int i = 0;
    for (int k = 0; k < static_cast<int>(r); ++k)
        i += daq[static_cast<std::size_t>(k)];
    return i;
}

std::optional<std::string> OfSizes::problem() const {
    for (std::size_t i = 0; i < 5; ++i) {
        if (ctrl[i] < 0 || ctrl[i] > kMaxDataSize)
            return "ctrl " + std::string(kNames[i]) + " size " + std::to_string(ctrl[i]) +
                   " is not a size";
        if (daq[i] < 0 || daq[i] > kMaxDataSize)
            return "daq " + std::string(kNames[i]) + " size " + std::to_string(daq[i]) +
                   " is not a size";
    }
    if (dataSize < 1 || dataSize > kMaxDataSize)
        return "dataSize " + std::to_string(dataSize) + " is outside 1.." +
               std::to_string(kMaxDataSize);
    if (1 + sum(ctrl) > dataSize)
        return "a trial frame needs 1 + " + std::to_string(sum(ctrl)) +
               " doubles, more than dataSize " + std::to_string(dataSize);
    if (sum(daq) > dataSize)
        return "a daq reply needs " + std::to_string(sum(daq)) + " doubles, more than dataSize " +
               std::to_string(dataSize);
    return std::nullopt;
}

std::string OfSizes::describe() const {
    return "ctrl " + list(ctrl) + ", daq " + list(daq) + ", dataSize " + std::to_string(dataSize);
}

std::array<std::uint8_t, kSizesBytes> encodeSizes(const OfSizes& s) {
    std::int32_t v[kSizesCount];
    for (std::size_t i = 0; i < 5; ++i) {
        v[i] = s.ctrl[i];
        v[5 + i] = s.daq[i];
    }
    v[10] = s.dataSize;
    std::array<std::uint8_t, kSizesBytes> out{};
    std::memcpy(out.data(), v, kSizesBytes);
    return out;
}

OfSizes decodeSizes(const std::uint8_t* bytes) {
    std::int32_t v[kSizesCount];
    std::memcpy(v, bytes, kSizesBytes);
    OfSizes s;
    for (std::size_t i = 0; i < 5; ++i) {
        s.ctrl[i] = v[i];
        s.daq[i] = v[5 + i];
    }
    s.dataSize = v[10];
    return s;
}

} // namespace hsmu::comms::of
