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

// Gauss-Legendre on 5 nodes over [0, 1]: exact for polynomials of degree <= 9; the affine
// integrand below has degree 3 n - 1 <= 8.
constexpr double kNodes5[5] = {0.0469100770306680, 0.2307653449471585, 0.5, 0.7692346550528415,
                               0.9530899229693320};
constexpr double kWeights5[5] = {0.1184634425280945, 0.2393143352496832, 0.2844444444444444,
                                 0.2393143352496832, 0.1184634425280945};

// A jump of the visible value: c + gx x + gy y (BandPiece).
struct Jump {
    double c, gx, gy;
    bool affine() const { return gx != 0.0 || gy != 0.0; }
};

// The integral over the part of the cell [cell, cell + 1] right of the piece, between its
// heights at ta and tb, of the jump: the integral of J(y) (cell + 1 - x) + gx (cell + 1 - x)
// (cell + 1 + x) / 2 over y, J(y) = c + gy y, by 5-point Gauss-Legendre in t (exact).
double affine_part(const Segment& s, double ta, double tb, double cell, const Jump& jump) {
    const double h = tb - ta, right = cell + 1.0;
    double sum = 0.0;
    for (int k = 0; k < 5; ++k) {
        const double t = ta + kNodes5[k] * h;
        const Point b = bezier_at(s, t);
        const double gap = right - b.x;
        sum += kWeights5[k] * gap * (jump.c + jump.gy * b.y + 0.5 * jump.gx * (right + b.x)) *
               bezier_derivative(s, t).y;
    }
    return sum * h;
}

// One row's cells: pixel i gets left + sum_{c < i} cover[c] + cover[i] - area[i]. Affine
// jumps add, where a scene has them, left0 + sum_{c < i} full0[c] + (left1 + sum_{c < i}
// full1[c]) (i + 1/2) + part[i]: a cell's full-pixel integral right of it is that of
// c + gy y over its height plus gx times the pixel's mean x, i + 1/2, times the height.
struct RowCells {
    std::vector<double> cover, area;
    double left = 0.0;
    std::vector<double> full0, full1, part;  // empty until an affine jump comes
    double left0 = 0.0, left1 = 0.0;
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
             const Jump& jump) {
        for (int j = static_cast<int>(std::floor(y_top)); j < y_bottom; ++j) {
            const double ya = std::max<double>(y_top, j), yb = std::min<double>(y_bottom, j + 1.0);
            if (!(ya < yb)) continue;
            // The roots lie between the band's ends (the piece is monotone): a narrow bracket
            // is a good start for solve_monotone's Newton steps.
            const double lo = std::min(t_top, t_bottom), hi = std::max(t_top, t_bottom);
            const double ta = ya == y_top ? t_top : piece_solve(p, 1, ya, lo, hi);
            const double tb = yb == y_bottom ? t_bottom : piece_solve(p, 1, yb, lo, hi);
            add_in_row(rows_[static_cast<std::size_t>(j - row_lo_)], p, ta, tb, ya, yb, jump);
        }
    }

    // Pixel values of every row into `out` (a Coverage or an Image: rounded once to its type).
    template <class Raster>
    void write(double background, Raster& out) const {
        for (std::size_t r = 0; r < rows_.size(); ++r) {
            const RowCells& row = rows_[r];
            auto* dst = out.row(row_lo_ + static_cast<int>(r));
            using T = std::remove_reference_t<decltype(dst[0])>;
            double run = background + row.left;
            if (row.part.empty()) {
                for (int i = 0; i < width_; ++i) {
                    const std::size_t c = static_cast<std::size_t>(i);
                    dst[i] = static_cast<T>(run + row.cover[c] - row.area[c]);
                    run += row.cover[c];
                }
                continue;
            }
            double run0 = row.left0, run1 = row.left1;
            for (int i = 0; i < width_; ++i) {
                const std::size_t c = static_cast<std::size_t>(i);
                dst[i] = static_cast<T>(run + row.cover[c] - row.area[c] + run0 +
                                        run1 * (i + 0.5) + row.part[c]);
                run += row.cover[c];
                run0 += row.full0[c];
                run1 += row.full1[c];
            }
        }
    }

private:
    void add_in_row(RowCells& row, const BezierPiece& p, double ta, double tb, double ya, double yb,
                    const Jump& jump) {
        if (!jump.affine()) {
            for_each_piece_cell(p, ta, tb, ya, yb, width_, [&](double cell, double t0, double t1, double y0,
                                                 double y1) {
                const double dy = y1 - y0;
                if (cell < 0.0) {
                    row.left += jump.c * dy;
                    return;
                }
                const std::size_t c = static_cast<std::size_t>(cell);
                row.cover[c] += jump.c * dy;
                row.area[c] += jump.c * piece_area_integral(p, t0, t1, cell);
            });
            return;
        }
        // An affine jump (on a segment's piece: monotone_pieces refuses planes beside circles).
        if (row.part.empty()) {
            row.full0.assign(row.cover.size(), 0.0);
            row.full1 = row.full0;
            row.part = row.full0;
        }
        for_each_piece_cell(p, ta, tb, ya, yb, width_, [&](double cell, double t0, double t1, double y0,
                                             double y1) {
            // The jump's full-pixel integral over heights y0 .. y1: (c + gy ymid) dy, and gx dy
            // times the pixel's mean x.
            const double full0 = (jump.c + jump.gy * 0.5 * (y0 + y1)) * (y1 - y0);
            const double full1 = jump.gx * (y1 - y0);
            if (cell < 0.0) {
                row.left0 += full0;
                row.left1 += full1;
                return;
            }
            const std::size_t c = static_cast<std::size_t>(cell);
            row.full0[c] += full0;
            row.full1[c] += full1;
            row.part[c] += affine_part(*p.segment, t0, t1, cell, jump);
        });
    }

    int width_;
    int row_lo_;
    std::vector<RowCells> rows_;
};

void accumulate(const Scene& scene, const BezierPieces& pieces, int row_lo, int row_hi,
                Accumulator& acc) {
    sweep_bezier_bands(scene, pieces, row_lo, row_hi, [&](const BezierBand& band) {
        for (const BandPiece& b : band.pieces) {
            acc.add(*b.piece, b.t_top, b.t_bottom, band.y_top, band.y_bottom,
                    Jump{b.jump, b.jump_gx, b.jump_gy});
        }
    });
}

void accumulate(const Scene& scene, int row_lo, int row_hi, Accumulator& acc) {
    accumulate(scene, monotone_pieces(scene), row_lo, row_hi, acc);
}

template <class Raster>
void rows_each(const Scene& scene, std::span<const int> rows, Raster& out) {
    const BezierPieces pieces = monotone_pieces(scene);
    for (const int j : rows) {
        if (j < 0 || j >= scene.height) continue;
        Accumulator acc(scene.width, j, j + 1);
        accumulate(scene, pieces, j, j + 1, acc);
        acc.write(scene.background, out);
    }
}

}  // namespace

void bezier_rows_each(const Scene& scene, std::span<const int> rows, Coverage& out) {
    rows_each(scene, rows, out);
}

void bezier_rows_each(const Scene& scene, std::span<const int> rows, Image& out) {
    rows_each(scene, rows, out);
}

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
