#pragma once
// Units: the lab units data come in and go out in, and their exact factors to the console's
// own units (kN, m, s, rad; moments kN m). docs/units.md.
//
//   length    m 1, cm 0.01, mm 0.001, in 0.0254, ft 0.3048                    -> m
//   force     N 0.001, kN 1, MN 1000, lbf 0.0044482216152605, kip 4.4482216152605,
//             kgf 0.00980665, tonf 9.80665 (metric tonne-force)                 -> kN
//   moment    any force unit times any length unit: "kN m", "kN*m", "kN.m", "kN-m",
//             "kN·m" or written together ("kNm", "Nmm", "kipin", "lbfft")       -> kN m
//   rotation  rad 1, mrad 0.001, deg pi/180                                     -> rad
//   time      s 1, ms 0.001                                                     -> s
// Definitions: 1 in = 0.0254 m and 1 ft = 12 in exactly (international yard, 1959);
// 1 lbf = 0.45359237 kg x 9.80665 m/s^2 = 4.4482216152605 N exactly; 1 kip = 1000 lbf;
// 1 kgf = 9.80665 N and 1 tonf = 1000 kgf (standard gravity, CGPM 1901).
// Symbols are matched ignoring letter case ("KN", "kn" and "kN" are the kilonewton) and
// surrounding blanks, except "mN" (a millinewton, not supported), which is not the MN; the US
// plural "kips" is the kip (also in moments: "kips*in", "kips ft").
// Thread rules: none (pure functions).

#include <optional>
#include <string>
#include <string_view>

namespace hsmu::units {

enum class Dimension { Length, Force, Moment, Rotation, Time };

struct Unit {
    std::string symbol;  ///< as the tables above spell it ("kN m" for moments)
    Dimension dimension = Dimension::Length;
    double factor = 1.0; ///< value in the console's unit = value in this unit * factor
};

/// The unit `text` names if it is one of dimension d; nullopt otherwise.
std::optional<Unit> parse(std::string_view text, Dimension d);
/// A deformation unit: a length or a rotation.
std::optional<Unit> parseDeformation(std::string_view text);
/// A force unit or a moment unit.
std::optional<Unit> parseForce(std::string_view text);

/// The console's unit of d: "m", "kN", "kN m", "rad", "s".
const char* baseSymbol(Dimension d);
/// The accepted symbols of d, for messages: "m, cm, mm, in, ft"; moments: "a force unit times a
/// length unit, e.g. kN m, kip in, lbf ft, tonf m".
std::string accepted(Dimension d);
/// Words for d: "length", "force", "moment", "rotation", "time".
const char* dimensionName(Dimension d);

/// value in `unit` -> console unit, and back.
inline double toBase(double value, const Unit& unit) { return value * unit.factor; }
inline double fromBase(double value, const Unit& unit) { return value / unit.factor; }

} // namespace hsmu::units
