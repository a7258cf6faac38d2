// Seeded generator of valid polygons in many families (see generate.h).
//
// Validity by construction: most families use small integer coordinates, where simplicity
// follows from the construction (monotone chains, disjoint cells, offsets at safe spacing).
// Curved families use double coordinates from our own sin/cos (deterministic: only +, -, *, /)
// and are filtered to stay strictly star-shaped around their centre, which proves simplicity.
//
// [SECTION] index: PRNG and math | helpers | families | table and API | transform |
//                 (the invalid families: generate_invalid.cpp)
#include "flood/tools/generate.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "flood/geometry/predicates.h"
#include "flood/io/io.h"
#include "tools/generate_parts.h"

namespace flood {

namespace generate_detail {

// [SECTION] PRNG and math (the PRNG itself: generate_parts.h)

constexpr double kPi = 3.14159265358979323846;

// sin and cos of x by quadrant reduction and Taylor series on [-pi/4, pi/4]: reproducible
// bit for bit on any IEEE platform (fp contraction is off in this project).
void sinCos(double x, double& s, double& c) {
    double q = std::floor(x / (kPi / 2) + 0.5);
    double r = x - q * (kPi / 2);
    double r2 = r * r;
    double sr = r, term = r;
    for (int k = 1; k <= 10; ++k) {
        term = -term * r2 / double((2 * k) * (2 * k + 1));
        sr += term;
    }
    double cr = 1;
    term = 1;
    for (int k = 1; k <= 10; ++k) {
        term = -term * r2 / double((2 * k - 1) * (2 * k));
        cr += term;
    }
    long quadrant = long(q) & 3;
    switch (quadrant) {
        case 0: s = sr, c = cr; break;
        case 1: s = cr, c = -sr; break;
        case 2: s = -sr, c = -cr; break;
        default: s = -cr, c = sr; break;
    }
}

// [SECTION] helpers

// Drops vertices until every consecutive pair turns strictly counter-clockwise around `centre`:
// the ring is then star-shaped around it, hence simple. The input goes once around, in order.
Pts keepStarShaped(Pts ring, Point centre) {
    bool changed = true;
    while (changed && ring.size() >= 3) {
        changed = false;
        Pts out;
        out.reserve(ring.size());
        for (size_t i = 0; i < ring.size(); ++i) {
            const Point& prev = out.empty() ? ring.back() : out.back();
            if (orient(centre, prev, ring[i]) > 0) out.push_back(ring[i]);
            else changed = true;
        }
        if (out.size() >= 2 && orient(centre, out.back(), out.front()) <= 0) {
            out.pop_back();
            changed = true;
        }
        ring.swap(out);
    }
    return ring;
}

// Points on a circle-like closed curve of radius radius(i) around c, n of them, star-shaped.
template <class Radius>
Pts radialRing(Point c, size_t n, Radius radius, double phase = 0) {
    Pts ring;
    ring.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        double s, co;
        sinCos(phase + 2 * kPi * double(i) / double(n), s, co);
        double r = radius(i);
        ring.push_back({c.x + r * co, c.y + r * s});
    }
    return keepStarShaped(ring, c);
}

// The polygon bounded by `ring` alone.
Polygon outerRing(const Pts& ring) {
    Polygon p;
    p.addRing(ring, true);
    return p;
}

// x-monotone orthogonal polygon, the union of columns [xs[j], xs[j+1]] x [bottom[j], top[j]];
// neighbouring columns must overlap vertically. Counter-clockwise.
Pts columnsRing(const std::vector<int>& xs, const std::vector<int>& bottom,
                const std::vector<int>& top) {
    size_t m = bottom.size();
    Pts r;
    r.push_back(pt(xs[0], bottom[0]));
    for (size_t j = 1; j < m; ++j)
        if (bottom[j] != bottom[j - 1]) {
            r.push_back(pt(xs[j], bottom[j - 1]));
            r.push_back(pt(xs[j], bottom[j]));
        }
    r.push_back(pt(xs[m], bottom[m - 1]));
    r.push_back(pt(xs[m], top[m - 1]));
    for (size_t j = m - 1; j >= 1; --j)
        if (top[j] != top[j - 1]) {
            r.push_back(pt(xs[j], top[j]));
            r.push_back(pt(xs[j], top[j - 1]));
        }
    r.push_back(pt(xs[0], top[0]));
    return r;
}

// Inserts 0..maxExtra collinear vertices on each edge at exact dyadic fractions k/4.
Pts addCollinear(const Pts& ring, Rng& rng, int maxExtra) {
    Pts out;
    for (size_t i = 0; i < ring.size(); ++i) {
        Point p = ring[i], q = ring[(i + 1) % ring.size()];
        out.push_back(p);
        int extra = rng.range(0, maxExtra);
        int k = 0;
        for (int e = 0; e < extra && k < 3; ++e) {
            k = rng.range(k + 1, 3);
            out.push_back({p.x + (q.x - p.x) * (k * 0.25), p.y + (q.y - p.y) * (k * 0.25)});
        }
    }
    return out;
}

// [SECTION] families

// Star-shaped polygon with random radii, integer coordinates.
Polygon star(Rng& rng, size_t size) {
    size_t n = std::max<size_t>(3, size);
    const double R = 1 << 22;
    Pts ring;
    for (size_t i = 0; i < n; ++i) {
        double s, c;
        sinCos(2 * kPi * (double(i) + 0.45 * rng.unit()) / double(n), s, c);
        double r = R * (0.15 + 0.85 * rng.unit());
        ring.push_back({std::round(r * c), std::round(r * s)});
    }
    ring = keepStarShaped(ring, {0, 0});
    if (ring.size() < 3) ring = {{-R, -R}, {R, -R}, {0, R}};
    return outerRing(ring);
}

Polygon circleSmooth(Rng& rng, size_t size) {
    Pts ring = radialRing({0, 0}, std::max<size_t>(3, size),
                          [&](size_t) { return 1.0 + 0.01 * rng.unit(); });
    return outerRing(ring);
}

Polygon circleJagged(Rng& rng, size_t size) {
    Pts ring = radialRing({0, 0}, std::max<size_t>(4, size), [&](size_t i) {
        return (i & 1) ? 0.2 + 0.5 * rng.unit() : 0.8 + 0.2 * rng.unit();
    });
    return outerRing(ring);
}

// Circle with K circular holes, one per grid cell well inside the circle.
// A circle (outer radius 1 + noise·U[0,1)) with k circular holes, one per cell of a square
// grid, each cell well inside the circle.
Polygon circleWithHoles(Rng& rng, size_t size, size_t k, double noise) {
    size_t outerN = std::max<size_t>(8, size / 2);
    size_t holeN = std::max<size_t>(3, (size / 2) / k);
    // Inner radius of the outer polygon, with margin.
    double safe = 0.95 * std::cos(kPi / double(outerN));
    std::vector<Point> cells;
    double cell = 0;
    for (int g = 2;; ++g) {
        cells.clear();
        cell = 2.0 / g;
        for (int i = 0; i < g; ++i)
            for (int j = 0; j < g; ++j) {
                Point c{-1 + cell * (i + 0.5), -1 + cell * (j + 0.5)};
                if (std::sqrt(c.x * c.x + c.y * c.y) + cell * 0.75 < safe) cells.push_back(c);
            }
        if (cells.size() >= k) break;
    }
    while (cells.size() > k) cells.erase(cells.begin() + long(rng.next() % cells.size()));
    Polygon p;
    p.addRing(radialRing({0, 0}, outerN, [&](size_t) { return 1.0 + noise * rng.unit(); }), true);
    for (Point c : cells) {
        double r = cell * 0.5 * (0.4 + 0.5 * rng.unit());
        Pts hole = radialRing(
            c, holeN, [&](size_t) { return r; }, rng.unit());
        if (hole.size() >= 3) p.addRing(hole, false);
    }
    return p;
}

Polygon circleHoles(Rng& rng, size_t size) {
    return circleWithHoles(rng, size, std::max<size_t>(1, size / 24), 0);
}

// The benchmark family of the issue: K = sqrt(N)/2 holes in a 1%-noisy circle.
Polygon circleSqrtHoles(Rng& rng, size_t size) {
    size_t k = std::max<size_t>(1, size_t(std::lround(std::sqrt(double(size)) / 2)));
    return circleWithHoles(rng, size, k, 0.01);
}

// Square with a k x k grid of holes (squares, triangles, diamonds) in 2 x 2 cells.
Polygon gridHoles(Rng& rng, size_t size) {
    int k = std::max(1, int(std::sqrt(double(size) / 4.0)));
    double side = 3.0 * k + 1;
    Polygon p;
    p.addRing({{0, 0}, {side, 0}, {side, side}, {0, side}}, true);
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
            double a = 3.0 * i + 1, b = 3.0 * j + 1;
            switch (rng.range(0, 2)) {
                case 0: p.addRing({{a, b}, {a + 2, b}, {a + 2, b + 2}, {a, b + 2}}, false); break;
                case 1: p.addRing({{a, b}, {a + 2, b}, {a + 1, b + 2}}, false); break;
                default: p.addRing({{a + 1, b}, {a + 2, b + 1}, {a + 1, b + 2}, {a, b + 1}}, false);
            }
        }
    return p;
}

// Zigzag comb: teeth down along the bottom (bottoms, with ceilings between them) and up along
// the top (tops, with sags between them).
Polygon comb(Rng& rng, size_t size, int heightRange) {
    int m = std::max(2, int(size / 4));
    Pts r;
    for (int i = 0; i <= 2 * m; ++i)
        r.push_back(pt(i, (i & 1) ? -rng.range(1, heightRange) : rng.range(0, 1)));
    const int H = 4;
    for (int i = 2 * m; i >= 0; --i)
        r.push_back(pt(i, (i & 1) ? H + rng.range(1, heightRange) : H - rng.range(0, 1)));
    return outerRing(r);
}

// m random columns 1..maxWidth wide; heights(j) gives column j's {bottom, top} (drawn after
// its width, so each family's random sequence is what it always was).
template <class Heights>
Polygon randomColumns(Rng& rng, int m, int maxWidth, Heights&& heights) {
    std::vector<int> xs{0}, bottom, top;
    for (int j = 0; j < m; ++j) {
        xs.push_back(xs.back() + rng.range(1, maxWidth));
        auto [b, t] = heights(j);
        bottom.push_back(b);
        top.push_back(t);
    }
    return outerRing(columnsRing(xs, bottom, top));
}

// Orthogonal comb: rectangular teeth up and down with many equal heights.
Polygon combRect(Rng& rng, size_t size) {
    return randomColumns(rng, std::max(2, int(size / 3)), 3, [&rng](int j) {
        bool tooth = j & 1;
        int bottom = tooth && rng.range(0, 1) ? -rng.range(1, 4) * 2 : 0;
        int top = tooth && rng.range(0, 1) ? 10 + rng.range(1, 4) * 2 : 10;
        return std::pair{bottom, top};
    });
}

// Random orthogonal x-monotone polygon: columns with random tops and bottoms.
Polygon orthoHistogram(Rng& rng, size_t size) {
    return randomColumns(rng, std::max(1, int(size / 4)), 4, [&rng](int) {
        int bottom = -rng.range(0, 10);
        return std::pair{bottom, rng.range(1, 10)};
    });
}

// Monotone staircase: random step widths and heights.
Polygon staircase(Rng& rng, size_t size) {
    int steps = std::max(1, int(size / 2) - 1);
    std::vector<int> w(steps), h(steps);
    int W = 0;
    for (int k = 0; k < steps; ++k) W += (w[k] = rng.range(1, 3)), h[k] = rng.range(1, 3);
    Pts r{{0, 0}, {double(W), 0}};
    double x = W, y = 0;
    for (int k = 0; k < steps; ++k) {
        y += h[k];
        r.push_back({x, y});
        x -= w[k];
        r.push_back({x, y});
    }
    return outerRing(r);
}

// Corridor of half-width 1 around a square spiral centreline with spacing 4.
Polygon orthoSpiral(Rng&, size_t size) {
    int segs = std::max(2, int(size / 2));
    const int dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};
    Pts centre{{0, 0}};
    for (int k = 0; k < segs; ++k) {
        int len = 4 * (k / 2 + 1);
        centre.push_back({centre.back().x + dx[k % 4] * len, centre.back().y + dy[k % 4] * len});
    }
    auto normal = [&](int k) { return Point{double(-dy[k % 4]), double(dx[k % 4])}; };
    Pts left, right;
    for (int i = 0; i <= segs; ++i) {
        Point n{0, 0};
        if (i > 0) n = {n.x + normal(i - 1).x, n.y + normal(i - 1).y};
        if (i < segs) n = {n.x + normal(i).x, n.y + normal(i).y};
        left.push_back({centre[i].x + n.x, centre[i].y + n.y});
        right.push_back({centre[i].x - n.x, centre[i].y - n.y});
    }
    Pts r = left;
    r.insert(r.end(), right.rbegin(), right.rend());
    return outerRing(r);
}

// Smooth Archimedean spiral band, double coordinates.
Polygon spiral(Rng& rng, size_t size) {
    int turns = std::max(1, std::min(40, int(size / 300) + 1));
    size_t perTurn =
        std::max<size_t>(size / (2 * size_t(turns)), size_t(8 * std::sqrt(turns + 2.0) + 16));
    size_t n = perTurn * turns;
    double phase = rng.unit() * 2 * kPi;
    Pts outer, inner;
    for (size_t i = 0; i <= n; ++i) {
        double t = 2 * kPi * double(i) / double(perTurn);
        double s, c;
        sinCos(t + phase, s, c);
        double r = 1 + t / (2 * kPi);
        outer.push_back({(r + 0.25) * c, (r + 0.25) * s});
        inner.push_back({(r - 0.25) * c, (r - 0.25) * s});
    }
    Pts ring = outer;
    ring.insert(ring.end(), inner.rbegin(), inner.rend());
    return outerRing(ring);
}

// Zigzag on the integer grid with heights from a tiny set: many equal heights.
Polygon equalHeights(Rng& rng, size_t size) {
    int m = std::max(2, int(size / 2));
    Pts r;
    for (int i = 0; i < m; ++i) r.push_back(pt(i, rng.range(0, 2)));
    for (int i = m - 1; i >= 0; --i) r.push_back(pt(i, rng.range(3, 5)));
    return outerRing(r);
}

// A histogram or a star with extra vertices inserted on its edges, and a collinear hole.
Polygon collinear(Rng& rng, size_t size) {
    Polygon base = rng.range(0, 1) ? orthoHistogram(rng, std::max<size_t>(4, size / 3))
                                   : star(rng, std::max<size_t>(3, size / 3));
    Pts ring(base.vertices.begin(), base.vertices.end());
    return outerRing(addCollinear(ring, rng, 3));
}

// Rectangle whose bottom and top edges carry vertices every 4 units; triangular holes touch
// the outer ring at some of these vertices (one shared point each).
Polygon touchingOuter(Rng& rng, size_t size) {
    int k = std::max(2, int(size / 8));
    const double H = 6;
    Pts outer;
    for (int i = 0; i <= k; ++i) outer.push_back(pt(4 * i, 0));
    for (int i = k; i >= 0; --i) outer.push_back(pt(4 * i, H));
    Polygon p;
    p.addRing(outer, true);
    for (int i = 1; i < k; ++i) {
        double x = 4 * i;
        if (rng.range(0, 3) != 0) {
            double h = rng.range(1, 2);
            p.addRing({{x, 0}, {x + 1, h}, {x - 1, h}}, false);
        }
        if (rng.range(0, 3) != 0) {
            double h = rng.range(1, 2);
            p.addRing({{x, H}, {x - 1, H - h}, {x + 1, H - h}}, false);
        }
    }
    return p;
}

// Rows of diamond holes, each touching its neighbours at a shared tip.
Polygon touchingHoles(Rng& rng, size_t size) {
    int total = std::max(2, int(size / 4));
    int rows = std::max(1, int(std::sqrt(total / 4.0)));
    int k = std::max(2, total / rows);
    Polygon p;
    p.addRing({{0, 0}, {4.0 * k + 2, 0}, {4.0 * k + 2, 6.0 * rows}, {0, 6.0 * rows}}, true);
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < k; ++i) {
            double cx = 4 * i + 3, cy = 6 * j + 3;
            double down = rng.range(1, 2), up = rng.range(1, 2);
            p.addRing({{cx - 2, cy}, {cx, cy - down}, {cx + 2, cy}, {cx, cy + up}}, false);
        }
    return p;
}

// Building floor plan: rooms on a grid; walls are plus-shaped holes at inner wall crossings
// (doors between their arms) and stubs from the outer wall.
Polygon rooms(Rng& rng, size_t size) {
    int a = std::max(2, int(std::sqrt(double(size) / 9.0)) + 1);
    int b = std::max(2, int(a * (0.5 + rng.unit())));
    const int c = 10;
    Pts outer;
    auto stubs = [&](bool bottomEdge) {
        // Along the bottom edge left to right (or top edge right to left).
        for (int ii = 1; ii < a; ++ii) {
            int i = bottomEdge ? ii : a - ii;
            double x = c * i, y = bottomEdge ? 0 : c * b;
            double len = rng.range(0, 3);
            if (len == 0) continue;
            double in = bottomEdge ? len : -len;
            if (bottomEdge)
                outer.insert(outer.end(),
                             {{x - 1, y}, {x - 1, y + in}, {x + 1, y + in}, {x + 1, y}});
            else
                outer.insert(outer.end(),
                             {{x + 1, y}, {x + 1, y + in}, {x - 1, y + in}, {x - 1, y}});
        }
    };
    outer.push_back(pt(0, 0));
    stubs(true);
    outer.push_back(pt(c * a, 0));
    outer.push_back(pt(c * a, c * b));
    stubs(false);
    outer.push_back(pt(0, c * b));
    Polygon p;
    p.addRing(outer, true);
    for (int i = 1; i < a; ++i)
        for (int j = 1; j < b; ++j) {
            if (rng.range(0, 5) == 0) continue;  // an open hall
            double X = c * i, Y = c * j;
            double e = rng.range(2, 4), w = rng.range(2, 4), n = rng.range(2, 4),
                   s = rng.range(2, 4);
            p.addRing({{X - 1, Y - s},
                       {X + 1, Y - s},
                       {X + 1, Y - 1},
                       {X + e, Y - 1},
                       {X + e, Y + 1},
                       {X + 1, Y + 1},
                       {X + 1, Y + n},
                       {X - 1, Y + n},
                       {X - 1, Y + 1},
                       {X - w, Y + 1},
                       {X - w, Y - 1},
                       {X - 1, Y - 1}},
                      false);
        }
    return p;
}

// T-junctions: triangular holes whose apex lies inside an edge of the outer parallelogram
// (bottom, top and the 45-degree left side), and a middle row of square holes, each touched
// inside its right edge by the apex of a triangle hole. Integer coordinates, exact on the
// edges. validate() records the splits.
Polygon tJunctions(Rng& rng, size_t size) {
    int k = std::max(2, int(size / 16));
    double W = 4.0 * k + 4, H = 12, S = H;
    Polygon p;
    p.addRing({{0, 0}, {W, 0}, {W + S, H}, {S, H}}, true);
    for (int i = 1; i <= k; ++i) {
        double x = 4 * i;
        if (rng.range(0, 3) != 0) {  // apex inside the bottom edge
            double h = rng.range(1, 2);
            p.addRing({{x, 0}, {x + 1, h}, {x - 1, h}}, false);
        }
        if (rng.range(0, 3) != 0) {  // apex inside the top edge
            double h = rng.range(1, 2), xt = x + S;
            p.addRing({{xt, H}, {xt - 1, H - h}, {xt + 1, H - h}}, false);
        }
        // A square at height 5..7, a triangle touching its right edge at height 5, 6 or 7 -
        // only strictly inside the edge, so 6 unless the square is taller.
        double x0 = x + 5, top = 7 + rng.range(0, 1);
        p.addRing({{x0, 5}, {x0 + 1, 5}, {x0 + 1, top}, {x0, top}}, false);
        if (rng.range(0, 2) != 0) {
            double ay = 6 + (top > 7 ? rng.range(0, 1) : 0);
            p.addRing({{x0 + 1, ay}, {x0 + 2.5, ay - 0.5}, {x0 + 2.5, ay + 0.5}}, false);
        }
    }
    // On the left side (t, t), clear of the other holes: a triangle with its apex inside it.
    if (rng.range(0, 1)) p.addRing({{4, 4}, {5.5, 4}, {5.5, 5}}, false);
    validate(p, "t-junctions");  // records the T-junctions in p.splits (the only family with any)
    return p;
}

// Steiner points: a square of cells, each empty, a square hole, or up to three single-point
// holes at distinct integer points (many equal heights).
Polygon steinerPoints(Rng& rng, size_t size) {
    int k = std::max(2, int(std::sqrt(double(size) / 2.5)));
    Polygon p;
    p.addRing({{0, 0}, {4.0 * k, 0}, {4.0 * k, 4.0 * k}, {0, 4.0 * k}}, true);
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
            double x = 4 * i, y = 4 * j;
            int kind = rng.range(0, 3);
            if (kind == 0) {
                p.addRing({{x + 1, y + 1}, {x + 3, y + 1}, {x + 3, y + 3}, {x + 1, y + 3}}, false);
                continue;
            }
            bool used[3][3] = {};
            for (int m = 0; m < kind; ++m) {
                int a = rng.range(0, 2), b = rng.range(0, 2);
                if (used[a][b]) continue;
                used[a][b] = true;
                p.addRing({{x + 1 + a, y + 1 + b}}, false);
            }
        }
    return p;
}

// Several separate parts in a row, each a square, most with a square hole.
Polygon islands(Rng& rng, size_t size) {
    int k = std::max(2, int(size / 8));
    Polygon p;
    for (int i = 0; i < k; ++i) {
        double x = 4 * i, y = rng.range(0, 2);
        p.addRing({{x, y}, {x + 3, y}, {x + 3, y + 3}, {x, y + 3}}, true);
        if (rng.range(0, 3) != 0)
            p.addRing({{x + 1, y + 1}, {x + 2, y + 1}, {x + 2, y + 2}, {x + 1, y + 2}}, false);
    }
    return p;
}

// [SECTION] table and API

const Family kFamilies[] = {
    {"star", "star-shaped polygon with random radii, integer coordinates", star},
    {"circle-smooth", "circle with 1% radial noise, double coordinates", circleSmooth},
    {"circle-jagged", "circle with alternating long and short random radii", circleJagged},
    {"circle-holes", "circle with K circular holes, one per grid cell inside it", circleHoles},
    {"circle-sqrt-holes", "1%-noisy circle with sqrt(N)/2 circular holes (the benchmark's)",
     circleSqrtHoles},
    {"grid-holes", "square with a grid of square, triangle and diamond holes", gridHoles},
    {"comb", "zigzag comb: teeth down (bottoms, ceilings) and up (tops, sags)",
     [](Rng& r, size_t s) { return comb(r, s, 6); }},
    {"comb-rect", "orthogonal comb with rectangular teeth up and down, equal heights", combRect},
    {"ortho-histogram", "random orthogonal x-monotone polygon of columns", orthoHistogram},
    {"staircase", "orthogonal monotone staircase with random steps", staircase},
    {"ortho-spiral", "orthogonal corridor around a square spiral", orthoSpiral},
    {"spiral", "smooth Archimedean spiral band, double coordinates", spiral},
    {"equal-heights", "integer zigzag with heights from {0..5}: many equal heights", equalHeights},
    {"collinear", "histogram or star with extra collinear vertices on its edges", collinear},
    {"touching-outer", "triangular holes touching the outer ring at shared vertices",
     touchingOuter},
    {"touching-holes", "rows of diamond holes touching each other at shared tips", touchingHoles},
    {"rooms", "floor plan: plus-shaped wall holes, wall stubs on the outer ring", rooms},
    {"islands", "several separate square parts, most with a square hole", islands},
    {"t-junctions", "holes touching the outer ring and each other inside edges (T-junctions)",
     tJunctions},
    {"steiner", "single-point holes (Steiner points) and square holes on a grid of cells",
     steinerPoints},
};

}  // namespace generate_detail

using generate_detail::descriptionIn;
using generate_detail::kFamilies;
using generate_detail::makeFrom;
using generate_detail::namesOf;

std::vector<std::string> familyNames() { return namesOf(kFamilies); }
std::string familyDescription(const std::string& family) {
    return descriptionIn(kFamilies, family);
}
Polygon generate(const std::string& family, uint64_t seed, size_t size) {
    return makeFrom(kFamilies, family, seed, size, 0x1234567);
}

// [SECTION] transform

Polygon transform(const Polygon& polygon, int rotation90, bool mirror, bool reverse, size_t shift) {
    Polygon out = polygon;
    int rot = ((rotation90 % 4) + 4) % 4;
    for (Point& v : out.vertices) {
        for (int k = 0; k < rot; ++k) v = {0.0 - v.y, v.x};  // 0.0 - y: no negative zero
        if (mirror) v.x = 0.0 - v.x;
    }
    for (const Ring& r : out.rings) {
        auto first = out.vertices.begin() + r.first, last = first + r.count;
        if (reverse) std::reverse(first, last);
        if (r.count > 0) std::rotate(first, first + long(shift % r.count), last);
    }
    // Vertex indices moved: find the T-junctions again.
    if (!out.splits.empty() && (reverse || shift != 0)) validate(out, "transform");
    return out;
}

}  // namespace flood
