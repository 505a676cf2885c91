// The invariant checks of the hard-case suite (harness/measure/hardcases.h): check_finite,
// check_range, check_area, check_same; the scene transforms (perturbed, offset_with_window); and
// the edge geometry the documented bounds are measured with (edge_neighbourhood and friends).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include <fmt/format.h>

#include "harness/measure/hardcase_internal.h"
#include "harness/measure/hardcases.h"
#include "patterns/scene/curves.h"

namespace aabench {

// ---- Edge geometry of a window-frame scene (for the documented bounds) ----

namespace hardcase_detail {
namespace {

template <class Fn>
void for_each_edge(const Scene& scene, Fn&& fn) {
    for (const Shape& shape : scene.shapes) {
        for (const Contour& c : shape.contours) {
            for (std::size_t k = 0; k < c.size(); ++k) fn(c[k], c[(k + 1) % c.size()]);
        }
    }
}

// Liang-Barsky: clips a-b to [x0, x1] x [y0, y1]; false when nothing is left.
bool clip_segment(Point& a, Point& b, double x0, double y0, double x1, double y1) {
    double t0 = 0.0, t1 = 1.0;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x - x0, x1 - a.x, a.y - y0, y1 - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0) {
            t0 = std::max(t0, t);
        } else {
            t1 = std::min(t1, t);
        }
        if (t0 > t1) return false;
    }
    const Point a0 = a;
    a = {a0.x + t0 * dx, a0.y + t0 * dy};
    b = {a0.x + t1 * dx, a0.y + t1 * dy};
    return true;
}

}  // namespace

// Per pixel, the number of edges whose closed segment meets the pixel's closed square (capped
// at 255), over the window grown by `margin` pixels on each side.
Raster<std::uint8_t> edge_counts(const Scene& scene, int margin) {
    const int w = scene.width + 2 * margin, h = scene.height + 2 * margin;
    Raster<std::uint8_t> count(w, h, 0);
    std::vector<int> seen(static_cast<std::size_t>(w) * h, -1);  // last edge that counted
    int edge_index = 0;
    for_each_edge(scene, [&](Point a, Point b) {
        const int id = edge_index++;
        // Clip a little beyond the grown window, so the pixels on its rim are complete.
        if (!clip_segment(a, b, -margin - 1.0, -margin - 1.0, scene.width + margin + 1.0,
                          scene.height + margin + 1.0)) {
            return;
        }
        auto mark = [&](int i, int j) {
            i += margin, j += margin;
            if (i < 0 || j < 0 || i >= w || j >= h) return;
            const std::size_t p = static_cast<std::size_t>(j) * w + i;
            if (seen[p] == id) return;
            seen[p] = id;
            if (count.data[p] < 255) ++count.data[p];
        };
        const double ylo = std::min(a.y, b.y), yhi = std::max(a.y, b.y);
        // Rows whose closed band [r, r+1] meets [ylo, yhi]: an endpoint on a row border
        // touches both rows.
        const int r0 = static_cast<int>(std::ceil(ylo)) - 1, r1 = static_cast<int>(std::floor(yhi));
        for (int r = r0; r <= r1; ++r) {
            const double ya = std::max<double>(ylo, r), yb = std::min<double>(yhi, r + 1.0);
            if (ya > yb) continue;
            double xa, xb;
            if (a.y == b.y) {
                xa = a.x, xb = b.x;
            } else {
                xa = a.x + (b.x - a.x) * ((ya - a.y) / (b.y - a.y));
                xb = a.x + (b.x - a.x) * ((yb - a.y) / (b.y - a.y));
            }
            const double xlo = std::min(xa, xb), xhi = std::max(xa, xb);
            // Columns whose closed band meets [xlo, xhi], with one column of slack for the
            // rounding of the interpolation.
            const int c0 = static_cast<int>(std::ceil(xlo)) - 2,
                      c1 = static_cast<int>(std::floor(xhi)) + 1;
            for (int c = c0; c <= c1; ++c) mark(c, r);
        }
    });
    return count;
}

Raster<std::uint8_t> dilate_and_crop(const Raster<std::uint8_t>& grown, int margin, int reach,
                                     int width, int height) {
    Raster<std::uint8_t> across(grown.width, grown.height, 0);
    for (int j = 0; j < grown.height; ++j) {
        for (int i = 0; i < grown.width; ++i) {
            if (!grown.at(i, j)) continue;
            for (int d = std::max(0, i - reach); d <= std::min(grown.width - 1, i + reach); ++d) {
                across.at(d, j) = 1;
            }
        }
    }
    Raster<std::uint8_t> out(width, height, 0);
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            for (int d = -reach; d <= reach && !out.at(i, j); ++d) {
                const int gj = j + margin + d;
                if (gj >= 0 && gj < grown.height && across.at(i + margin, gj)) out.at(i, j) = 1;
            }
        }
    }
    return out;
}

double clipped_perimeter(const Scene& scene) {
    double length = 0.0;
    for_each_edge(scene, [&](Point a, Point b) {
        if (clip_segment(a, b, -1.0, -1.0, scene.width + 1.0, scene.height + 1.0)) {
            length += std::hypot(b.x - a.x, b.y - a.y);
        }
    });
    return length;
}

// The trapezoidal rule's error bound for box-multiscan with n sub-scanlines (docs/
// hardcases.md): L(y) = integral over [0, W] of (v - background) dx is linear in y between
// kinks (vertex heights, heights where two edges cross or an edge crosses x = 0 or x = W),
// and the rule is exact on every sub-band without one. On a sub-band with a kink both the
// integral and the rule's value lie in h [min L, max L], so the error there is at most
// h x osc(L), and osc(L) <= span x the x-extent (clipped to [0, W]) of the edges in the band.
double trapezoid_bound(const Scene& scene, int n, double span) {
    struct Seg {
        Point a, b;
    };
    std::vector<Seg> segs;
    std::vector<double> kinks;
    const double width = scene.width;
    for_each_edge(scene, [&](Point a, Point b) {
        if (!clip_segment(a, b, -1e300, -1.0, 1e300, scene.height + 1.0)) return;
        segs.push_back({a, b});
        kinks.push_back(a.y);
        kinks.push_back(b.y);
        for (const double side : {0.0, width}) {
            if ((a.x - side) * (b.x - side) < 0.0) {
                kinks.push_back(a.y + (b.y - a.y) * ((side - a.x) / (b.x - a.x)));
            }
        }
    });
    // Crossings of two edges: a sweep down the edges' y-ranges (sorted by top, the ones still
    // reaching the next top kept), boxes first. Every pair whose y-ranges overlap is tested,
    // as all pairs were; the sweep only skips those that cannot meet (all pairs took minutes
    // on the 10^5 cubics of bezier-1e5, whose flattening has 10^5 edges).
    std::vector<std::size_t> by_top(segs.size());
    for (std::size_t i = 0; i < segs.size(); ++i) by_top[i] = i;
    auto top = [&](const Seg& s) { return std::min(s.a.y, s.b.y); };
    auto bottom = [&](const Seg& s) { return std::max(s.a.y, s.b.y); };
    std::sort(by_top.begin(), by_top.end(),
              [&](std::size_t u, std::size_t v) { return top(segs[u]) < top(segs[v]); });
    std::vector<std::size_t> active;
    for (const std::size_t i : by_top) {
        const double sx0 = std::min(segs[i].a.x, segs[i].b.x);
        const double sx1 = std::max(segs[i].a.x, segs[i].b.x);
        const double sy0 = top(segs[i]);
        std::erase_if(active, [&](std::size_t k) { return bottom(segs[k]) < sy0; });
        for (const std::size_t k : active) {
            if (std::max(segs[k].a.x, segs[k].b.x) < sx0 || std::min(segs[k].a.x, segs[k].b.x) > sx1) {
                continue;
            }
            // As the pair (first, second) in edge order: the line parameter on the first.
            const Seg& s = segs[std::min(i, k)];
            const Seg& t = segs[std::max(i, k)];
            const double rx = s.b.x - s.a.x, ry = s.b.y - s.a.y;
            const double qx = t.b.x - t.a.x, qy = t.b.y - t.a.y;
            const double denom = rx * qy - ry * qx;
            if (denom == 0.0) continue;  // parallel: no kink between them
            const double u = ((t.a.x - s.a.x) * qy - (t.a.y - s.a.y) * qx) / denom;
            if (u >= 0.0 && u <= 1.0) kinks.push_back(s.a.y + u * ry);
        }
        active.push_back(i);
    }
    // Sub-bands g = j n + l ([j + l/n, j + (l+1)/n]) holding a kink, with a neighbour on each
    // side so that rounding of y n cannot miss the right one.
    const long long bands = static_cast<long long>(scene.height) * n;
    std::vector<long long> marked;
    for (const double y : kinks) {
        if (!(y >= -1.0 && y <= scene.height + 1.0)) continue;
        const long long g = static_cast<long long>(std::floor(y * n));
        for (long long d = g - 1; d <= g + 1; ++d) {
            if (d >= 0 && d < bands) marked.push_back(d);
        }
    }
    std::sort(marked.begin(), marked.end());
    marked.erase(std::unique(marked.begin(), marked.end()), marked.end());
    const double h = 1.0 / n;
    double bound = 0.0;
    for (const Seg& s : segs) {
        const double y0 = std::min(s.a.y, s.b.y), y1 = std::max(s.a.y, s.b.y);
        auto it = std::lower_bound(marked.begin(), marked.end(),
                                   static_cast<long long>(std::floor(y0 * n)) - 1);
        for (; it != marked.end() && static_cast<double>(*it) <= y1 * n + 1.0; ++it) {
            const double ya = std::max(y0, static_cast<double>(*it) * h);
            const double yb = std::min(y1, static_cast<double>(*it + 1) * h);
            if (ya > yb) continue;
            double xa, xb;
            if (s.a.y == s.b.y) {
                xa = s.a.x, xb = s.b.x;
            } else {
                xa = s.a.x + (s.b.x - s.a.x) * ((ya - s.a.y) / (s.b.y - s.a.y));
                xb = s.a.x + (s.b.x - s.a.x) * ((yb - s.a.y) / (s.b.y - s.a.y));
            }
            xa = std::clamp(xa, 0.0, width);
            xb = std::clamp(xb, 0.0, width);
            bound += h * span * std::abs(xb - xa);
        }
    }
    return bound;
}

}  // namespace hardcase_detail

using namespace hardcase_detail;

namespace {

std::uint64_t splitmix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

// A uniform double in [-1, 1] from a hash.
double unit(std::uint64_t h) { return static_cast<double>(h >> 11) * 0x1p-52 - 1.0; }

}  // namespace

// ---- Public: checks and scene transforms ----

InvariantResult check_finite(const Coverage& image) {
    InvariantResult r;
    r.bound = 0.0;
    long long bad = 0;
    for (int j = 0; j < image.height; ++j) {
        for (int i = 0; i < image.width; ++i) {
            if (std::isfinite(image.at(i, j))) continue;
            if (bad++ == 0) r.x = i, r.y = j;
        }
    }
    r.value = static_cast<double>(bad);
    r.outcome = bad == 0 ? Outcome::kPass : Outcome::kFail;
    if (bad) r.note = fmt::format("{} non-finite pixels", bad);
    return r;
}

InvariantResult check_range(const Coverage& image, double lo, double hi, double slack) {
    InvariantResult r;
    r.bound = slack;
    for (int j = 0; j < image.height; ++j) {
        for (int i = 0; i < image.width; ++i) {
            const double v = image.at(i, j);
            // A NaN is out of every range: its excursion is infinite.
            const double excursion = v >= lo && v <= hi ? 0.0
                                     : v < lo          ? lo - v
                                     : v > hi          ? v - hi
                                                       : HUGE_VAL;
            if (excursion > r.value) r.value = excursion, r.x = i, r.y = j;
        }
    }
    r.outcome = r.value <= slack ? Outcome::kPass : Outcome::kFail;
    if (r.outcome == Outcome::kFail) {
        r.note = fmt::format("value {} outside [{}, {}]", image.at(r.x, r.y), lo, hi);
    }
    return r;
}

InvariantResult check_area(double mass, double exact_mass, double bound) {
    InvariantResult r;
    r.bound = bound;
    r.value = std::abs(mass - exact_mass);
    // Written so that a NaN mass fails.
    r.outcome = r.value <= bound ? Outcome::kPass : Outcome::kFail;
    if (r.outcome == Outcome::kFail) {
        r.note = fmt::format("mass {} against exact {}", mass, exact_mass);
    }
    return r;
}

InvariantResult check_same(const Coverage& a, const Coverage& b, double tolerance) {
    InvariantResult r;
    r.bound = tolerance;
    long long changed = 0;
    for (int j = 0; j < a.height; ++j) {
        for (int i = 0; i < a.width; ++i) {
            double d = std::abs(a.at(i, j) - b.at(i, j));
            if (std::isnan(d)) d = HUGE_VAL;  // a NaN in either is the worst difference
            if (d > tolerance) ++changed;
            if (d > r.value) r.value = d, r.x = i, r.y = j;
        }
    }
    r.changed_fraction = a.data.empty() ? 0.0 : static_cast<double>(changed) / a.data.size();
    r.outcome = changed == 0 ? Outcome::kPass : Outcome::kFail;
    if (changed) {
        r.note = fmt::format("{} pixels differ by more than {}", changed, short_number(tolerance));
    }
    return r;
}

Scene perturbed(const Scene& scene, double move_px) {
    Scene out = scene;
    // A point's move depends on the point alone, so a point shared by two segments (or
    // repeated) moves once and every contour stays closed.
    auto move = [move_px](Point& p) {
        const std::uint64_t h = splitmix(std::bit_cast<std::uint64_t>(p.x) ^
                                         splitmix(std::bit_cast<std::uint64_t>(p.y)));
        p.x += move_px * unit(h);
        p.y += move_px * unit(splitmix(h));
    };
    for (Shape& shape : out.shapes) {
        for (Contour& contour : shape.contours) {
            for (Point& p : contour) move(p);
        }
        for (SegmentContour& contour : shape.outline) {  // Bezier control points too
            for (Segment& s : contour) {
                for (int k = 0; k <= s.degree; ++k) move(s.p[static_cast<std::size_t>(k)]);
            }
        }
    }
    return out;
}

Scene offset_with_window(const Scene& scene, double offset_px) {
    Scene out = scene;
    out.origin_x += offset_px;
    out.origin_y += offset_px;
    // Contours, Bezier outlines and circles' centres alike (curves.h).
    auto shift = [offset_px](Shape& shape) { translate_shape(shape, offset_px, offset_px); };
    for (Shape& shape : out.shapes) shift(shape);
    for (ThinObject& object : out.thin_objects) shift(object.shape);
    return out;
}

Raster<std::uint8_t> edge_neighbourhood(const Scene& scene, int reach) {
    require_window_frame(scene, "edge_neighbourhood");
    const int margin = reach + 1;
    return dilate_and_crop(edge_counts(scene, margin), margin, reach, scene.width, scene.height);
}

}  // namespace aabench
