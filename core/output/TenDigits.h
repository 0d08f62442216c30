#pragma once
// TenDigits: a double written like printf("%.10g") (equal to std::to_chars(first, last, x,
// std::chars_format::general, 10)): 10 significant digits rounded to nearest, trailing zeros
// dropped, fixed notation for decimal exponents -4..9 and "d.ddde+XX" otherwise, '.' as the
// decimal point whatever the locale. steps.csv writes every value this way (docs/cli.md).
//
// Why not std::to_chars directly: libstdc++'s precision overload costs ~100-200 ns a value
// (an exact multi-precision conversion every time), a third of a strong-SDOF run's CPU with
// its 218,000 values (docs/benchmarks.md, issue 27). The fast path here scales |x| by an
// exact power of ten (10^k, |k| <= 22, exactly representable), one correctly rounded multiply
// or divide: y = |x| 10^(9-e) is within 2^-53 relative (< 1.2e-6 absolute, y < 1e10) of the
// exact product, so rounding y to an integer is exact unless y's fraction is within 1e-5 of
// one half; those values (about 1 in 50,000), |x| outside [1e-13, 1e31), zeros, infinities and
// NaN take std::to_chars itself. Same characters in every case (tests/core/output).

#include <cstddef>

namespace hsmu {

/// Longest text writeTenDigits() produces ("-1.234567891e-308").
inline constexpr std::size_t kTenDigitsMaxChars = 24;

/// Writes x at first (room for kTenDigitsMaxChars characters, no terminating zero); returns
/// one past the last character written.
char* writeTenDigits(char* first, double x);

} // namespace hsmu
