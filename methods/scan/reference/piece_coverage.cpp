// The exact box filter of disjoint pieces with affine values, by exact areas and first moments.
//
// Shared by the box reference (harness/reference/box_reference.h: box_reference_of_pieces) and
// by the `exact` method when it renders a depth image (values affine on each piece).
//
// What it computes. For pixel (i, j) with square S = [i, i+1] x [j, j+1] (unit area),
//     value(i, j) = sum over pieces P of integral over P ∩ S of v_P dA
//                   + background * (1 - sum over pieces of area(P ∩ S)),
// v_P(x, y) = c + gx x + gy y (value_plane) or the constant `value`. This is the box filter of
// the visible value because the pieces are disjoint (visibility.h) and cover the visible part
// of every shape; the rest of the pixel shows the background.
//
// Why it is exact. P ∩ S is found by cutting P along the lines y = j (rows), then each row
// strip along x = i (columns). A cut along an axis line is Sutherland-Hodgman against a
// half-plane, which keeps the winding number of every point on the kept side, so the cut
// pieces of a simple polygon (convex or not) are polygons whose signed integrals are those of
// P ∩ S (a non-convex P may leave zero-width doubled edges along the cut; they integrate to
// zero). For a polygon with vertices (u_k, w_k), in coordinates relative to the pixel corner
// (u = x - i, w = y - j), Green's theorem gives the closed forms
//     2 A  = sum cross_k,                  cross_k = u_k w_{k+1} - u_{k+1} w_k,
//     6 Mu = sum (u_k + u_{k+1}) cross_k,  6 Mw = sum (w_k + w_{k+1}) cross_k,
// with Mu = integral of u dA, Mw = integral of w dA; and since v is affine,
//     integral of v dA = v(i, j) A + gx Mu + gy Mw.
// These are identities, so the only errors are roundings.
//
// Precision. Taking coordinates relative to the pixel corner keeps every term of the sums
// O(1): the cross products do not cancel the way they would with raw coordinates (x ~ 1000).
// The new vertex on a cut is computed with the cut coordinate exactly i or j and the other by
// one interpolation from the edge's endpoints taken in a fixed order, so two pieces sharing
// an edge get the same cut vertex and tile the pixel without a gap. Each vertex carries the
// rounding of its coordinate, |error| <~ 2^-52 |x|, which moves area by at most that times
// the perimeter in the pixel (<= 4): 4.5e-13 for coordinates up to 1024 with values of order
// one, <= 1e-12 for ordinary scenes (the figure tests/visibility_test.cpp checks against an
// independent oracle; the visibility step has its own sliver budget, visibility.cpp).
// Large values (depth images: z_s ~ f d / z_v) scale the absolute error with them.
//
// Cost: O(vertices x rows + cells) per piece, one cut per row and per column it crosses.
#include "methods/scan/reference/piece_coverage.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace aabench {
namespace {

// The coordinate a cut is along (kX: a column line x = c; kY: a row line y = c).
enum class Axis { kX, kY };

double along(const Point& p, Axis axis) { return axis == Axis::kX ? p.x : p.y; }
double across(const Point& p, Axis axis) { return axis == Axis::kX ? p.y : p.x; }

// The point of segment ab on the line `axis` = c (a and b strictly on opposite sides). The
// endpoints are put in a fixed order first, so the same edge walked either way (by the two
// pieces it separates) gives the same point to the last bit.
Point crossing(Point a, Point b, Axis axis, double c) {
    if (along(a, axis) > along(b, axis)) std::swap(a, b);
    const double t = (c - along(a, axis)) / (along(b, axis) - along(a, axis));
    const double other = across(a, axis) + t * (across(b, axis) - across(a, axis));
    return axis == Axis::kX ? Point{c, other} : Point{other, c};
}

// Sutherland-Hodgman both ways at once: `low` gets the part with `axis` <= c, `high` the part
// with `axis` >= c. Vertices on the line go to both.
void split_at(const Contour& poly, Axis axis, double c, Contour* low, Contour* high) {
    low->clear();
    high->clear();
    const std::size_t n = poly.size();
    for (std::size_t k = 0; k < n; ++k) {
        const Point& a = poly[k];
        const Point& b = poly[(k + 1) % n];
        const double da = along(a, axis) - c, db = along(b, axis) - c;
        if (da <= 0.0) low->push_back(a);
        if (da >= 0.0) high->push_back(a);
        if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) {
            const Point cut = crossing(a, b, axis, c);
            low->push_back(cut);
            high->push_back(cut);
        }
    }
}

// The value of one piece: its plane, or its constant as a plane with no slope.
AffinePlane value_of(const Shape& shape) {
    return shape.value_plane ? *shape.value_plane : AffinePlane{shape.value, 0.0, 0.0};
}

// The range [lo, hi] of a piece's vertices along `axis`.
std::pair<double, double> extent(const Contour& poly, Axis axis) {
    const auto at = [axis](const Point& p) { return axis == Axis::kX ? p.x : p.y; };
    double lo = at(poly[0]), hi = lo;
    for (const Point& p : poly) {
        lo = std::min(lo, at(p));
        hi = std::max(hi, at(p));
    }
    return {lo, hi};
}

// Cuts `rest` into the unit slabs [k, k + 1) along `axis`, k = k0..k1 (k0 <= lo and hi <= k1 + 1
// for the piece's range [lo, hi] along the axis, clamped to the image), handing each to
// on_slab(k) in `slab`; what lies before k0 is dropped first, and `rest` ends empty. The rows
// and then each row's cells of a piece are cut by this one loop.
template <class OnSlab>
void cut_unit_slabs(Contour& rest, Axis axis, double lo, double hi, int k0, int k1, Contour& slab,
                    Contour& scratch, OnSlab on_slab) {
    if (lo < k0) {
        split_at(rest, axis, k0, &scratch, &slab);
        rest.swap(slab);
    }
    for (int k = k0; k <= k1; ++k) {
        if (k + 1 < hi) {
            split_at(rest, axis, k + 1.0, &slab, &scratch);
            rest.swap(scratch);
        } else {
            slab.swap(rest);
            rest.clear();
        }
        on_slab(k);
    }
}

class PieceIntegrator {
public:
    PieceIntegrator(int width, int height)
        : width_(width), height_(height), integral_(width, height), area_(width, height) {}

    void add(const Contour& poly, const AffinePlane& value) {
        if (poly.size() < 3) return;
        const auto [y0, y1] = extent(poly, Axis::kY);
        if (!(y1 > 0.0 && y0 < height_)) return;
        // Orientation of the whole piece: a cut keeps it, so every cell integral gets its sign.
        sign_ = twice_signed_area(poly) >= 0.0 ? 1.0 : -1.0;
        value_ = value;
        // Clamped in double before the conversion: a piece may reach far past the image (1e10
        // px and more), where converting first is undefined.
        const int j0 = static_cast<int>(std::max(0.0, std::floor(y0)));
        const int j1 = static_cast<int>(std::min(height_ - 1.0, std::ceil(y1) - 1.0));
        rest_ = poly;
        // What lies above the image (y < 0) is dropped first.
        cut_unit_slabs(rest_, Axis::kY, y0, y1, j0, j1, strip_, scratch_,
                       [&](int j) { add_strip(j); });
    }

    Coverage resolve(double background) const {
        Coverage out(width_, height_);
        for (std::size_t k = 0; k < out.data.size(); ++k) {
            out.data[k] = integral_.data[k] + background * (1.0 - area_.data[k]);
        }
        return out;
    }

private:
    // strip_ (the piece within row j) cut into cells.
    void add_strip(int j) {
        if (strip_.size() < 3) return;
        const auto [x0, x1] = extent(strip_, Axis::kX);
        if (!(x1 > 0.0 && x0 < width_)) return;
        // Clamped in double before the conversion, as the rows in add().
        const int i0 = static_cast<int>(std::max(0.0, std::floor(x0)));
        const int i1 = static_cast<int>(std::min(width_ - 1.0, std::ceil(x1) - 1.0));
        // What lies left of the image is dropped first.
        cut_unit_slabs(strip_, Axis::kX, x0, x1, i0, i1, cell_, scratch_,
                       [&](int i) { add_cell(i, j); });
    }

    // cell_ (the piece within pixel (i, j)): area and first moments about the pixel corner.
    void add_cell(int i, int j) {
        const std::size_t n = cell_.size();
        if (n < 3) return;
        double twice_area = 0.0, six_mu = 0.0, six_mw = 0.0;
        for (std::size_t k = 0; k < n; ++k) {
            const Point& a = cell_[k];
            const Point& b = cell_[(k + 1) % n];
            const double ua = a.x - i, wa = a.y - j, ub = b.x - i, wb = b.y - j;
            const double cross = ua * wb - ub * wa;
            twice_area += cross;
            six_mu += (ua + ub) * cross;
            six_mw += (wa + wb) * cross;
        }
        const double area = sign_ * 0.5 * twice_area;
        const double mu = sign_ * six_mu / 6.0, mw = sign_ * six_mw / 6.0;
        integral_.at(i, j) += value_.at(i, j) * area + value_.gx * mu + value_.gy * mw;
        area_.at(i, j) += area;
    }

    int width_, height_;
    Coverage integral_;  // sum of integral of v dA per pixel
    Coverage area_;      // covered area per pixel
    AffinePlane value_;
    double sign_ = 1.0;
    Contour rest_, strip_, cell_, scratch_;  // reused: one allocation per size, not per cut
};

}  // namespace

bool has_affine_values(const Scene& scene) {
    return std::any_of(scene.shapes.begin(), scene.shapes.end(),
                       [](const Shape& s) { return s.value_plane.has_value(); });
}

Coverage piece_box_coverage(const Scene& pieces) {
    PieceIntegrator integrator(pieces.width, pieces.height);
    for (std::size_t k = 0; k < pieces.shapes.size(); ++k) {
        const Shape& shape = pieces.shapes[k];
        if (shape.contours.size() > 1) {
            throw InputError(fmt::format(
                "box coverage of pieces: shape {} has {} contours; a piece is one contour", k,
                shape.contours.size()));
        }
        if (shape.contours.empty()) continue;
        integrator.add(shape.contours[0], value_of(shape));
    }
    return integrator.resolve(pieces.background);
}

}  // namespace aabench
