// The chosen vertical (§3): the direction the water rises along. Any nonzero finite vector d;
// only its direction matters. Heights are compared exactly, as the sign of d·(b − a)
// (predicates.h: belowToward), never by rotating the coordinates: a rotation by an angle that
// is not a multiple of 90° is not exact in doubles.
#pragma once
#include <string>

namespace flood {

struct Up {
    double x = 0, y = 1;
    static const Up PlusY, MinusY, PlusX, MinusX;
    // Along an axis: heights are then plain coordinate comparisons (the machine's fast path).
    bool axis() const { return x == 0 || y == 0; }
    // Nonzero and finite: something water can rise along.
    bool valid() const;
};
inline constexpr Up Up::PlusY{0, 1};
inline constexpr Up Up::MinusY{0, -1};
inline constexpr Up Up::PlusX{1, 0};
inline constexpr Up Up::MinusX{-1, 0};
inline bool operator==(Up a, Up b) { return a.x == b.x && a.y == b.y; }
inline bool operator!=(Up a, Up b) { return !(a == b); }

// Degrees counter-clockwise from +x: 90 is +y, 0 is +x, 180 is -x, 270 (or -90) is -y.
// Multiples of 90 give the exact axis vectors (cos 90° is not 0 in doubles).
Up upFromDegrees(double degrees);
// The direction's angle in degrees, in [0, 360).
double upDegrees(Up up);
// "+y", "-y", "+x", "-x" for the axis constants, else "X,Y" (shortest exact decimals).
std::string upName(Up up);
// What --up accepts: +y, y, -y, +x, x, -x, an angle in degrees ("17", "-30.5"), or "X,Y".
// False, with `why` saying what is wrong with `text`, otherwise.
bool parseUp(const std::string& text, Up& out, std::string& why);

}  // namespace flood
