// Exact box coverage of discs and rings (curve_coverage.h).
//
// disc ∩ square. Walk the square's boundary counter-clockwise (in the (u, v) frame, where the
// shoelace sum of (0,0), (1,0), (1,1), (0,1) is +2). On each side the part inside the disc is
// one interval (a line meets a disc in one interval), found in closed form: on the side
// v = b the disc spans |u| <= sqrt((r - b)(r + b)) (the factored form keeps the difference of
// squares exact near tangency). The intersection's boundary is these intervals, in order,
// joined by arcs of the circle wherever one interval's end is not the next one's start. Its
// area (Green's theorem) is the shoelace area of the polygon through the intervals' end
// points plus, for each arc, the circular segment between the arc and its chord:
//     segment(theta) = r^2 / 2 (theta - sin theta),   theta the arc's angle (0, 2 pi).
// No interval at all: the square is wholly inside (area 1, caught first), or the disc lies in
// the square (pi r^2) or apart from it (0).
//
// Precision. The shoelace sum is taken relative to the square's corner, so its terms are O(1)
// and the only error is the rounding of the crossing points (~ulp(r)). For an arc shorter than
// half the circle theta = 2 asin(chord / 2r), with the chord measured between two O(1)-apart
// points (no cancellation), and theta - sin theta by its Taylor series below 0.1 (the
// subtraction would lose (6 / theta^2) ulps); longer arcs (a disc smaller than the square) use
// atan2 of the end points, where nothing cancels.
#include "methods/scan/reference/curve_coverage.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "methods/scan/reference/bezier_coverage.h"
#include "methods/scan/reference/box_coverage.h"
#include "patterns/scene/bezier.h"
#include "patterns/scene/curves.h"

namespace aabench {
namespace {

// theta - sin(theta), accurate to a few ulps for all theta in [0, 2 pi].
double theta_minus_sin(double t) {
    if (t >= 0.1) return t - std::sin(t);
    // t^3/3! - t^5/5! + t^7/7! - t^9/9! + t^11/11!; the next term is < 1e-19 relative.
    const double t2 = t * t;
    return t * t2 *
           (1.0 / 6.0 -
            t2 * (1.0 / 120.0 -
                  t2 * (1.0 / 5040.0 - t2 * (1.0 / 362880.0 - t2 * (1.0 / 39916800.0)))));
}

struct Vertex {
    double u, v;  // relative to the disc's centre
};

}  // namespace

double disc_square_area(double u0, double v0, double r) {
    const double u1 = u0 + 1.0, v1 = v0 + 1.0;
    // Nearest and farthest point of the square from the centre: the quick answers.
    const double nu = std::max({u0, 0.0, -u1}), nv = std::max({v0, 0.0, -v1});
    if (nu * nu + nv * nv >= r * r) return 0.0;
    const double fu = std::max(std::abs(u0), std::abs(u1)), fv = std::max(std::abs(v0), std::abs(v1));
    if (fu * fu + fv * fv <= r * r) return 1.0;

    // Sides counter-clockwise: (u0,v0)->(u1,v0)->(u1,v1)->(u0,v1)->(u0,v0). Each side is
    // "fixed" coordinate c, the other running from a to b.
    std::array<Vertex, 8> pts;  // interval ends: start, end per side
    std::array<bool, 4> has{};
    int count = 0;
    auto half_width = [r](double c) {
        return std::abs(c) < r ? std::sqrt((r - c) * (r + c)) : -1.0;  // -1: side misses
    };
    const double sides[4][3] = {{v0, u0, u1}, {u1, v0, v1}, {v1, u1, u0}, {u0, v1, v0}};
    for (int s = 0; s < 4; ++s) {
        const double c = sides[s][0], a = sides[s][1], b = sides[s][2];
        const double w = half_width(c);
        if (w < 0.0) continue;
        // Interval of the running coordinate inside the disc, clamped to the side, in the
        // side's direction (a to b). A clamped end is the corner itself, exactly.
        double lo, hi;
        if (a < b) {
            lo = std::max(a, -w);
            hi = std::min(b, w);
            if (!(lo < hi)) continue;
        } else {
            lo = std::min(a, w);
            hi = std::max(b, -w);
            if (!(lo > hi)) continue;
        }
        const bool horizontal = (s % 2 == 0);
        pts[2 * s] = horizontal ? Vertex{lo, c} : Vertex{c, lo};
        pts[2 * s + 1] = horizontal ? Vertex{hi, c} : Vertex{c, hi};
        has[s] = true;
        ++count;
    }
    if (count == 0) {
        // The square's boundary misses the disc: the disc lies inside the square or apart.
        const bool centre_inside = u0 <= 0.0 && 0.0 <= u1 && v0 <= 0.0 && 0.0 <= v1;
        return centre_inside ? std::numbers::pi * r * r : 0.0;
    }
    std::vector<Vertex> ring;
    ring.reserve(8);
    for (int s = 0; s < 4; ++s) {
        if (!has[s]) continue;
        ring.push_back(pts[2 * s]);
        ring.push_back(pts[2 * s + 1]);
    }
    double twice_area = 0.0, segments = 0.0;
    const std::size_t n = ring.size();
    for (std::size_t k = 0; k < n; ++k) {
        const Vertex& a = ring[k];
        const Vertex& b = ring[(k + 1) % n];
        const double au = a.u - u0, av = a.v - v0, bu = b.u - u0, bv = b.v - v0;
        twice_area += au * bv - bu * av;
        // An arc joins an interval's end (odd k) to the next interval's start, unless they
        // are the same corner.
        if (k % 2 == 1 && !(a.u == b.u && a.v == b.v)) {
            double theta = std::atan2(a.u * b.v - a.v * b.u, a.u * b.u + a.v * b.v);
            if (theta <= 0.0) theta += 2.0 * std::numbers::pi;
            if (theta < 0.5 * std::numbers::pi) {
                const double chord = std::hypot(bu - au, bv - av);
                theta = 2.0 * std::asin(std::min(1.0, chord / (2.0 * r)));
            }
            segments += 0.5 * r * r * theta_minus_sin(theta);
        }
    }
    return 0.5 * twice_area + segments;
}

namespace {

// Negligible area (see curve_box_coverage in the header): below the areas' own rounding.
constexpr double kNegligibleArea = 1e-13;

struct Layer {
    std::size_t first_shape = 0;  // the shape (curve) or the first of the run (polygons)
    std::size_t last_shape = 0;
    const Circle* circle = nullptr;  // null: a run of polygon shapes
    double value = 0.0;              // a curve's value
    bool uniform = true;             // a polygon run of one value (a full cover is uniform)
    Coverage integral;               // polygon runs: integral of the value over the pixel
    Coverage area;                   // polygon runs: covered area
};

double curve_area(const Circle& c, int i, int j) {
    const double u0 = i - c.center.x, v0 = j - c.center.y;
    const double outer = disc_square_area(u0, v0, c.outer);
    return c.is_disc() || outer == 0.0 ? outer : outer - disc_square_area(u0, v0, c.inner);
}

std::vector<Layer> make_layers(const Scene& scene) {
    std::vector<Layer> layers;
    std::size_t k = 0;
    while (k < scene.shapes.size()) {
        Layer layer;
        layer.first_shape = k;
        if (scene.shapes[k].circle) {
            layer.circle = &*scene.shapes[k].circle;
            layer.value = scene.shapes[k].value;
            layer.last_shape = k++;
            layers.push_back(std::move(layer));
            continue;
        }
        Scene run;
        run.width = scene.width;
        run.height = scene.height;
        while (k < scene.shapes.size() && !scene.shapes[k].circle) run.shapes.push_back(scene.shapes[k++]);
        layer.last_shape = k - 1;
        for (const Shape& s : run.shapes) layer.uniform = layer.uniform && s.value == run.shapes[0].value;
        layer.value = run.shapes[0].value;
        // A run with Bezier segments goes to the Bezier engine (exact, no flattening), a run of
        // polygons to the polygon engine.
        const bool bezier = has_bezier(run);
        layer.integral = bezier ? bezier_box_coverage(run) : box_coverage(run);
        for (Shape& s : run.shapes) s.value = 1.0;
        layer.area = bezier ? bezier_box_coverage(run) : box_coverage(run);
        layers.push_back(std::move(layer));
    }
    return layers;
}

}  // namespace

namespace {
// A pixel index from a floored coordinate, clamped to [0, n - 1] in double first.
int clamped_index(double v, int n) { return static_cast<int>(std::clamp(v, 0.0, n - 1.0)); }

// A rectangle of pixels, inclusive; empty when i1 < i0 or j1 < j0.
struct Region {
    int i0 = 0, i1 = -1, j0 = 0, j1 = -1;
    bool empty() const { return i1 < i0 || j1 < j0; }
    int width() const { return i1 - i0 + 1; }
};

// The pixels of the image a layer can touch: a curve's bounding box (empty when the curve
// lies wholly outside), or the whole image for a polygon run.
Region layer_box(const Layer& layer, int w, int h) {
    if (!layer.circle) return {0, w - 1, 0, h - 1};
    const Circle& c = *layer.circle;
    if (std::floor(c.center.x + c.outer) < 0 || std::floor(c.center.x - c.outer) > w - 1 ||
        std::floor(c.center.y + c.outer) < 0 || std::floor(c.center.y - c.outer) > h - 1) {
        return {};  // wholly outside the image
    }
    // Clamped in double before the cast: a centre moved by a far window origin may lie beyond
    // int range (the cast would be undefined).
    return {clamped_index(std::floor(c.center.x - c.outer), w),
            clamped_index(std::floor(c.center.x + c.outer), w),
            clamped_index(std::floor(c.center.y - c.outer), h),
            clamped_index(std::floor(c.center.y + c.outer), h)};
}

// Per-pixel state of the compositing, over a region only (kept per thread: a warm render of
// curves alone allocates nothing here).
struct Composite {
    Region region;
    std::vector<double> value, base;
    std::vector<char> uniform;
    std::vector<int> last;  // per pixel, the newest of its partial layers in `nodes`, -1: none
    struct Node {
        int layer, previous;
    };
    std::vector<Node> nodes;
    std::vector<char> conflict;  // per row of the region: a pixel whose partial layers may meet
    std::vector<int> conflict_rows;

    // The rows of the image with such a pixel, ascending.
    const std::vector<int>& rows_to_sweep() {
        conflict_rows.clear();
        for (std::size_t k = 0; k < conflict.size(); ++k) {
            if (conflict[k]) conflict_rows.push_back(region.j0 + static_cast<int>(k));
        }
        return conflict_rows;
    }
};

// Composites `layers` over the pixels of rows [row_lo, row_hi) they can touch (the union of
// their boxes): each pixel's value depends only on the layers covering it, so any set of rows
// gives what the whole image gives there. Pixels outside c.region are the background.
void composite(const std::vector<Layer>& layers, double background, int w, int h, int row_lo,
               int row_hi, Composite& c) {
    Region& r = c.region;
    r = Region{w, -1, h, -1};
    for (const Layer& layer : layers) {
        const Region box = layer_box(layer, w, h);
        if (box.empty()) continue;
        r.i0 = std::min(r.i0, box.i0);
        r.i1 = std::max(r.i1, box.i1);
        r.j0 = std::min(r.j0, box.j0);
        r.j1 = std::max(r.j1, box.j1);
    }
    r.j0 = std::max(r.j0, row_lo);
    r.j1 = std::min(r.j1, row_hi - 1);
    c.conflict.clear();
    if (r.empty()) return;
    c.conflict.assign(static_cast<std::size_t>(r.j1 - r.j0 + 1), 0);
    const std::size_t size = static_cast<std::size_t>(r.width()) * (r.j1 - r.j0 + 1);
    c.value.assign(size, background);
    c.base.assign(size, background);
    c.uniform.assign(size, 1);
    c.last.assign(size, -1);
    c.nodes.clear();
    for (std::size_t l = 0; l < layers.size(); ++l) {
        const Layer& layer = layers[l];
        const Region box = layer_box(layer, w, h);
        const int j0 = std::max(box.j0, r.j0), j1 = std::min(box.j1, r.j1);
        for (int j = j0; j <= j1; ++j) {
            for (int i = box.i0; i <= box.i1; ++i) {
                const std::size_t p = static_cast<std::size_t>(j - r.j0) * r.width() + (i - r.i0);
                const double a = layer.circle ? curve_area(*layer.circle, i, j) : layer.area.at(i, j);
                if (a <= kNegligibleArea) continue;
                const double integral = layer.circle ? layer.value * a : layer.integral.at(i, j);
                if (a >= 1.0 - kNegligibleArea) {  // covers the pixel: what was under is gone
                    c.value[p] = layer.circle ? layer.value : integral;
                    c.base[p] = layer.value;
                    c.uniform[p] = layer.uniform;
                    c.last[p] = -1;
                    continue;
                }
                bool exact = c.uniform[p] != 0;
                for (int q = c.last[p]; q >= 0; q = c.nodes[q].previous) {
                    const Layer& under = layers[c.nodes[q].layer];
                    exact = exact && layer.circle && under.circle &&
                            circles_disjoint(*layer.circle, *under.circle);
                }
                if (!exact) {  // the row goes to the sweep (below); this pixel stops here
                    c.conflict[static_cast<std::size_t>(j - r.j0)] = 1;
                    continue;
                }
                // The layer lies on the uniform base, apart from the other partial layers.
                c.value[p] += integral - c.base[p] * a;
                c.nodes.push_back({static_cast<int>(l), c.last[p]});
                c.last[p] = static_cast<int>(c.nodes.size() - 1);
            }
        }
    }
}

thread_local Composite t_composite;

}  // namespace

Coverage curve_box_coverage(const Scene& scene) {
    const std::vector<Layer> layers = make_layers(scene);
    const int w = scene.width, h = scene.height;
    Coverage value(w, h, scene.background);
    Composite c;
    composite(layers, scene.background, w, h, 0, h, c);
    for (int j = c.region.j0; j <= c.region.j1; ++j) {
        for (int i = c.region.i0; i <= c.region.i1; ++i) {
            value.at(i, j) = c.value[static_cast<std::size_t>(j - c.region.j0) * c.region.width() +
                                     (i - c.region.i0)];
        }
    }
    bezier_rows_each(scene, c.rows_to_sweep(), value);
    return value;
}

void curve_rows(const Scene& scene, Image& out, int row_lo, int row_hi) {
    row_lo = std::max(row_lo, 0);
    row_hi = std::min(row_hi, scene.height);
    if (row_lo >= row_hi) return;
    const std::vector<Layer> layers = make_layers(scene);
    Composite& c = t_composite;
    composite(layers, scene.background, scene.width, scene.height, row_lo, row_hi, c);
    const float background = static_cast<float>(scene.background);
    for (int j = row_lo; j < row_hi; ++j) {
        float* row = out.row(j);
        std::fill(row, row + scene.width, background);
        if (j < c.region.j0 || j > c.region.j1) continue;
        const double* values =
            c.value.data() + static_cast<std::size_t>(j - c.region.j0) * c.region.width();
        for (int i = c.region.i0; i <= c.region.i1; ++i) {
            row[i] = static_cast<float>(values[i - c.region.i0]);
        }
    }
    bezier_rows_each(scene, c.rows_to_sweep(), out);
}

}  // namespace aabench
