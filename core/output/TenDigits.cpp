#include "core/output/TenDigits.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

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

} // namespace

char* writeTenDigits(char* first, double x) {
    const double ax = std::fabs(x);
    if (!(ax >= 1e-13 && ax < 1e31)) // zeros, subnormals, huge values, inf, NaN
        return exact(first, x);
    std::uint64_t n = 0;
    int e = 0;
    if (!significand(ax, n, e))
        return exact(first, x);
    char digits[10];
    for (int i = 8; i >= 0; i -= 2) { // two digits at a time
        std::memcpy(digits + i, kPairs + 2 * (n % 100), 2);
        n /= 100;
    }
    int used = 10; // significant digits left once trailing zeros are dropped
    while (used > 1 && digits[used - 1] == '0')
        --used;
    char* p = first;
    if (std::signbit(x))
        *p++ = '-';
    if (e < -4 || e >= 10) { // exponential: d[.ddd]e+XX
        *p++ = digits[0];
        if (used > 1) {
            *p++ = '.';
            std::memcpy(p, digits + 1, std::size_t(used - 1));
            p += used - 1;
        }
        *p++ = 'e';
        *p++ = e < 0 ? '-' : '+';
        const int a = e < 0 ? -e : e;
        if (a >= 100)
            *p++ = char('0' + a / 100);
        *p++ = char('0' + a / 10 % 10);
        *p++ = char('0' + a % 10);
    } else if (e >= 0) { // ddd[.ddd]
        const int whole = e + 1;
        std::memcpy(p, digits, std::size_t(whole));
        p += whole;
        if (used > whole) {
            *p++ = '.';
            std::memcpy(p, digits + whole, std::size_t(used - whole));
            p += used - whole;
        }
    } else { // 0.000ddd
        *p++ = '0';
        *p++ = '.';
        for (int i = 0; i < -e - 1; ++i)
            *p++ = '0';
        std::memcpy(p, digits, std::size_t(used));
        p += used;
    }
    return p;
}

} // namespace hsmu
