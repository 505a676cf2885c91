// nishita-d — Nishita & Nakamae's method D: 3 x 3 point samples per pixel, filtered by a
// radius-1 Gaussian over the 5 x 5 lattice points around each pixel centre.
//
// Source: Nishita & Nakamae 1984, §4 and Fig. 5(d): "(d) is filtering by the usual method of
// increasing the sample points (a Gaussian filter, 3 x 3 sample points in a pixel, the colour
// of one pixel decided from 5 x 5 points including the neighbouring pixels)". The paper's
// filters have a radius of one pixel width and unit volume (§2.2.2), which fixes radius 1 and
// the normalisation. The paper gives no sigma for its Gaussian: sigma is a parameter whose
// default, 0.5 px, is the suite's default Gaussian. Exact reference: "gaussian:sigma=S,radius=1".
//
// Two readings of "3 x 3 sample points in a pixel" (parameter `lattice`):
//
//   lattice=third (default): the centres of a 3 x 3 stratification of the pixel, a lattice of
//     spacing 1/3 px at x = i + 1/6, i + 1/2, i + 5/6 (likewise y). Every pixel owns 9 points
//     and shares none; the 5 x 5 window of the lattice around the pixel centre (offsets
//     dx/3, dy/3 with dx, dy in -2..2) is the pixel's own 9 and the nearest 16 of its
//     neighbours', all within r = sqrt(8)/3 = 0.943 px, so all 25 carry a Gaussian weight.
//   lattice=half: a lattice of spacing 1/2 px through the pixel centres, so also through the
//     pixel corners and edge midpoints. The footprint [i, i+1] x [j, j+1] holds 3 x 3 points,
//     but those on its border are shared with the neighbours: about 4 distinct samples per
//     pixel, 2 sample rows per pixel row. Of the 5 x 5 window (offsets dx/2, dy/2) only the 13
//     points with r <= 1 are weighted (the centre, four at r = 1/2, four diagonal at
//     r = sqrt(2)/2, and the four neighbour centres at r = 1 exactly; r <= 1 is inclusive so
//     the window does reach the neighbouring pixels, as the paper says).
//
// Why `third` is the default: "3 x 3 inside the pixel" reads most naturally as 9 samples that
// belong to the pixel (the usual stratified supersampling the paper compares against), and
// with it every one of the "5 x 5 points including the neighbouring pixels" lies inside the
// filter's radius and counts; the half-pixel reading samples the pixel at about 4 points, and
// 12 of its 25 window points would carry no weight, which the paper's wording does not
// suggest. `half` stays for comparison with figures measured before.
//
// Computes, for either lattice (spacing 1/n px, n = 3 or 2):
//   out(i, j) = sum w(dx, dy) v(i + 1/2 + dx/n, j + 1/2 + dy/n),  dx, dy in -2..2,
//   w(dx, dy) = exp(-r^2 / (2 sigma^2)) / W  with r = sqrt(dx^2 + dy^2)/n px when r <= 1, else 0,
// W the sum of the unnormalised weights over the window, v the scene's visible value at the
// point (methods/scan/sampling/point_sampling.h, the tie rule of `none`). The weights sum to 1, so
// a constant scene gives its value. The lattice reaches 2/n - 1/2 px (1/6 or 1/2) past the image
// on every side.
//
// 3-D scenes (a ScreenScene with depth planes; Method::own_visibility()): each lattice point is
// the shape nearest at it by its depth plane (a depth per sample: a z-buffer on the lattice,
// methods/scan/sampling/point_sampling.h); affine values are taken at the point.
//
// Parameters:
//   sigma    real, default 0.5, range 0.05..10 px. The Gaussian's sigma (the paper gives none;
//            0.5 is the suite's default). Below 0.05 the nearest ring weighs nothing next to
//            the centre (the method degenerates to `none`); above 10 the weights are equal.
//   lattice  third (default) or half: the reading above.
//
// Cost: (3w + 2)(3h + 2) samples (9 per pixel, 3 sample rows per pixel row) for `third`,
// (2w + 3)(2h + 3) (about 4 per pixel) for `half`; 25 multiply-adds per pixel either way (for
// `half` 12 of the weights are zero: a fixed-size loop is cheaper than skipping them), plus the
// edge crossings of each lattice row, found once per row.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/sampling/point_sampling.h"
#include "methods/scan/sampling/run_sums.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

constexpr int kWindow = 5;    // lattice points per side of a pixel's window
constexpr int kRingRows = 5;  // lattice rows held at once: one pixel row's window

// Lattice points per pixel side: the two readings of "3 x 3 sample points in a pixel".
int points_per_px(const ParamValues& p) { return p.get_choice("lattice") == "half" ? 2 : 3; }

class NishitaDMethod : public Method {
public:
    // per_px: 3 (lattice=third, spacing 1/3 px) or 2 (lattice=half, spacing 1/2 px); `filter`
    // the radius-1 Gaussian.
    NishitaDMethod(const Filter& filter, int per_px) : filter_(filter), per_px_(per_px) {
        double total = 0.0;
        for (int dy = -2; dy <= 2; ++dy) {
            for (int dx = -2; dx <= 2; ++dx) {
                const int d2 = dx * dx + dy * dy;  // (n r)^2, exact
                const double r2 = static_cast<double>(d2) / (per_px_ * per_px_);
                // r <= 1 compared on the integers: exact, so the four neighbour centres of the
                // half lattice (r = 1) are in. Every point of the third lattice's window is.
                const bool inside = d2 <= per_px_ * per_px_;
                const double w = inside ? filter_.profile_r2(r2) : 0.0;
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
        const int width = scene.width, height = scene.height, n = per_px_;
        // Lattice index q <-> x = (q - 2)/n + 1/2, computed as (2q + n - 4) / (2n): exact for
        // n = 2, correctly rounded for n = 3, and pixel centres (q = n i + 2) are exact. Pixel
        // i's window is q in [n i, n i + 4]; the lattice runs from q = 0 to the last pixel's
        // window end, n (w - 1) + 4. Rows likewise.
        const int lattice_w = n * width + kWindow - n, lattice_h = n * height + kWindow - n;
        auto position = [n](int q) { return static_cast<double>(2 * q + n - 4) / (2.0 * n); };
        // Per-thread scratch (one Method may render from several threads at once), kept between
        // renders: a warm render allocates nothing.
        thread_local std::vector<double> xs, ring;
        thread_local std::vector<ValueRuns> ring_runs;  // per ring slot, flat scenes
        thread_local std::vector<char> marked;
        thread_local std::array<char, kRingRows> written;  // per ring slot: values written out
        thread_local PointSampler sampler;
        xs.resize(lattice_w);
        for (int q = 0; q < lattice_w; ++q) xs[q] = position(q);
        // Ring of the last kRingRows lattice rows: row q lives in slot q % kRingRows, and a
        // pixel row's window is 5 consecutive rows, so they never collide.
        ring.resize(static_cast<std::size_t>(kRingRows) * lattice_w);
        auto ring_row = [&](int q) { return ring.data() + (q % kRingRows) * lattice_w; };
        // The lattice rows this band samples, where curves cross exactly (none without curves).
        thread_local std::vector<double> lines;
        lines.clear();
        if (has_bezier(scene)) {
            const int q_end = std::min(n * (row_hi - 1) + kWindow, lattice_h);
            for (int q = n * row_lo; q < q_end; ++q) lines.push_back(position(q));
        }
        sampler.reset(scene, 1.0, lines);  // lattice rows reach y = -1/2 and y = h + 1/2 at most
        // Flat scenes (constant values, no depth): lattice rows taken as runs between
        // crossings (nothing written per point), and only the pixels whose window (or the span
        // from their left neighbour's window to theirs) holds a change of value are summed; the
        // others copy their left neighbour, whose 25 values are the same in the same order, so
        // the same sum bit for bit (point_sampling.h, mark_pixels_at_starts). The 25
        // multiply-adds of every pixel were most of the time; now it is the crossings of the
        // lattice rows, a copy per pixel and the pixels an edge passes through.
        const bool runs = sampler.flat();
        ring_runs.resize(kRingRows);
        marked.resize(width);
        // Values in one power-of-two unit: the sparse rows summed from the steps (below).
        thread_local RowDifferences sums_by_pixel;
        std::optional<FixedPointWindow> fixed;
        if (runs) {
            const DyadicValues dyadic = DyadicValues::of(sampler.table());
            if (dyadic.exact) {
                fixed.emplace(weights_, n, width, dyadic);
                sums_by_pixel.reset(width);
            }
        }
        // Lattice rows [n row_lo, sampled) have been sampled: pixel row j's window starts at
        // lattice row n j.
        int sampled = n * row_lo;
        for (int j = row_lo; j < row_hi; ++j) {
            for (; sampled <= n * j + kWindow - 1 && sampled < lattice_h; ++sampled) {
                const std::span<double> values(ring_row(sampled),
                                               static_cast<std::size_t>(lattice_w));
                if (runs) {
                    sampler.sample_runs(position(sampled), xs, ring_runs[sampled % kRingRows]);
                    written[sampled % kRingRows] = 0;
                } else {
                    sampler.sample_values(position(sampled), xs, values);
                }
            }
            // Dense rows (an edge every pixel or two) and scenes with planes: every pixel
            // summed from the lattice values written out.
            bool dense = !runs;
            if (runs) {
                std::size_t changes = 0;
                for (int dy = 0; dy < kWindow; ++dy) {
                    changes += ring_runs[(n * j + dy) % kRingRows].changes().size();
                }
                dense = dense_changes(changes, kWindow, width);
                for (int dy = 0; dense && dy < kWindow; ++dy) {
                    const int slot = (n * j + dy) % kRingRows;
                    if (written[slot]) continue;
                    ring_runs[slot].write(
                        {ring_row(n * j + dy), static_cast<std::size_t>(lattice_w)});
                    written[slot] = 1;
                }
            }
            float* row = out.row(j);
            if (!dense && fixed) {
                sum_row_by_steps(*fixed, ring_runs, j, width, sums_by_pixel, row);
                continue;
            }
            if (dense) {
                for (int i = 0; i < width; ++i) {
                    double sum = 0.0;
                    for (int dy = 0; dy < kWindow; ++dy) {
                        const double* lattice = ring_row(n * j + dy) + n * i;
                        for (int dx = 0; dx < kWindow; ++dx) sum += weights_[dy][dx] * lattice[dx];
                    }
                    row[i] = static_cast<float>(sum);
                }
                continue;
            }
            // The other pixels equal their left neighbour unless a change lies in between.
            std::fill(marked.begin(), marked.end(), 0);
            marked[0] = 1;
            for (int dy = 0; dy < kWindow; ++dy) {
                mark_pixels_at_starts(ring_runs[(n * j + dy) % kRingRows].changes(), n, 0, kWindow,
                                      marked);
            }
            write_marked_row(marked, row, [&](std::size_t i) {
                double sum = 0.0;
                for (int dy = 0; dy < kWindow; ++dy) {
                    ValueRuns& lattice = ring_runs[(n * j + dy) % kRingRows];
                    const std::size_t first = static_cast<std::size_t>(n) * i;
                    for (int dx = 0; dx < kWindow; ++dx) {
                        sum += weights_[dy][dx] * lattice.at(first + dx);
                    }
                }
                return static_cast<float>(sum);
            });
        }
    }

private:
    // Flat scenes whose values are integers in one power-of-two unit (0 and 1 in the built-in
    // patterns; methods/scan/sampling/run_sums.h), rows with few changes. A change of value at
    // lattice point s of window row dy steps the sum of the pixels whose window reaches it: pixel i
    // sees the new value at its window columns dx >= s - n i, so its sum holds step * (the
    // weights of row dy from column s - n i on), which is 0 left of the change, all of the
    // row's weight from the pixel whose window starts at s, and between them two or three
    // partial values: a difference array over the pixels takes those two or three entries, and
    // one prefix sum along the row gives every pixel's sum. (Dense rows keep the 25
    // multiply-adds per pixel: past a change every pixel or so they cost less than the steps.)
    //
    // In integers, exactly: the weights as fixed-point integers of 2^-F (F fractional bits,
    // as many as keep every entry below 2^62), the values in their units. The method's own
    // sum, sum_s w(s) v(s) in double in window order, differs from that exact sum by a few
    // double ulps (summation) and the fixed point's rounding of the 25 weights; that slack is
    // bounded below, and where the two ends of [sum - slack, sum + slack] round to the same
    // float32, that float is the method's output bit for bit (decided_float). Where they do
    // not (a sum within about 1e-14 of a float32 midpoint, or a sum of exactly 0 with values
    // of both signs), the pixel is summed in window order as before. A pixel whose exact sum
    // is 0 with no negative value and no weight lost to the fixed point has every term 0,
    // whose window-order sum is +0.
    struct FixedPointWindow {
        FixedPointWindow(const double (&weights)[kWindow][kWindow], int n, int width,
                         const DyadicValues& values)
            : dyadic(values), n(n), divide(n, static_cast<std::uint64_t>(n) * width + kWindow + n) {
            // F: |an entry| <= (at most n + 4 changes of a window row reach a pixel, five rows)
            // * (a step, <= 2 max_units) * 2^F < 2^7 * 2^bits * 2^F <= 2^62.
            int bits = 1;
            while ((dyadic.max_units >> bits) != 0) ++bits;
            const int fraction_bits = 55 - bits;
            // suffix[dy][t]: the fixed-point weights of window row dy from column t on.
            std::int64_t suffix[kWindow][kWindow + 1];
            zero_is_every_term_zero = dyadic.nonnegative;
            for (int dy = 0; dy < kWindow; ++dy) {
                suffix[dy][kWindow] = 0;
                for (int dx = kWindow - 1; dx >= 0; --dx) {
                    const std::int64_t w = std::llround(std::ldexp(weights[dy][dx], fraction_bits));
                    suffix[dy][dx] = suffix[dy][dx + 1] + w;
                    // An exact sum of 0 then means every term is 0 (values >= 0, weights > 0),
                    // unless a weight too small for the fixed point (sigma near its minimum)
                    // was rounded to 0.
                    if (weights[dy][dx] != 0.0 && w == 0) zero_is_every_term_zero = false;
                }
            }
            // The entry of a change at window column t = s - n i of pixel i > 0 (its sum minus
            // pixel i - 1's), t in [1 - n, 4] (i runs up to the pixel whose window starts at or
            // after s), at index t + n - 1; and pixel 0's whole contribution, the same t.
            auto suffix_at = [&](int dy, int t) { return suffix[dy][std::clamp(t, 0, kWindow)]; };
            for (int dy = 0; dy < kWindow; ++dy) {
                first_weight[dy] = suffix[dy][0];
                for (int t = 1 - n; t < kWindow; ++t) {
                    entry[dy][t + n - 1] = suffix_at(dy, t) - suffix_at(dy, t + n);
                    entry_first[dy][t + n - 1] = suffix_at(dy, t);
                }
            }
            unit = std::ldexp(1.0, dyadic.exponent - fraction_bits);
            // |window-order sum - exact sum| <= 50 ulps of the largest value (25 products and
            // 25 additions of terms whose weights sum to 1); |fixed-point sum - exact| <= 25
            // half units of 2^-F of it; the conversion to double and the two ends one ulp
            // each. Doubled.
            const double largest =
                std::ldexp(static_cast<double>(dyadic.max_units), dyadic.exponent);
            slack = largest * (std::ldexp(256.0, -53) + std::ldexp(64.0, -(fraction_bits + 1)));
        }

        DyadicValues dyadic;
        int n;
        DivideBy divide;
        std::int64_t first_weight[kWindow];
        std::int64_t entry[kWindow][kWindow + 2], entry_first[kWindow][kWindow + 2];
        double unit = 0.0, slack = 0.0;  // a sum's value is sum * unit, within slack
        bool zero_is_every_term_zero = false;
    };

    // Pixel row j from the runs of its window rows (ring slot (n j + dy) % kRingRows).
    void sum_row_by_steps(const FixedPointWindow& fixed, std::vector<ValueRuns>& ring, int j,
                          int width, RowDifferences& sums_by_pixel, float* row) const {
        const int n = fixed.n;
        const DyadicValues& dyadic = fixed.dyadic;
        const RowDifferences::Writer steps = sums_by_pixel.writer();
        std::int64_t first = 0;  // pixel 0's sum before the steps (the rows' first values)
        for (int dy = 0; dy < kWindow; ++dy) {
            const ValueRuns& lattice = ring[(n * j + dy) % kRingRows];
            first += dyadic.units(lattice.values[0]) * fixed.first_weight[dy];
            std::int64_t before = dyadic.units(lattice.values[0]);
            const std::int64_t* row_entry = fixed.entry[dy] + n - 1;  // by t
            for (std::size_t r = 1; r < lattice.starts.size(); ++r) {
                const std::int64_t after = dyadic.units(lattice.values[r]);
                const std::int64_t step = after - before;
                before = after;
                const std::uint32_t s = lattice.starts[r];
                // Pixels whose window [n i, n i + 4] reaches s (i >= ceil((s - 4) / n)), up to
                // the one it starts at (ceil(s / n)).
                std::uint32_t i = s > kWindow - 1 ? fixed.divide(s - kWindow + n) : 0;
                if (i >= static_cast<std::uint32_t>(width)) break;  // and every later change
                const std::uint32_t i_last =
                    std::min(fixed.divide(s + n - 1), static_cast<std::uint32_t>(width - 1));
                if (i == 0) {
                    steps.add(0, step * fixed.entry_first[dy][s + n - 1]);
                    ++i;
                }
                for (; i <= i_last; ++i) {
                    steps.add(i, step * row_entry[static_cast<int>(s - n * i)]);
                }
            }
        }
        sums_by_pixel.resolve_and_clear(first, row, [&](std::size_t i, std::int64_t sum) {
            if (sum == 0 && fixed.zero_is_every_term_zero) return 0.0f;
            float value;
            if (decided_float(static_cast<double>(sum) * fixed.unit, fixed.slack, value)) {
                return value;
            }
            double exact = 0.0;  // the window-order sum, as the other paths compute it
            for (int dy = 0; dy < kWindow; ++dy) {
                ValueRuns& lattice = ring[(n * j + dy) % kRingRows];
                for (int dx = 0; dx < kWindow; ++dx) {
                    exact += weights_[dy][dx] * lattice.at(static_cast<std::size_t>(n) * i + dx);
                }
            }
            return static_cast<float>(exact);
        });
    }

    Filter filter_;
    int per_px_;
    double weights_[kWindow][kWindow];  // [dy + 2][dx + 2], zero beyond r = 1, sum 1
};

// The radius-1 Gaussian of `sigma`: the weights' profile and the exact reference scored against.
Filter nishita_d_filter(const ParamValues& p) { return Filter::gaussian(p.get_real("sigma"), 1.0); }

}  // namespace

// What the harness knows of `nishita-d` (methods/method_traits.h).
MethodTraits nishita_d_traits() {
    MethodTraits t;
    t.curves = "exact crossings of each sample row: the roots of y(t) = row, no flattening";
    t.own_visibility = true;
    t.affine_values = true;  // z-buffer per sample in 3-D
    t.filter = nishita_d_filter;
    t.working_bytes = [](const ParamValues& p, const SceneSize& s) {
        // Five lattice rows of n W + 5 - n doubles, and the positions.
        const double n = points_per_px(p);
        return memory_model::edge_table_bytes(s) + 6.0 * 8.0 * (n * s.width + 5.0 - n);
    };
    t.time_ms = [](const ParamValues& p, const SceneSize& s) {
        const double factor = points_per_px(p) == 3 ? cost_model::kNishitaDThirdFactor : 1.0;
        return factor * cost_model::linear_ms(cost_model::kNishitaD, s.pixels(), s.vertices);
    };
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "point sampling on the lattice: samples on edges flip"},
        {Invariant::kTranslation, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "2^20 + x rounds x by up to 2^-33 px: a sample exactly on an edge flips"},
    };
    return t;
}

MethodInfo nishita_d_method() {
    return {"nishita-d",
            "Nishita & Nakamae method D: 3x3 samples per pixel (1/3-px lattice, or the "
            "half-pixel one), radius-1 Gaussian over the 5x5 lattice points around the centre",
            {{"sigma",
              ParamKind::kReal,
              0.5,
              0.05,
              10,
              {},
              "Gaussian sigma in px; the paper gives none, 0.5 is the suite's default"},
             {"lattice",
              ParamKind::kChoice,
              0,
              0,
              0,
              {"third", "half"},
              "third: the centres of a 3x3 stratification of the pixel, all 25 window points "
              "weighted; half: a half-pixel lattice through centres, edge midpoints and "
              "corners, 13 of the 25 within the radius"}},
            [](const ParamValues& p) {
                return std::make_unique<NishitaDMethod>(nishita_d_filter(p), points_per_px(p));
            }};
}

}  // namespace aabench
