// Exact box-filtered rendering by cell accumulation along edges.
//
// What it computes. For pixel (i, j), value = (1 / pixel area) * integral over the pixel of
// v(x, y), where v is the visible value: the value of the last shape whose nonzero winding
// number is nonzero at (x, y), else the background. Pixels have unit area.
//
// Why accumulation is exact. Take a horizontal band [ya, yb] in which no two edges cross and
// no edge starts or ends. Then every edge spans the whole band, the left-to-right order of the
// edges is the same at every height, and v is constant between two neighbouring edges. So
// v(x, y) = background + sum over edges e left of x of dv_e, where dv_e is the jump of v
// across e (value right of e minus value left of e). Integrating over the band and a pixel
// column [i, i+1]: each edge contributes dv_e times the area of the part of the column that
// lies right of it. Splitting an edge at integer x gives pieces of height h_p and mean x m_p
// inside one column c; the area right of such a piece inside column c is h_p * (c + 1 - m_p)
// (a trapezoid: the mean of a linear function is its midpoint value), and every column > c
// gets the full h_p. This is the "area and cover" accumulation of analytic rasterizers
// (FreeType's smooth rasterizer, font-rs, Blend2D): one diff array per row, acc[c] += the
// partial area, acc[c + 1] += the rest of the cover, and a prefix sum turns the diffs into
// pixel values. Work: O(pixels touched by each edge + row length).
//
// The bands. Row j is split at every edge endpoint strictly inside (j, j+1) and at every
// crossing of two edges inside it. Crossings are found exactly where they occur: edges are
// sorted by x at the band's top; an insertion sort by x at the band's bottom swaps exactly
// the pairs that cross inside the band (an inversion), and each swap gives one crossing
// height. Within the final band, the order at mid-height is the order everywhere, and a
// walk in that order (VisibilityWalker) gives each edge's dv.
//
// Floating point. Crossing heights closer than kMinBandHeight to a band edge are not split
// off: the region misassigned by treating such a band as crossing-free is a triangle of
// height < kMinBandHeight, whose area is far below the 1e-12 bound for edges of bounded
// slope. Coincident edges (two shapes sharing a border) need no split: the zero-width region
// between them contributes nothing, and their dvs add up to the true jump.
#include "harness/box_reference.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "methods/edge_table.h"

namespace aabench {
namespace {

constexpr double kMinBandHeight = 1e-13;

struct BandEdge {
    double x_top;
    double x_bottom;
    std::uint32_t index;
};

class RowAccumulator {
public:
    explicit RowAccumulator(int width) : width_(width), acc_(width + 2, 0.0) {}

    void clear() { std::fill(acc_.begin(), acc_.end(), 0.0); }

    // Adds weight * (area right of the segment (xa, ya)-(xb, yb) within each pixel of the row),
    // for a segment inside the row's band with yb > ya.
    void add_segment(double xa, double xb, double height, double weight) {
        const double w = weight * height;
        double xl = std::min(xa, xb), xr = std::max(xa, xb);
        if (xr <= 0.0) {  // wholly left of the image: every pixel lies right of it
            acc_[0] += w;
            return;
        }
        if (xl >= width_) return;  // wholly right of the image: no pixel lies right of it
        const double span = xr - xl;
        if (std::floor(xl) == std::floor(xr)) {
            add_piece(xl, xr, w);
            return;
        }
        // Pieces between integer x; each gets its share of the height by length.
        double left = xl;
        if (left < 0.0) {  // the part left of the image covers every pixel
            acc_[0] += w * (0.0 - xl) / span;
            left = 0.0;
        }
        const double right = std::min(xr, static_cast<double>(width_));
        while (left < right) {
            const double next = std::min(std::floor(left) + 1.0, right);
            add_piece(left, next, w * (next - left) / span);
            left = next;
        }
    }

    // Writes background + prefix sums into `out` (one image row).
    void resolve(double background, double* out) const {
        double sum = background;
        for (int i = 0; i < width_; ++i) {
            sum += acc_[i];
            out[i] = sum;
        }
    }

private:
    // A piece inside one column (or at its right border); w = weight * piece height.
    void add_piece(double xl, double xr, double w) {
        const double mid = 0.5 * (xl + xr);
        double c = std::floor(mid);
        if (c < 0.0) {
            acc_[0] += w;
            return;
        }
        if (c >= width_) return;
        const auto col = static_cast<std::size_t>(c);
        const double right_area = c + 1.0 - mid;  // in [0, 1]
        acc_[col] += w * right_area;
        acc_[col + 1] += w * (1.0 - right_area);
    }

    int width_;
    std::vector<double> acc_;
};

class BoxRasterizer {
public:
    explicit BoxRasterizer(const Scene& scene)
        : table_(scene), walker_(table_), row_(scene.width) {}

    Coverage run() {
        Coverage out(table_.width(), table_.height());
        for (int j = 0; j < table_.height(); ++j) {
            row_.clear();
            rasterize_row(j);
            row_.resolve(table_.background(), out.row(j));
        }
        return out;
    }

private:
    void rasterize_row(int j) {
        const auto ids = table_.row(j);
        if (ids.empty()) return;
        const double top = j, bottom = j + 1.0;
        breaks_.assign({top, bottom});
        for (const std::uint32_t idx : ids) {
            const Edge& e = table_.edges()[idx];
            if (e.y0 > top && e.y0 < bottom) breaks_.push_back(e.y0);
            if (e.y1 > top && e.y1 < bottom) breaks_.push_back(e.y1);
        }
        std::sort(breaks_.begin(), breaks_.end());
        breaks_.erase(std::unique(breaks_.begin(), breaks_.end()), breaks_.end());
        for (std::size_t k = 0; k + 1 < breaks_.size(); ++k) {
            const double ya = breaks_[k], yb = breaks_[k + 1];
            band_.clear();
            for (const std::uint32_t idx : ids) {
                const Edge& e = table_.edges()[idx];
                if (e.y0 <= ya && e.y1 >= yb) band_.push_back({e.x_at(ya), e.x_at(yb), idx});
            }
            if (!band_.empty()) rasterize_band(ya, yb);
        }
    }

    // All edges in band_ span [ya, yb]. Splits the band at crossings, then accumulates.
    void rasterize_band(double ya, double yb) {
        std::sort(band_.begin(), band_.end(), [](const BandEdge& a, const BandEdge& b) {
            return a.x_top < b.x_top || (a.x_top == b.x_top && a.x_bottom < b.x_bottom);
        });
        // Insertion sort by x at the bottom: each swap is a pair that crosses in the band.
        crossings_.clear();
        order_ = band_;
        for (std::size_t k = 1; k < order_.size(); ++k) {
            for (std::size_t m = k; m > 0 && order_[m - 1].x_bottom > order_[m].x_bottom; --m) {
                const BandEdge& a = order_[m - 1];
                const BandEdge& b = order_[m];
                // a is left of b at the top and right of it at the bottom.
                const double gap_top = b.x_top - a.x_top;                 // >= 0
                const double gap_bottom = a.x_bottom - b.x_bottom;        // > 0
                const double t = gap_top / (gap_top + gap_bottom);        // in [0, 1)
                const double yc = ya + t * (yb - ya);
                if (yc - ya > kMinBandHeight && yb - yc > kMinBandHeight) {
                    crossings_.push_back(yc);
                }
                std::swap(order_[m - 1], order_[m]);
            }
        }
        if (crossings_.empty()) {
            accumulate_band(ya, yb);
            return;
        }
        std::sort(crossings_.begin(), crossings_.end());
        crossings_.erase(std::unique(crossings_.begin(), crossings_.end()), crossings_.end());
        std::vector<double> cuts = std::move(crossings_);
        cuts.insert(cuts.begin(), ya);
        cuts.push_back(yb);
        const std::vector<BandEdge> all = band_;
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
            const double sa = cuts[k], sb = cuts[k + 1];
            if (!(sb - sa > 0.0)) continue;
            band_.clear();
            for (const BandEdge& be : all) {
                const Edge& e = table_.edges()[be.index];
                band_.push_back({e.x_at(sa), e.x_at(sb), be.index});
            }
            accumulate_band(sa, sb);
        }
    }

    // No crossings inside [ya, yb]: walk the edges in their order at mid-height.
    void accumulate_band(double ya, double yb) {
        const double ym = 0.5 * (ya + yb);
        for (BandEdge& be : band_) be.x_top = table_.edges()[be.index].x_at(ym);  // reuse slot
        std::sort(band_.begin(), band_.end(),
                  [](const BandEdge& a, const BandEdge& b) { return a.x_top < b.x_top; });
        walker_.reset();
        double before = table_.background();
        const double height = yb - ya;
        for (const BandEdge& be : band_) {
            const Edge& e = table_.edges()[be.index];
            const double after = walker_.cross(e.shape, e.winding);
            const double jump = after - before;
            before = after;
            if (jump != 0.0) row_.add_segment(e.x_at(ya), e.x_at(yb), height, jump);
        }
    }

    EdgeTable table_;
    VisibilityWalker walker_;
    RowAccumulator row_;
    std::vector<double> breaks_;
    std::vector<BandEdge> band_;
    std::vector<BandEdge> order_;
    std::vector<double> crossings_;
};

}  // namespace

Coverage box_reference(const Scene& scene) { return BoxRasterizer(scene).run(); }

}  // namespace aabench
