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
// The bands. The row is cut into horizontal bands in which no two edges cross and no edge
// starts or ends (methods/scan/reference/visible_boundary.cpp says how, and why crossings closer
// than 1e-13 to a band edge may be left unsplit: the misassigned area is a sliver far below the
// 1e-12 bound). Each band arrives with its edges in left-to-right order and each edge's dv;
// this file only accumulates.
#include "methods/scan/reference/box_coverage.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "methods/scan/kernel/area_cover_row.h"
#include "methods/scan/kernel/edge_table.h"
#include "methods/scan/reference/visible_boundary.h"

namespace aabench {
namespace {

// weight * (area right of the segment (xa, .)-(xb, .) of the given height within each pixel
// of the row), for a segment inside the row's band, into cells of the kernel row
// (methods/scan/kernel/cells.h, area_cover_row.h). The split into pieces is this file's own,
// one column at a time, and not the exact engine's (which adds a run of whole cells as k/2, k,
// ..., k/2): the reference's sums are independent of the engine's shortcuts, only the cell and
// its piece are shared.
void add_box_segment(AreaCells& row, double xa, double xb, double height, double weight) {
    const AreaCells::Writer cells = row.writer();
    const int width = row.width();
    const double w = weight * height;
    const double xl = std::min(xa, xb), xr = std::max(xa, xb);
    if (xr <= 0.0) {  // wholly left of the image: every pixel lies right of it
        cells.add(0, w);
        return;
    }
    if (xl >= width) return;  // wholly right of the image: no pixel lies right of it
    const double span = xr - xl;
    if (std::floor(xl) == std::floor(xr)) {
        add_area_piece(cells, xl, xr, w, width);
        return;
    }
    // Pieces between integer x; each gets its share of the height by length.
    double left = xl;
    if (left < 0.0) {  // the part left of the image covers every pixel
        cells.add(0, w * (0.0 - xl) / span);
        left = 0.0;
    }
    const double right = std::min(xr, static_cast<double>(width));
    while (left < right) {
        const double next = std::min(std::floor(left) + 1.0, right);
        add_area_piece(cells, left, next, w * (next - left) / span, width);
        left = next;
    }
}

class BoxRasterizer {
public:
    explicit BoxRasterizer(const Scene& scene)
        : table_(scene), sweep_(table_, 0, table_.height()) {
        row_.reset(scene.width);
    }

    Coverage run() {
        Coverage out(table_.width(), table_.height());
        const BandCallback on_band = [this](const Band& band) { accumulate_band(band); };
        for (int j = 0; j < table_.height(); ++j) {
            sweep_.sweep_row(j, on_band);
            // In order, not rounded: the reference is double (the row is clear after it).
            row_.resolve_and_clear(table_.background(), out.row(j),
                                   [](std::size_t, double sum) { return sum; });
        }
        return out;
    }

private:
    // No crossings inside the band: each edge adds its dv times the area right of it.
    void accumulate_band(const Band& band) {
        for (const BandSegment& s : band.segments) {
            if (s.jump == 0.0) continue;
            for_each_piece(table_, band, s, [&](double xa, double ya, double xb, double yb) {
                add_box_segment(row_, xa, xb, yb - ya, s.jump);
            });
        }
    }

    EdgeTable table_;
    BandSweep sweep_;
    AreaCells row_;
};

}  // namespace

Coverage box_coverage(const Scene& scene) { return BoxRasterizer(scene).run(); }

}  // namespace aabench
