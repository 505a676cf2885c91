// nishita-d — Nishita & Nakamae's method D: 3 x 3 point samples per pixel on a half-pixel
// lattice, filtered by a radius-1 Gaussian over the 5 x 5 lattice points around each pixel.
//
// Computes: the scene's visible value (methods/scan/point_sampling.h, the tie rule of `none`) at
// the lattice points (m/2, n/2) for all integers m, n — a lattice of spacing 1/2 px through the
// pixel centres (i + 1/2, j + 1/2), so it also passes through the pixel corners and edge
// midpoints. A pixel's footprint [i, i+1] x [j, j+1] holds 3 x 3 of them; the points on its
// border are shared with the neighbouring pixels and count, with their own weights, for each
// pixel whose window holds them (they are sampled once). Then
//   out(i, j) = sum w(dx, dy) v(i + 1/2 + dx/2, j + 1/2 + dy/2),  dx, dy in -2..2,
//   w(dx, dy) = exp(-r^2 / (2 sigma^2)) / W  with r = sqrt(dx^2 + dy^2)/2 px when r <= 1, else 0,
// W the sum of the unnormalised weights over the 5 x 5 window (13 points have r <= 1: the
// centre, four at r = 1/2, four diagonal at r = sqrt(2)/2, and the four neighbour centres at
// r = 1 exactly; the window's other 12 points lie beyond the radius). The weights sum to 1, so
// a constant scene gives its value.
// Source: Nishita & Nakamae 1984, §4 and Fig. 5(d): "(d) is filtering by the usual method of
// increasing the sample points (a Gaussian filter, 3 x 3 sample points in a pixel, the colour
// of one pixel decided from 5 x 5 points including the neighbouring pixels)". The paper's
// filters have a radius of one pixel width and unit volume (§2.2.2), which fixes radius 1 and
// the normalisation; r <= 1 is inclusive so that the window does reach the neighbouring pixels
// as the paper says (with r < 1 only the pixel's own 3 x 3 points would count). The paper
// gives no sigma for its Gaussian: sigma is a parameter whose default, 0.5 px, is the suite's
// default Gaussian. Exact reference: "gaussian:sigma=S,radius=1".
//
// 3-D scenes (a ScreenScene with depth planes; Method::own_visibility()): each lattice point is
// the shape nearest at it by its depth plane (a depth per sample: a z-buffer on the lattice,
// methods/scan/point_sampling.h); affine values are taken at the point.
//
// Parameters:
//   sigma  real, default 0.5, range 0.05..10 px. The Gaussian's sigma (the paper gives none;
//          0.5 is the suite's default). Below 0.05 the ring r = 1/2 weighs nothing next to the
//          centre (the method degenerates to `none`); above 10 the 13 weights are equal.
//
// Cost: (2w + 3)(2h + 3) samples (about 4 per pixel) and 25 multiply-adds per pixel (the whole
// 5 x 5 window, 12 of the weights zero: a fixed-size loop is cheaper than skipping them), plus
// the edge crossings of each lattice row, found once per row.
#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/point_sampling.h"

namespace aabench {
namespace {

constexpr int kWindow = 5;    // lattice points per side of a pixel's window
constexpr int kRingRows = 5;  // lattice rows held at once: one pixel row's window

class NishitaDMethod : public Method {
public:
    explicit NishitaDMethod(double sigma) : sigma_(sigma) {
        double total = 0.0;
        for (int dy = -2; dy <= 2; ++dy) {
            for (int dx = -2; dx <= 2; ++dx) {
                const int d2 = dx * dx + dy * dy;  // (2 r)^2, exact
                const double w = d2 <= 4 ? std::exp(-(d2 / 4.0) / (2.0 * sigma_ * sigma_)) : 0.0;
                weights_[dy + 2][dx + 2] = w;
                total += w;
            }
        }
        for (auto& row : weights_) {
            for (double& w : row) w /= total;
        }
    }

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        const int width = scene.width, height = scene.height;
        // Lattice index m <-> x = (m - 1)/2, m in [0, 2w + 2]: the lattice runs from half a
        // pixel left of the image to half a pixel right of it. Pixel i's centre is m = 2i + 2,
        // its window m in [2i, 2i + 4]. Rows likewise.
        const int lattice_w = 2 * width + 3, lattice_h = 2 * height + 3;
        // Per-thread scratch (one Method may render from several threads at once), kept between
        // renders: a warm render allocates nothing.
        thread_local std::vector<double> xs, ring;
        thread_local PointSampler sampler;
        xs.resize(lattice_w);
        for (int m = 0; m < lattice_w; ++m) xs[m] = 0.5 * m - 0.5;  // exact in double
        // Ring of the last kRingRows lattice rows: row n lives in slot n % kRingRows, and a
        // pixel row's window is 5 consecutive rows, so they never collide.
        ring.resize(static_cast<std::size_t>(kRingRows) * lattice_w);
        auto ring_row = [&](int n) { return ring.data() + (n % kRingRows) * lattice_w; };
        sampler.reset(scene, 1.0);  // lattice rows reach y = -1/2 and y = h + 1/2
        // Lattice rows [2 row_lo, sampled) have been sampled: pixel row j's window starts at
        // lattice row 2j.
        int sampled = 2 * row_lo;
        for (int j = row_lo; j < row_hi; ++j) {
            for (; sampled <= 2 * j + 4 && sampled < lattice_h; ++sampled) {
                sampler.sample_values(0.5 * sampled - 0.5, xs,
                                      {ring_row(sampled), static_cast<std::size_t>(lattice_w)});
            }
            float* row = out.row(j);
            for (int i = 0; i < width; ++i) {
                double sum = 0.0;
                for (int dy = 0; dy < kWindow; ++dy) {
                    const double* lattice = ring_row(2 * j + dy) + 2 * i;
                    for (int dx = 0; dx < kWindow; ++dx) sum += weights_[dy][dx] * lattice[dx];
                }
                row[i] = static_cast<float>(sum);
            }
        }
    }

private:
    double sigma_;
    double weights_[kWindow][kWindow];  // [dy + 2][dx + 2], zero beyond r = 1, sum 1
};

}  // namespace

// What the harness knows of `nishita-d` (methods/method_traits.h).
MethodTraits nishita_d_traits() {
    MethodTraits t;
    t.own_visibility = true;
    t.affine_values = true;  // z-buffer per sample in 3-D
    t.filter = [](const ParamValues& p) { return FilterSpec::gaussian(p.get_real("sigma"), 1.0); };
    t.working_bytes = [](const ParamValues&, const SceneSize& s) {
        // Five lattice rows of 2 W + 3 doubles, and the positions.
        return memory_model::edge_table_bytes(s) + 6.0 * 8.0 * (2.0 * s.width + 3.0);
    };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        return cost_model::linear_ms(cost_model::kNishitaD, s.pixels(), s.vertices);
    };
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "point sampling on the half-pixel lattice: samples on edges flip"},
        {Invariant::kTranslation, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "2^20 + x rounds x by up to 2^-33 px: a sample exactly on an edge flips"},
    };
    return t;
}

MethodInfo nishita_d_method() {
    return {"nishita-d",
            "Nishita & Nakamae method D: 3x3 samples per pixel on a half-pixel lattice, "
            "radius-1 Gaussian over the 5x5 lattice points",
            {{"sigma", ParamKind::kReal, 0.5, 0.05, 10, {},
              "Gaussian sigma in px; the paper gives none, 0.5 is the suite's default"}},
            [](const ParamValues& p) {
                return std::make_unique<NishitaDMethod>(p.get_real("sigma"));
            }};
}

}  // namespace aabench
