// The web build only (cmake/web.cmake passes it with -include): Emscripten 3.1.6's libc++ has
// no std::to_chars / std::from_chars for double, which the core uses for every number it reads
// and writes. geometry/number_text.h's writeDouble and readDouble call these instead when
// FLOOD_DOUBLE_CHARCONV is defined (adding overloads to namespace std would be undefined
// behaviour). They give the same text as libstdc++'s (the shortest that reads back
// as the same double, %f or %e whichever is shorter, %f on a tie) and the same values (correctly
// rounded), through double-conversion; printf and strtod are exact there too but 30-50x slower.
#pragma once
#ifdef __cplusplus
#include <charconv>
#include <cmath>
#include <cstring>
#include <system_error>

#include <double-conversion/double-to-string.h>
#include <double-conversion/string-to-double.h>

// Tells geometry/number_text.h to use these.
#define FLOOD_DOUBLE_CHARCONV 1

namespace flood::web {

using std::errc;
using std::from_chars_result;
using std::to_chars_result;

inline to_chars_result toChars(char* first, char* last, double v) {
    using double_conversion::DoubleToStringConverter;
    char text[40];  // sign, digits, point or zeros, exponent
    char* p = text;
    if (std::signbit(v)) *p++ = '-';
    if (std::isnan(v) || std::isinf(v)) {
        std::memcpy(p, std::isnan(v) ? "nan" : "inf", 3);
        p += 3;
    } else {
        char digits[18];
        bool sign = false;
        int n = 0, point = 0;  // v = 0.d1...dn * 10^point
        DoubleToStringConverter::DoubleToAscii(v, DoubleToStringConverter::SHORTEST, 0, digits,
                                               sizeof digits, &sign, &n, &point);
        const int exponent = point - 1, e = exponent < 0 ? -exponent : exponent;
        const int fixedLength = point <= 0 ? 2 - point + n : point < n ? n + 1 : point;
        const int sciLength = n + (n > 1) + 2 + (e >= 100 ? 3 : 2);
        if (fixedLength <= sciLength) {
            if (point <= 0) {
                *p++ = '0', *p++ = '.';
                for (int i = 0; i < -point; ++i) *p++ = '0';
                std::memcpy(p, digits, size_t(n)), p += n;
            } else if (point < n) {
                std::memcpy(p, digits, size_t(point)), p += point;
                *p++ = '.';
                std::memcpy(p, digits + point, size_t(n - point)), p += n - point;
            } else {
                std::memcpy(p, digits, size_t(n)), p += n;
                for (int i = n; i < point; ++i) *p++ = '0';
            }
        } else {
            *p++ = digits[0];
            if (n > 1) {
                *p++ = '.';
                std::memcpy(p, digits + 1, size_t(n - 1)), p += n - 1;
            }
            *p++ = 'e', *p++ = exponent < 0 ? '-' : '+';
            if (e >= 100) *p++ = char('0' + e / 100);
            *p++ = char('0' + e / 10 % 10), *p++ = char('0' + e % 10);
        }
    }
    const size_t length = size_t(p - text);
    if (size_t(last - first) < length) return {last, errc::value_too_large};
    std::memcpy(first, text, length);
    return {first + length, errc()};
}

// As libstdc++ does: the longest prefix that is a number (no '+', no leading space, no hex),
// result_out_of_range (value untouched) for one beyond the double range or a nonzero one that
// rounds to zero.
inline from_chars_result fromChars(const char* first, const char* last, double& value) {
    using double_conversion::StringToDoubleConverter;
    static const StringToDoubleConverter converter(StringToDoubleConverter::ALLOW_TRAILING_JUNK,
                                                   0.0, std::nan(""), "inf", "nan");
    const char* p = first + (first < last && *first == '-');
    if (p == last || !((*p >= '0' && *p <= '9') || *p == '.' || *p == 'i' || *p == 'n'))
        return {first, errc::invalid_argument};
    int used = 0;
    const double d = converter.StringToDouble(first, int(last - first), &used);
    if (used == 0) return {first, errc::invalid_argument};
    const char* end = first + used;
    const bool literalInf = *p == 'i';
    bool nonzero = false;
    for (const char* q = p; q < end && *q != 'e' && *q != 'E'; ++q)
        nonzero |= *q >= '1' && *q <= '9';
    if ((std::isinf(d) && !literalInf) || (d == 0 && nonzero))
        return {end, errc::result_out_of_range};
    value = d;
    return {end, errc()};
}

}  // namespace flood::web
#endif
