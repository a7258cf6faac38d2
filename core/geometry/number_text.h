// Numbers as every message, file and panel writes them: the shortest decimal text that reads
// back as the same double (-127.71, never -127.70999999999999); "nan", "inf", "-inf" for the
// non-finite values, which JSON cannot hold but messages and WKT can.
#pragma once
#include <algorithm>
#include <charconv>
#include <cstddef>
#include <string>

#include "flood/geometry/polygon.h"

namespace flood {

// Writes it at `to` (room for kDoubleChars) and returns the end.
constexpr size_t kDoubleChars = 32;
inline char* writeDouble(char* to, double v) {
    auto copy = [to](const char* s, size_t k) { return std::copy(s, s + k, to); };
    if (v != v) return copy("nan", 3);
    if (v == 1.0 / 0.0) return copy("inf", 3);
    if (v == -1.0 / 0.0) return copy("-inf", 4);
#ifdef FLOOD_DOUBLE_CHARCONV  // the web build's libc++ has none for double (web/charconv_double.h)
    return web::toChars(to, to + kDoubleChars, v).ptr;
#else
    return std::to_chars(to, to + kDoubleChars, v).ptr;
#endif
}

// Reads the longest number at [first, last), correctly rounded, as std::from_chars does.
inline std::from_chars_result readDouble(const char* first, const char* last, double& v) {
#ifdef FLOOD_DOUBLE_CHARCONV
    return web::fromChars(first, last, v);
#else
    return std::from_chars(first, last, v);
#endif
}
inline std::string formatDouble(double v) {
    char buf[kDoubleChars];
    return std::string(buf, writeDouble(buf, v));
}

inline std::string formatPoint(Point p) {
    return "(" + formatDouble(p.x) + ", " + formatDouble(p.y) + ")";
}

}  // namespace flood
