// Well-known text: POLYGON((x y, ...), (...)) and MULTIPOLYGON(((...)), ((...))).
// A small hand-written recursive-descent parser (depth is fixed by the grammar, so no stack
// risk). Keywords are case-insensitive; "Z", "M", "ZM" dimension tags (also run together,
// POLYGONZM) are accepted, and points of 2 to 4 ordinates with or without a tag, the extra
// ordinates dropped. EMPTY, as the grammar allows it: a whole POLYGON EMPTY has no rings (an
// error, as for JSON); an EMPTY hole or MULTIPOLYGON part is dropped with a warning.
// Numbers go through strtod, so "nan" and "inf" are read as such and left for validate() to
// report. Errors name NAME:LINE:COL of the offending token; echoed tokens are cut.
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <string>

#include "flood/io/io.h"
#include "io/io_util.h"

namespace flood {

namespace io_detail {
void addCleanRing(ReadResult& rr, const std::string& name, const std::vector<Point>& raw,
                  bool outer);
}

namespace {

struct WktError {
    size_t offset;
    std::string message;
};

class WktParser {
public:
    // `text` is `full` after a byte order mark, for warnings' line and column.
    WktParser(std::string_view full, std::string_view text, const std::string& name, ReadResult& rr)
        : full_(full), text_(text), name_(name), rr_(rr) {}

    void parse() {
        std::string kw = keyword("POLYGON or MULTIPOLYGON");
        for (const char* dim : {"ZM", "Z", "M"})  // POLYGONZM, as some writers spell it
            if (kw.size() > 7 &&
                kw.compare(kw.size() - std::strlen(dim), std::string::npos, dim) == 0) {
                std::string base = kw.substr(0, kw.size() - std::strlen(dim));
                if (base == "POLYGON" || base == "MULTIPOLYGON") kw = base;
                break;
            }
        bool multi;
        if (kw == "POLYGON") multi = false;
        else if (kw == "MULTIPOLYGON") multi = true;
        else
            throw WktError{tokStart_, "unsupported WKT geometry \"" + io_detail::echo(kw) +
                                          "\" (expected POLYGON or MULTIPOLYGON)"};
        skipSpace();
        if (peekWord()) {
            size_t at = pos_;
            std::string dim = keyword("");
            if (dim == "Z" || dim == "M" || dim == "ZM") {
                skipSpace();
                at = pos_;
                dim = peekWord() ? keyword("") : std::string();
            }
            if (dim == "EMPTY")
                throw WktError{at, multi ? "MULTIPOLYGON EMPTY: no polygon"
                                         : "POLYGON EMPTY: polygon has no rings"};
            if (!dim.empty())
                throw WktError{at, "unexpected \"" + io_detail::echo(dim) + "\" after " + kw};
        }
        if (multi) {
            size_t start = pos_;
            expect('(');
            do {
                skipSpace();
                size_t at = pos_;
                if (!polygon())
                    rr_.warn([&] { return where(at) + ": WKT: EMPTY polygon dropped"; });
            } while (accept(','));
            expect(')');
            if (rr_.polygon.rings.empty())
                throw WktError{start, "every polygon of the MULTIPOLYGON is EMPTY: no polygon"};
        } else {
            skipSpace();
            size_t at = pos_;
            if (!polygon()) throw WktError{at, "POLYGON (EMPTY): polygon has no rings"};
        }
        skipSpace();
        if (pos_ < text_.size() && text_[pos_] == ';') ++pos_;
        skipSpace();
        if (pos_ < text_.size()) throw WktError{pos_, "unexpected text after the geometry"};
    }

private:
    // Reads one polygon; false when it is EMPTY or its outer ring is (nothing was added).
    bool polygon() {
        if (acceptEmpty()) return false;
        expect('(');
        if (acceptEmpty()) {
            if (accept(','))
                throw WktError{pos_,
                               "the outer ring is EMPTY but holes follow: they have no outer ring"};
            expect(')');
            return false;
        }
        ring(true);
        while (accept(',')) {
            skipSpace();
            size_t at = pos_;
            if (acceptEmpty()) rr_.warn([&] { return where(at) + ": WKT: EMPTY hole dropped"; });
            else ring(false);
        }
        expect(')');
        return true;
    }

    // Consumes the keyword EMPTY where a ring or polygon may be empty.
    bool acceptEmpty() {
        skipSpace();
        if (!peekWord()) return false;
        size_t at = pos_;
        std::string w = keyword("");
        if (w != "EMPTY")
            throw WktError{at, "expected '(' or EMPTY, found \"" + io_detail::echo(w) + "\""};
        return true;
    }

    std::string where(size_t offset) const {
        return io_detail::where(name_, full_, offset + (full_.size() - text_.size()));
    }

    void ring(bool outer) {
        expect('(');
        std::vector<Point> raw;
        do {
            Point p;
            p.x = number();
            p.y = number();
            // Z and M ordinates: read and dropped.
            for (int extra = 0; extra < 2; ++extra) {
                skipSpace();
                if (pos_ >= text_.size() || !startsNumber()) break;
                number();
            }
            raw.push_back(p);
        } while (accept(','));
        expect(')');
        io_detail::addCleanRing(rr_, name_, raw, outer);
    }

    bool startsNumber() {
        char c = text_[pos_];
        return std::isdigit((unsigned char)c) || c == '-' || c == '+' || c == '.' ||
               std::tolower((unsigned char)c) == 'n' || std::tolower((unsigned char)c) == 'i';
    }

    double number() {
        skipSpace();
        size_t start = pos_;
        while (pos_ < text_.size() &&
               (std::isalnum((unsigned char)text_[pos_]) || text_[pos_] == '.' ||
                text_[pos_] == '-' || text_[pos_] == '+'))
            ++pos_;
        std::string tok(text_.substr(start, pos_ - start));
        if (tok.empty()) {
            throw WktError{start,
                           pos_ < text_.size()
                               ? std::string("expected a number, found '") + text_[pos_] + "'"
                               : std::string("expected a number, found end of input")};
        }
        char* end = nullptr;
        double v = std::strtod(tok.c_str(), &end);
        if (end != tok.c_str() + tok.size())
            throw WktError{start, "expected a number, found \"" + io_detail::echo(tok) + "\""};
        if (v == 0 && io_detail::underflows(tok))
            throw WktError{start, io_detail::underflowReason(tok)};
        return v;
    }

    bool peekWord() { return pos_ < text_.size() && std::isalpha((unsigned char)text_[pos_]); }

    std::string keyword(const char* what) {
        skipSpace();
        tokStart_ = pos_;
        std::string w;
        while (pos_ < text_.size() && std::isalnum((unsigned char)text_[pos_]))
            w += char(std::toupper((unsigned char)text_[pos_++]));
        if (w.empty())
            throw WktError{tokStart_, std::string("expected a WKT keyword (") + what + ")"};
        return w;
    }

    void skipSpace() {
        while (pos_ < text_.size() && std::isspace((unsigned char)text_[pos_])) ++pos_;
    }

    bool accept(char c) {
        skipSpace();
        if (pos_ < text_.size() && text_[pos_] == c) {
            ++pos_;
            return true;
        }
        return false;
    }

    void expect(char c) {
        skipSpace();
        if (pos_ >= text_.size())
            throw WktError{pos_, std::string("expected '") + c + "', found end of input"};
        if (text_[pos_] != c)
            throw WktError{pos_, std::string("expected '") + c + "', found '" + text_[pos_] + "'"};
        ++pos_;
    }

    std::string_view full_, text_;
    const std::string& name_;
    ReadResult& rr_;
    size_t pos_ = 0, tokStart_ = 0;
};

}  // namespace

ReadResult parseWkt(std::string_view text, const std::string& name) {
    ReadResult rr;
    // Skip a UTF-8 byte order mark, which would otherwise be an unexpected token.
    size_t skip = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
    std::string_view body = text.substr(skip);
    try {
        WktParser(text, body, name, rr).parse();
    } catch (const WktError& e) {
        rr.polygon = Polygon{};
        rr.diagnostic = {Status::Malformed,
                         io_detail::where(name, text, e.offset + skip) + ": WKT: " + e.message};
    }
    return rr;
}

}  // namespace flood
