// Exact box coverage of Bezier regions (bezier_coverage.h).
#include "methods/scan/reference/bezier_coverage.h"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include "methods/scan/reference/bezier_sweep.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

// Gauss-Legendre on 3 nodes over [0, 1]: exact for polynomials of degree <= 5, and the area
// integrand (x(t) - c) y'(t) has degree 2 n - 1 <= 5 for a segment of degree n <= 3.
constexpr double kNodes[3] = {0.1127016653792583, 0.5, 0.8872983346207417};
constexpr double kWeights[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};

// The integral of (x(t) - c) y'(t) dt from ta to tb (in either order).
double area_integral(const Segment& s, double ta, double tb, double c) {
    const double h = tb - ta;
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double t = ta + kNodes[k] * h;
        sum += kWeights[k] * (bezier_at(s, t).x - c) * bezier_derivative(s, t).y;
    }
    return sum * h;
}

// One row's cells: pixel i gets left + sum_{c < i} cover[c] + cover[i] - area[i].
struct RowCells {
    std::vector<double> cover, area;
    double left = 0.0;
    explicit RowCells(int width) : cover(static_cast<std::size_t>(width), 0.0), area(cover) {}
};

class Accumulator {
public:
    Accumulator(int width, int row_lo, int row_hi) : width_(width), row_lo_(row_lo) {
        rows_.reserve(static_cast<std::size_t>(row_hi - row_lo));
        for (int j = row_lo; j < row_hi; ++j) rows_.emplace_back(width);
    }

    // The piece from (t_top, y_top) to (t_bottom, y_bottom), y_top < y_bottom, within the rows.
    void add(const BezierPiece& p, double t_top, double t_bottom, double y_top, double y_bottom,
             double jump) {
        const Segment& s = *p.segment;
        for (int j = static_cast<int>(std::floor(y_top)); j < y_bottom; ++j) {
            const double ya = std::max<double>(y_top, j), yb = std::min<double>(y_bottom, j + 1.0);
            if (!(ya < yb)) continue;
            // The roots lie between the band's ends (the piece is monotone): a narrow bracket
            // is a good start for solve_monotone's Newton steps.
            const double lo = std::min(t_top, t_bottom), hi = std::max(t_top, t_bottom);
            const double ta = ya == y_top ? t_top : solve_monotone(s, 1, ya, lo, hi);
            const double tb = yb == y_bottom ? t_bottom : solve_monotone(s, 1, yb, lo, hi);
            add_in_row(rows_[static_cast<std::size_t>(j - row_lo_)], p, ta, tb, ya, yb, jump);
        }
    }

    // Pixel values of every row into `out` (a Coverage or an Image: rounded once to its type).
    template <class Raster>
    void write(double background, Raster& out) const {
        for (std::size_t r = 0; r < rows_.size(); ++r) {
            const RowCells& row = rows_[r];
            auto* dst = out.row(row_lo_ + static_cast<int>(r));
            double run = background + row.left;
            for (int i = 0; i < width_; ++i) {
                const std::size_t c = static_cast<std::size_t>(i);
                dst[i] = static_cast<std::remove_reference_t<decltype(dst[i])>>(run + row.cover[c] -
                                                                                row.area[c]);
                run += row.cover[c];
            }
        }
    }

private:
    // The piece inside one row, from (ta, ya) to (tb, yb), cut at every integer x in the window.
    void add_in_row(RowCells& row, const BezierPiece& p, double ta, double tb, double ya, double yb,
                    double jump) {
        const Segment& s = *p.segment;
        const double xa = bezier_at(s, ta).x, xb = bezier_at(s, tb).x;
        const double lo = std::min(xa, xb), hi = std::max(xa, xb);
        if (lo >= width_) return;  // right of every pixel: changes none
        if (hi <= 0.0) {
            row.left += jump * (yb - ya);
            return;
        }
        // Cut points: integers strictly inside (lo, hi), limited to [0, width].
        const double first = std::max(std::floor(lo) + 1.0, 0.0);
        const double last = std::min(std::ceil(hi) - 1.0, static_cast<double>(width_));
        double t0 = ta, y0 = ya, x0 = xa;
        const bool increasing = xb > xa;
        const long long count = last >= first ? static_cast<long long>(last - first) + 1 : 0;
        for (long long k = 0; k <= count; ++k) {
            double t1 = tb, y1 = yb, x1 = xb;
            if (k < count) {
                x1 = increasing ? first + static_cast<double>(k) : last - static_cast<double>(k);
                t1 = solve_monotone(s, 0, x1, std::min(t0, tb), std::max(t0, tb));
                y1 = std::clamp(bezier_at(s, t1).y, y0, yb);
            }
            const double cell = std::floor(0.5 * (x0 + x1));
            const double dy = y1 - y0;
            if (cell < 0.0) {
                row.left += jump * dy;
            } else if (cell < width_) {
                const std::size_t c = static_cast<std::size_t>(cell);
                row.cover[c] += jump * dy;
                row.area[c] += jump * area_integral(s, t0, t1, cell);
            }
            t0 = t1;
            y0 = y1;
            x0 = x1;
        }
    }

    int width_;
    int row_lo_;
    std::vector<RowCells> rows_;
};

void accumulate(const Scene& scene, int row_lo, int row_hi, Accumulator& acc) {
    const BezierPieces pieces = monotone_pieces(scene);
    sweep_bezier_bands(scene, pieces, row_lo, row_hi, [&](const BezierBand& band) {
        for (const BandPiece& b : band.pieces) {
            acc.add(*b.piece, b.t_top, b.t_bottom, band.y_top, band.y_bottom, b.jump);
        }
    });
}

}  // namespace

Coverage bezier_box_coverage(const Scene& scene) {
    require_window_frame(scene, "Bezier box coverage");
    Coverage out(scene.width, scene.height);
    Accumulator acc(scene.width, 0, scene.height);
    accumulate(scene, 0, scene.height, acc);
    acc.write(scene.background, out);
    return out;
}

void bezier_rows(const Scene& scene, Image& out, int row_lo, int row_hi) {
    require_window_frame(scene, "Bezier rows");
    Accumulator acc(scene.width, row_lo, row_hi);
    accumulate(scene, row_lo, row_hi, acc);
    acc.write(scene.background, out);
}

}  // namespace aabench
