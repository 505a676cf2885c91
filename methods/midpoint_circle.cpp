// midpoint-circle — the aliased midpoint (Bresenham) circle: the "none" of circles.
//
// Computes (source: J. Bresenham, "A linear algorithm for incremental digital display of
// circular arcs", CACM 20(2), 1977; the midpoint form as in Foley, van Dam et al., Computer
// Graphics, §3.3). For a circle of integer radius r about a pixel centre (grid and shapes:
// methods/scan/circles/circle_raster.h): from (r, 0), for y = 0, 1, ... while x >= y, light (x, y)
// and its seven mirror images at full value; the decision variable e = x^2 + y^2 - r^2 evaluated
// at the midpoint between the two candidates, kept in integers (e starts at 1 - r, the
// midpoint value rounded: it decides the same way since the true one differs by 1/4) says
// whether x steps left. One pixel per row in the octant, no antialiasing. Radius 0 is the
// centre pixel.
//
// Parameters: none.
#include <vector>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/circles/circle_raster.h"

namespace aabench {
namespace {

class MidpointCircleMethod : public Method {
protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        render_grid_circles(
            scene, out, row_lo, row_hi,
            [](int cx, int cy, int r, CirclePlotter& plotter) { draw(cx, cy, r, plotter); });
    }

public:
    std::string not_applicable(const Scene& scene) const override {
        return grid_circles(scene, nullptr);
    }

private:
    static void draw(int cx, int cy, int r, CirclePlotter& plotter) {
        if (r == 0) {
            plotter.plot(cx, cy, 1.0f);
            return;
        }
        int x = r, y = 0;
        long long e = 1 - static_cast<long long>(r);
        while (x >= y) {
            plotter.plot8(cx, cy, x, y, 1.0f);
            ++y;
            if (e < 0) {
                e += 2LL * y + 1;
            } else {
                --x;
                e += 2LL * (y - x) + 1;
            }
        }
    }
};

}  // namespace

// What the harness knows of `midpoint-circle` (methods/method_traits.h).
MethodTraits midpoint_circle_traits() {
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

MethodInfo midpoint_circle_method() {
    return {"midpoint-circle", "the aliased midpoint (Bresenham) circle (rings only)", {},
            [](const ParamValues&) { return std::make_unique<MidpointCircleMethod>(); }};
}

}  // namespace aabench
