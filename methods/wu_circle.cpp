// wu-circle — Xiaolin Wu's antialiased circle (1991), the classic peer of aa-circle.
//
// Computes (source: X. Wu, "An efficient antialiasing technique", SIGGRAPH '91, Computer
// Graphics 25(4), the circle section; also "Fast anti-aliased circle generation", Graphics
// Gems II, 1991). Our reading of it: for a circle of integer radius r about a pixel centre
// (grid and shapes: methods/scan/circles/circle_raster.h), start at (r, 0) at full intensity; for
// j = 1, 2, ... while i > j, D(r, j) = ceil(sqrt(r^2 - j^2)) - sqrt(r^2 - j^2) quantised to
// 2^bits - 1 levels (rounded to the nearest level), i steps left when D falls below its
// previous value T, and the pixels (i, j) and (i - 1, j) get 1 - D and D; eight-way symmetry
// as in aa-circle. It is the same two-pixel rule as aa-circle's, with three differences that the
// comparison shows: D computed per step (Wu's paper gets it from an integer square-root
// recurrence; here double sqrt, the same value), rounded rather than truncated, and the loop
// runs to the diagonal (i > j) where aa-circle's source stops one pixel
// pair earlier (y < x - 1).
//
// Parameters:
//   bits  8  1..16  intensity levels 2^bits - 1: 8 as the 8-bit frame buffers Wu wrote for.
#include <cmath>
#include <vector>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/circles/circle_raster.h"

namespace aabench {
namespace {

class WuCircleMethod : public Method {
public:
    explicit WuCircleMethod(int bits) : levels_(static_cast<double>((1 << bits) - 1)) {}

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

private:
    void draw(int cx, int cy, int r, CirclePlotter& plotter) const {
        if (r == 0) {
            plotter.plot(cx, cy, 1.0f);
            return;
        }
        int i = r, j = 0;
        double t = 0.0;
        plotter.plot8(cx, cy, i, j, 1.0f);
        while (i > j) {
            ++j;
            const double xt = std::sqrt(static_cast<double>(static_cast<long long>(r) * r -
                                                            static_cast<long long>(j) * j));
            const double d = std::round(levels_ * (std::ceil(xt) - xt));
            if (d < t) --i;
            plotter.plot8(cx, cy, i, j, static_cast<float>((levels_ - d) / levels_));
            plotter.plot8(cx, cy, i - 1, j, static_cast<float>(d / levels_));
            t = d;
        }
    }

    double levels_;
};

}  // namespace

// What the harness knows of `wu-circle` (methods/method_traits.h).
MethodTraits wu_circle_traits() {
    MethodTraits t;
    t.curves = "n/a: draws circles only";
    t.applies_to = Applicability::kGridCirclesOnly;
    t.working_bytes = [](const ParamValues&, const SceneSize& s) {
        return memory_model::grid_circle_bytes(s);
    };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        return cost_model::grid_circle_ms(s.pixels(), s.edge_columns);
    };
    return t;
}

MethodInfo wu_circle_method() {
    return {"wu-circle", "Xiaolin Wu's antialiased circle (1991), D per step (rings only)",
            {{"bits", ParamKind::kInt, 8, 1, 16, {}, "intensity levels 2^bits - 1 (8-bit frame buffer)"}},
            [](const ParamValues& p) { return std::make_unique<WuCircleMethod>(p.get_int("bits")); }};
}

}  // namespace aabench
