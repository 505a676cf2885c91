// aa-circle — the fast antialiased circle of a Japanese web article: one octant, eight-way
// symmetry, and a table D[r][y] that gives both the pixels' alpha and the step of x.
//
// Computes (source: the web article "アンチエイリアスがかかった円を高速描画するアルゴリズム",
// author and year not given, docs/methods-circles.md; grid and shapes:
// methods/scan/circles/circle_raster.h). For a circle of integer radius r about a pixel
// centre, the octant from (r, 0) to 45 degrees: the pixel (r, 0) at full alpha, then for
// y = 1, 2, ... while y < x - 1, the two pixels whose centres straddle the arc at height y,
// x - 1 and x, share one unit of ink by the horizontal distance l = ceil(x_t) - x_t from the arc
// to the right one, x_t = sqrt(r^2 - y^2): d = ALPHA_MAX * l (truncated to an integer, as the
// source's int table does), the outer pixel x gets ALPHA_MAX - d and the inner x - 1 gets d.
// x steps left exactly when l shrinks (x_t falls by less than one per step in the octant, so
// ceil(x_t) keeps its value and l grows, or drops by one and l shrinks), and d is monotone in
// l, so the source decides the step by d < d_old from the same table: no square root and no
// multiplication in the loop. (Truncated d can tie where l shrank by less than 1 / ALPHA_MAX,
// and the source then keeps x; this method does what the source does.) The octant is copied
// eight ways; pixels on the axes and diagonals, written by two octants, keep one alpha
// (CirclePlotter). Radius 0 is a point (one pixel, full alpha), as the source suggests;
// radius 1 runs the algorithm as written, which draws the four axis pixels without
// antialiasing, as the source notes ("全部の点をsetPixelした方が早いかも": plot them directly).
//
// The table holds D[r][y] for 1 <= r <= radius_max, 1 <= y <= ceil(r / sqrt 2): about
// sqrt(2) radius_max^2 / 4 entries, the source's figure (one byte each at ALPHA_MAX = 255).
// Larger radii, and any y past a row's end, compute d in the loop (one sqrt per step), which
// the source names as the way past RADIUS_MAX.
//
// Parameters:
//   radius_max  1024  0..4096   the table's last radius (the source's RADIUS_MAX); 0 computes
//                               every d on the fly. 1024 is 371,602 entries (363 KiB at 8 bit).
//   alpha_max   255   0..65535  ALPHA_MAX: 255 is the source's 8-bit alpha; 65535 a 16-bit
//                               table; 0 keeps l as a float (no quantisation, exact steps).
#include "methods/aa_circle.h"

#include <cmath>
#include <cstdint>
#include <vector>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/circles/circle_raster.h"

namespace aabench {
namespace {

class AaCircleMethod : public Method {
public:
    AaCircleMethod(int radius_max, int alpha_max)
        : radius_max_(radius_max), alpha_max_(alpha_max), scale_(alpha_max == 0 ? 1.0 : alpha_max) {
        row_start_.assign(static_cast<std::size_t>(radius_max) + 2, 0);
        std::size_t entries = 0;
        for (int r = 1; r <= radius_max; ++r) {
            row_start_[r] = entries;
            entries += rows(r);
        }
        row_start_[radius_max + 1] = entries;
        if (alpha_max == 0) {
            fill(table_f_, entries);
        } else if (alpha_max <= 255) {
            fill(table8_, entries);
        } else {
            fill(table16_, entries);
        }
    }

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        render_grid_circles(
            scene, out, row_lo, row_hi,
            [this](int cx, int cy, int r, CirclePlotter& plotter) { draw(cx, cy, r, plotter); });
    }

public:
    std::string not_applicable(const Scene& scene) const override {
        return grid_circles(scene, nullptr);
    }

    // The source's octant loop (see the top of the file), eight ways.
    void draw(int cx, int cy, int r, CirclePlotter& plotter) const {
        if (r == 0) {
            plotter.plot(cx, cy, 1.0f);
            return;
        }
        int x = r, y = 0;
        double d = 0.0, d_old = 0.0;
        plotter.plot8(cx, cy, x, y, 1.0f);  // the pixel on the axis
        while (y < x - 1) {                 // the inner pixel against the 45-degree line
            ++y;
            d = level(r, y);
            if (d < d_old) --x;
            plotter.plot8(cx, cy, x, y, static_cast<float>((scale_ - d) / scale_));  // outer
            plotter.plot8(cx, cy, x - 1, y, static_cast<float>(d / scale_));         // inner
            d_old = d;
        }
    }

    std::size_t table_entries() const { return row_start_.back(); }

private:
    // ceil(r / sqrt 2): the rows of D[r] in the source's initialisation loop.
    static int rows(int r) { return static_cast<int>(std::ceil(r / std::sqrt(2.0))); }

    // d = ALPHA_MAX (ceil(x_t) - x_t), truncated as the source's int table; l itself at 0.
    double compute(int r, int y) const {
        const double xt = std::sqrt(static_cast<double>(static_cast<long long>(r) * r -
                                                        static_cast<long long>(y) * y));
        const double l = std::ceil(xt) - xt;
        return alpha_max_ == 0 ? l : std::trunc(alpha_max_ * l);
    }

    double level(int r, int y) const {
        if (r > radius_max_) return compute(r, y);  // on the fly
        const std::size_t k = row_start_[r] + (y - 1);
        // Past the row: reached where a missed step keeps x a column out and the loop runs past
        // ceil(r / sqrt 2) (r = 804, 988, 1012 up to 1024 at ALPHA_MAX = 255; the source reads
        // beyond its row there): computed as on the fly (tests/circle_methods_test.cpp).
        if (k >= row_start_[r + 1]) return compute(r, y);
        if (alpha_max_ == 0) return table_f_[k];
        return alpha_max_ <= 255 ? table8_[k] : table16_[k];
    }

    template <class T>
    void fill(std::vector<T>& table, std::size_t entries) const {
        table.resize(entries);
        for (int r = 1; r <= radius_max_; ++r) {
            for (int y = 1; y <= rows(r); ++y) table[row_start_[r] + (y - 1)] = static_cast<T>(compute(r, y));
        }
    }

    int radius_max_, alpha_max_;
    double scale_;
    std::vector<std::size_t> row_start_;  // D[r][1] is at row_start_[r]; the total at the end
    std::vector<std::uint8_t> table8_;
    std::vector<std::uint16_t> table16_;
    std::vector<double> table_f_;  // alpha_max = 0: l in double, as on the fly
};

}  // namespace

namespace {

// The table's bytes: ceil(r / sqrt 2) entries per radius (as AaCircleMethod counts them) of
// one byte at alpha_max <= 255, two up to 65535, a double at alpha_max = 0, and its row index
// (8 bytes per radius).
double aa_circle_table_bytes(int radius_max, int alpha_max) {
    double entries = 0.0;
    for (int r = 1; r <= radius_max; ++r) entries += std::ceil(r / std::sqrt(2.0));
    const double entry_bytes = alpha_max == 0 ? 8.0 : alpha_max <= 255 ? 1.0 : 2.0;
    return entry_bytes * entries + 8.0 * (radius_max + 2.0);
}

}  // namespace

// What the harness knows of `aa-circle` (methods/method_traits.h).
MethodTraits aa_circle_traits() {
    MethodTraits t;
    t.curves = "n/a: draws circles only";
    t.applies_to = Applicability::kGridCirclesOnly;
    t.working_bytes = [](const ParamValues& p, const SceneSize& s) {
        return memory_model::grid_circle_bytes(s) +
               aa_circle_table_bytes(p.get_int("radius_max"), p.get_int("alpha_max"));
    };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        return cost_model::grid_circle_ms(s.pixels(), s.edge_columns);
    };
    return t;
}

MethodInfo aa_circle_method() {
    return {"aa-circle",
            "the fast antialiased circle: octant, 8-way symmetry, D[r][y] table (rings only)",
            {{"radius_max", ParamKind::kInt, 1024, 0, 4096, {},
              "the table's last radius (RADIUS_MAX); larger radii compute d on the fly"},
             {"alpha_max", ParamKind::kInt, 255, 0, 65535, {},
              "ALPHA_MAX: 255 the source's 8-bit alpha, 65535 16-bit, 0 = float l"}},
            [](const ParamValues& p) {
                return std::make_unique<AaCircleMethod>(p.get_int("radius_max"),
                                                        p.get_int("alpha_max"));
            }};
}

// The table's size for a radius_max (entries), for the benchmark's memory column and tests.
std::size_t aa_circle_table_entries(int radius_max) {
    return AaCircleMethod(radius_max, 255).table_entries();
}

}  // namespace aabench
