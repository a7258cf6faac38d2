// Small helpers shared by the file-format code (internal to core/, not a public API).
#pragma once
#include <algorithm>
#include <charconv>
#include <cstddef>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "flood/geometry/polygon.h"
#include "geometry/number_text.h"

namespace flood::io_detail {

// The number text of every message and file (geometry/number_text.h).
using flood::formatDouble;
using flood::formatPoint;
using flood::kDoubleChars;
using flood::writeDouble;

// Input echoed into a message is cut to kEchoChars bytes and an ellipsis: a 10 MB literal
// must not become a 10 MB message. The cut never splits a UTF-8 sequence.
constexpr size_t kEchoChars = 60;
inline std::string echo(std::string_view s) {
    if (s.size() <= kEchoChars) return std::string(s);
    size_t n = kEchoChars;
    while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;
    return std::string(s.substr(0, n)) + "\u2026";
}

// nlohmann's what() reads "[json.exception.parse_error.101] parse error at line 1, column 5:
// syntax error ...; last read: '<token>'"; keep only the part after the position, which we
// print ourselves, with the echoed token cut.
inline std::string jsonReason(const char* what) {
    std::string s = what;
    size_t col = s.find("column ");
    size_t colon = col == std::string::npos ? col : s.find(": ", col);
    size_t bracket = s.find("] ");
    if (colon != std::string::npos) s = s.substr(colon + 2);
    else if (bracket != std::string::npos) s = s.substr(bracket + 2);
    const std::string lastRead = "last read: '";
    size_t q = s.find(lastRead);
    if (q != std::string::npos) {
        q += lastRead.size();
        size_t end = s.rfind('\'');
        std::string_view token =
            std::string_view(s).substr(q, end > q ? end - q : std::string::npos);
        std::string echoed = echo(token) + "'";  // before the resize: token views s
        s.resize(q);
        s += echoed;
    }
    return s;
}

// A NUL byte never occurs in JSON, WKT or a trace: the input is binary.
inline std::string binaryData(const std::string& name, size_t offset, const char* expected) {
    return name + ": binary data (a NUL byte at byte " + std::to_string(offset) + "), not " +
           expected;
}

// A feature's warnings name it, "NAME: ring 0 ..." becoming "NAME: feature 17: ring 0 ...":
// flood check reads thousands of features, and a warning must say which one it is about.
inline void nameFeature(std::vector<std::string>& warnings, const std::string& name,
                        const std::string& feature) {
    const std::string lead = name + ": ";
    for (std::string& w : warnings)
        if (w.compare(0, lead.size(), lead) == 0 &&
            w.compare(lead.size(), feature.size(), feature) != 0)
            w.insert(lead.size(), feature + ": ");
}

// 1-based line and column of byte `offset` in `text` (columns count bytes).
struct LineCol {
    size_t line = 1, col = 1;
};
inline LineCol lineColAt(std::string_view text, size_t offset) {
    LineCol lc;
    if (offset > text.size()) offset = text.size();
    for (size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++lc.line;
            lc.col = 1;
        } else {
            ++lc.col;
        }
    }
    return lc;
}

inline std::string where(const std::string& name, std::string_view text, size_t offset) {
    LineCol lc = lineColAt(text, offset);
    return name + ":" + std::to_string(lc.line) + ":" + std::to_string(lc.col);
}

// Bytes the fast JSON reader may read past the end of its text (simdjson's SIMDJSON_PADDING,
// checked in io_json_fast.cpp): readInputFile leaves that much spare capacity.
constexpr size_t kReadAhead = 64;

// nlohmann's parser recurses once per nesting level: deeper documents are refused up front.
constexpr int kMaxJsonDepth = 64;

// Scans brackets outside strings; returns the offset of the first bracket deeper than
// kMaxJsonDepth, or npos. Linear time, no recursion.
inline size_t tooDeep(std::string_view text) {
    int depth = 0;
    bool inString = false;
    for (size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
            continue;
        }
        if (c == '"') inString = true;
        else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth) return i;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return std::string_view::npos;
}

// A number literal (JSON or WKT) that is not zero but reads as 0: smaller than half the least
// double (about 2.5e-324). It is refused as one too large is ("number out of range"): reading
// it as 0 would move a vertex silently. A subnormal such as 1e-310 is a double, and is read.
inline bool underflows(std::string_view literal) {
    size_t mantissa = literal.find_first_of("eE");
    if (mantissa == std::string_view::npos) mantissa = literal.size();
    if (literal.substr(0, mantissa).find_first_of("123456789") == std::string_view::npos)
        return false;  // zero, whatever its exponent
    // Only a negative exponent or hundreds of digits can reach below the doubles.
    if (literal.find("e-") == std::string_view::npos &&
        literal.find("E-") == std::string_view::npos && literal.size() < 300)
        return false;
    std::string copy(literal);
    char* end = nullptr;
    double v = std::strtod(copy.c_str(), &end);
    return v == 0 && end != copy.c_str();
}

// The message for such a literal, after the location.
inline std::string underflowReason(std::string_view literal) {
    return "number out of range: " + echo(literal) +
           " underflows to 0 (the least double is 4.9e-324)";
}

// The first JSON number literal outside strings that underflows (above): its offset, or npos.
// Linear time; `text` is valid JSON (it has been parsed).
inline size_t firstUnderflow(std::string_view text) {
    for (size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (c == '"') {
            for (++i; i < text.size() && text[i] != '"'; ++i)
                if (text[i] == '\\') ++i;
            continue;
        }
        if (c != '-' && (c < '0' || c > '9')) continue;
        size_t j = i;
        bool small = false;  // a negative exponent: underflows() must look
        while (j < text.size() &&
               ((text[j] >= '0' && text[j] <= '9') || text[j] == '.' || text[j] == 'e' ||
                text[j] == 'E' || text[j] == '-' || text[j] == '+')) {
            small |= text[j] == '-' && j > i;
            ++j;
        }
        if ((small || j - i >= 300) && underflows(text.substr(i, j - i))) return i;
        i = j - 1;
    }
    return std::string_view::npos;
}

// The literal at `offset` (as firstUnderflow found it).
inline std::string_view literalAt(std::string_view text, size_t offset) {
    size_t j = offset;
    while (j < text.size() &&
           std::string_view("0123456789.eE+-").find(text[j]) != std::string_view::npos)
        ++j;
    return text.substr(offset, j - offset);
}

}  // namespace flood::io_detail
