#include "core/output/TenDigits.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

static_assert(std::endian::native == std::endian::little, "eightDigits() lays digits out little-endian");

namespace hsmu {

namespace {

constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                             1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                             1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr char kPairs[] = "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
                           "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
                           "8081828384858687888990919293949596979899";
constexpr std::uint64_t kLow = 1000000000ULL;   // 10^9: the smallest 10-digit significand
constexpr std::uint64_t kHigh = 10000000000ULL; // 10^10
// |y - exact| < 1.2e-6: a fraction further than this from one half rounds the same way.
constexpr double kTieMargin = 1e-5;

char* exact(char* first, double x) {
    return std::to_chars(first, first + kTenDigitsMaxChars, x, std::chars_format::general, 10)
        .ptr;
}

/// The 10-digit significand n (10^9 <= n < 10^10) and decimal exponent e of |x| rounded to
/// 10 significant digits (|x| ~ n 10^(e-9)); false when the fast path cannot decide.
bool significand(double ax, std::uint64_t& n, int& e) {
    // floor(log10 |x|) from the binary exponent b (2^b <= |x| < 2^(b+1), |x| normal here):
    // floor(b log10 2), one too small at most; 78913 / 2^18 = log10 2 to 1e-6, exact for |b|
    // < 1650.
    const int b = int(std::bit_cast<std::uint64_t>(ax) >> 52) - 1023;
    e = (b * 78913) >> 18;
    for (int attempt = 0; attempt < 3; ++attempt) {
        const int k = 9 - e;
        if (k > 22 || k < -22)
            return false;
        const double y = k >= 0 ? ax * kPow10[k] : ax / kPow10[-k];
        if (y < double(kLow)) { // the estimate of e was one too large (rounding is monotonic)
            --e;
            continue;
        }
        if (y >= double(kHigh)) {
            ++e;
            continue;
        }
        const std::uint64_t whole = std::uint64_t(y); // y > 0: truncation is floor
        const double fraction = y - double(whole);     // exact (Sterbenz)
        if (std::fabs(fraction - 0.5) < kTieMargin)
            return false;
        n = whole + (fraction > 0.5 ? 1 : 0);
        if (n == kHigh) { // 9999999999.5 and above round up to the next decade
            n = kLow;
            ++e;
        }
        return true;
    }
    return false;
}

/// The eight decimal digits of x < 10^8 as byte values 0..9, the first digit in the lowest
/// byte (its first byte in memory on this little-endian target): x split into 4 + 4, 2 + 2
/// and 1 + 1 digits in the lanes of one 64-bit word, each division by 100 or 10 a multiply
/// and shift that is exact for the lane's range (x * 10486 >> 20 = x / 100 for x < 10^4,
/// x * 103 >> 10 = x / 10 for x < 100).
std::uint64_t eightDigits(std::uint32_t x) {
    std::uint64_t v = std::uint64_t(x / 10000) | (std::uint64_t(x % 10000) << 32);
    std::uint64_t hi = ((v * 10486) >> 20) & 0x0000007F0000007FULL;
    v = hi | ((v - hi * 100) << 16);
    hi = ((v * 103) >> 10) & 0x000F000F000F000FULL;
    return hi | ((v - hi * 10) << 8);
}

} // namespace

char* writeTenDigits(char* first, double x) {
    const double ax = std::fabs(x);
    if (!(ax >= 1e-13 && ax < 1e31)) // zeros, subnormals, huge values, inf, NaN
        return exact(first, x);
    std::uint64_t n = 0;
    int e = 0;
    if (!significand(ax, n, e))
        return exact(first, x);
    // The ten digits at digits[0..9]; the rest is room for the fixed-size copies below.
    char digits[24] = {};
    const std::uint32_t head = std::uint32_t(n / 100000000); // 10..99
    const std::uint64_t tail = eightDigits(std::uint32_t(n % 100000000));
    std::memcpy(digits, kPairs + 2 * head, 2);
    const std::uint64_t ascii = tail + 0x3030303030303030ULL;
    std::memcpy(digits + 2, &ascii, 8);
    // Significant digits once trailing zeros are dropped: the last digits are tail's high bytes.
    const int used = tail != 0 ? 10 - std::countl_zero(tail) / 8 : (head % 10 != 0 ? 2 : 1);
    char* p = first;
    if (std::signbit(x))
        *p++ = '-';
    // Fixed-size copies (single stores) may write past the text's end, never past
    // first + kTenDigitsMaxChars; the end returned is what counts.
    if (e < -4 || e >= 10) { // exponential: d[.ddd]e+XX
        p[0] = digits[0];
        p[1] = '.';
        std::memcpy(p + 2, digits + 1, 9);
        p += used > 1 ? used + 1 : 1;
        *p++ = 'e';
        *p++ = e < 0 ? '-' : '+';
        const int a = e < 0 ? -e : e;
        if (a >= 100)
            *p++ = char('0' + a / 100);
        std::memcpy(p, kPairs + 2 * (a % 100), 2);
        p += 2;
    } else if (e >= 0) { // ddd[.ddd]
        const int whole = e + 1;
        std::memcpy(p, digits, 10);
        if (used > whole) {
            p[whole] = '.';
            std::memcpy(p + whole + 1, digits + whole, 9);
            p += used + 1;
        } else {
            p += whole;
        }
    } else { // 0.000ddd
        const int zeros = -e - 1; // 0..3
        std::memcpy(p, "0.000", 5);
        std::memcpy(p + 2 + zeros, digits, 10);
        p += 2 + zeros + used;
    }
    return p;
}

} // namespace hsmu
