#include "flood/geometry/up.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace flood {

bool Up::valid() const { return std::isfinite(x) && std::isfinite(y) && (x != 0 || y != 0); }

Up upFromDegrees(double degrees) {
    double a = std::fmod(degrees, 360.0);  // exact
    if (a < 0) a += 360.0;
    if (a == 0) return Up::PlusX;
    if (a == 90) return Up::PlusY;
    if (a == 180) return Up::MinusX;
    if (a == 270) return Up::MinusY;
    const double r = a * (M_PI / 180.0);
    return {std::cos(r), std::sin(r)};
}

double upDegrees(Up up) {
    double a = std::atan2(up.y, up.x) * (180.0 / M_PI);
    if (up.axis()) a = up.x > 0 ? 0 : up.y > 0 ? 90 : up.x < 0 ? 180 : 270;  // exact for the axes
    return a < 0 ? a + 360.0 : a;
}

namespace {
std::string shortest(double v) {
    char buf[32];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(buf, sizeof buf, "%.*g", digits, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
}

// The whole of `s` as a finite double.
bool number(const std::string& s, double& v) {
    if (s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) return false;
    char* end = nullptr;
    v = std::strtod(s.c_str(), &end);  // a subnormal is kept (underflow is not an error here)
    return end == s.c_str() + s.size() && std::isfinite(v);
}
}  // namespace

std::string upName(Up up) {
    if (up == Up::PlusY) return "+y";
    if (up == Up::MinusY) return "-y";
    if (up == Up::PlusX) return "+x";
    if (up == Up::MinusX) return "-x";
    return shortest(up.x) + "," + shortest(up.y);
}

bool parseUp(const std::string& text, Up& out, std::string& why) {
    const char* axes[][2] = {{"+y", "y"}, {"-y", nullptr}, {"+x", "x"}, {"-x", nullptr}};
    const Up axis[] = {Up::PlusY, Up::MinusY, Up::PlusX, Up::MinusX};
    for (int i = 0; i < 4; ++i)
        if (text == axes[i][0] || (axes[i][1] && text == axes[i][1])) {
            out = axis[i];
            return true;
        }
    const std::string hint =
        " (write +y, -y, +x, -x, an angle in degrees counter-clockwise from +x, or X,Y)";
    const size_t comma = text.find(',');
    if (comma == std::string::npos) {
        double degrees;
        if (!number(text, degrees)) {
            why = "'" + text + "' is not a direction" + hint;
            return false;
        }
        out = upFromDegrees(degrees);
        return true;
    }
    Up d;
    if (!number(text.substr(0, comma), d.x) || !number(text.substr(comma + 1), d.y)) {
        why = "'" + text + "' is not a direction: X and Y must be finite numbers" + hint;
        return false;
    }
    if (!d.valid()) {
        why = "'" + text + "' is not a direction: the vector is zero";
        return false;
    }
    out = d;
    return true;
}

}  // namespace flood
