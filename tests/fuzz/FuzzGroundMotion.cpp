// libFuzzer target for the ground-motion readers (core/groundmotion: AT2, time-acceleration,
// single column, format detection). The input is written to a file (the readers take paths);
// every outcome must be a GroundMotion with finite values or a GroundMotionError.
#include "core/groundmotion/GroundMotionError.h"
#include "core/groundmotion/GroundMotionReader.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace hsmu;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    struct TempDir {
        std::string path;
        ~TempDir() { rmdir(path.c_str()); }
    };
    static const TempDir temp{[] {
        // In memory where the system offers it (the readers take paths; a disk costs time).
        char shm[] = "/dev/shm/hsmu-fuzz-gm-XXXXXX";
        char tmp[] = "/tmp/hsmu-fuzz-gm-XXXXXX";
        const char* made = mkdtemp(shm);
        return std::string(made ? made : mkdtemp(tmp));
    }()};
    const std::string& dir = temp.path;
    const std::string base = dir + "/record";
    const char* extension[] = {".at2", ".txt", ".dat"};
    const std::string path = base + extension[size > 0 ? data[0] % 3 : 0];
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    const auto check = [](const GroundMotion& g) {
        for (const double a : g.acceleration)
            if (!std::isfinite(a))
                std::abort(); // a read record holds finite values only
    };
    try {
        check(readGroundMotion(path, GroundMotionFormat::Auto, std::nullopt, 0.01));
    } catch (const GroundMotionError&) {
    }
    try {
        check(readAt2(path));
    } catch (const GroundMotionError&) {
    }
    try {
        check(readTimeAcceleration(path));
    } catch (const GroundMotionError&) {
    }
    std::remove(path.c_str());
    return 0;
}
