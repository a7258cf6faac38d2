// Well-known text: POLYGON((x y, ...), (...)) and MULTIPOLYGON(((...)), ((...))).
// A small hand-written recursive-descent parser (depth is fixed by the grammar, so no stack
// risk). Keywords are case-insensitive; "Z", "M", "ZM" dimension tags are accepted and the
// extra ordinates ignored. Numbers go through strtod, so "nan" and "inf" are read as such and
// left for validate() to report. Errors name NAME:LINE:COL of the offending token.
#include <cctype>
#include <cstdlib>
#include <string>

#include "io.h"
#include "io_util.h"

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
    WktParser(std::string_view text, const std::string& name, ReadResult& rr)
        : text_(text), name_(name), rr_(rr) {}

    void parse() {
        std::string kw = keyword("POLYGON or MULTIPOLYGON");
        bool multi;
        if (kw == "POLYGON") multi = false;
        else if (kw == "MULTIPOLYGON") multi = true;
        else
            throw WktError{tokStart_, "unsupported WKT geometry \"" + kw +
                                          "\" (expected POLYGON or MULTIPOLYGON)"};
        skipSpace();
        if (peekWord()) {
            size_t at = pos_;
            std::string dim = keyword("");
            if (dim == "EMPTY") throw WktError{at, "empty geometry, no polygon"};
            if (dim != "Z" && dim != "M" && dim != "ZM")
                throw WktError{at, "unexpected \"" + dim + "\" after " + kw};
            skipSpace();
            if (peekWord()) {
                at = pos_;
                if (keyword("") == "EMPTY") throw WktError{at, "empty geometry, no polygon"};
                throw WktError{at, "expected '('"};
            }
        }
        if (multi) {
            expect('(');
            do polygon();
            while (accept(','));
            expect(')');
        } else {
            polygon();
        }
        skipSpace();
        if (pos_ < text_.size() && text_[pos_] == ';') ++pos_;
        skipSpace();
        if (pos_ < text_.size()) throw WktError{pos_, "unexpected text after the geometry"};
    }

private:
    void polygon() {
        expect('(');
        bool outer = true;
        do {
            ring(outer);
            outer = false;
        } while (accept(','));
        expect(')');
    }

    void ring(bool outer) {
        expect('(');
        std::vector<Point> raw;
        do {
            Point p;
            p.x = number();
            p.y = number();
            skipSpace();
            // Z and M ordinates: read and ignore.
            for (int extra = 0; extra < 2 && pos_ < text_.size() && startsNumber(); ++extra)
                number();
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
            throw WktError{start, pos_ < text_.size()
                                      ? std::string("expected a number, found '") +
                                            text_[pos_] + "'"
                                      : std::string("expected a number, found end of input")};
        }
        char* end = nullptr;
        double v = std::strtod(tok.c_str(), &end);
        if (end != tok.c_str() + tok.size())
            throw WktError{start, "expected a number, found \"" + tok + "\""};
        return v;
    }

    bool peekWord() {
        return pos_ < text_.size() && std::isalpha((unsigned char)text_[pos_]);
    }

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

    std::string_view text_;
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
        WktParser(body, name, rr).parse();
    } catch (const WktError& e) {
        rr.polygon = Polygon{};
        rr.diagnostic = {Status::Malformed,
                         io_detail::where(name, text, e.offset + skip) + ": WKT: " + e.message};
    }
    return rr;
}

}  // namespace flood
