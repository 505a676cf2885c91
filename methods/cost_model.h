// The time estimates of the rows (MethodTraits::time_ms): a deterministic function of the job,
// from the coefficients below, never measured on the running machine. The figure is "ms on
// the machine of the cost-model run", good to a factor of about 2 (the ratios below); it ranks
// jobs and says which will take minutes, it is not a benchmark.
//
//   t_ms = fixed_ms + ms_per_mpixel * pixels / 1e6 + ms_per_medge * edges / 1e6
//          (+ ms_per_mcolumn * edge columns / 1e6 for the grid-circle methods)
//
// times a factor for the cost parameter, 1 at its default (the parameter values below).
//
// Fitted by `python3 scripts/fit_cost_model.py` from the cost-model run in docs/benchmarks.md
// ("Cost model": `build/aabench_bench --aabench_cost_model --benchmark_min_time=0.05`, commit
// a6abc3a): per method the four end points of its two series (star at 128^2 and 4096^2 with
// 180 and 576 edges; rings at 1024^2 with 5,092 and 123,052 edges), least squares on the
// relative error, coefficients >= 0. Predicted / measured at those points is 0.62 .. 1.33 for
// every method but fast-edge at 4096^2 (0.16: its blending per edge pixel grows faster than
// the pixels on the large star) and freetype (0.17 on the 4096^2 star, 0.37 on the 123,052-edge
// rings: its time grows faster than pixels and edges, ftgrays decomposing an outline per band
// of rows). freetype and stb-truetype were measured in a later run and scaled by agg's times in
// both (scripts/fit_cost_model.py says how).
#pragma once

namespace aabench::cost_model {

struct Coefficients {
    double fixed_ms = 0.0;
    double ms_per_mpixel = 0.0;
    double ms_per_medge = 0.0;
};

// clang-format off
inline constexpr Coefficients kNone           {0.02864, 0.2935, 54.75};
inline constexpr Coefficients kExact          {0.0907,  0.4531, 186.7};
inline constexpr Coefficients kBoxMultiscan   {0.1108,  0.9756, 91.55};  // n = 3
inline constexpr Coefficients kGaussMultiscan {0.2284,  4.296,  222.8};  // n = 3
inline constexpr Coefficients kSsaa           {0.2478,  20.04,  109.3};  // k = 3, grid, box
inline constexpr Coefficients kNishitaD       {0.1563,  13.34,  74.53};
inline constexpr Coefficients kFastEdge       {0.1035,  2.433,  113.0};
inline constexpr Coefficients kCairo          {0.03724, 2.298,  620.5};
inline constexpr Coefficients kAgg            {0.1028,  1.718,  300.1};
inline constexpr Coefficients kExact8Bit      {0.08924, 1.643,  245.7};
inline constexpr Coefficients kFreeType       {0.3569,  1.624,  552.8};
inline constexpr Coefficients kStbTruetype    {0.01249, 1.783,  115.8};
// clang-format on
// The optional peer blend2d (docs/peers.md) is not in the cost-model run's default build: its
// coefficients solve its two measured end points at 1024^2 (docs/benchmarks.md, "Exact against
// Blend2D"): star (192 edges) 0.875 ms and the dense rings (189,765 edges) 15.3 ms, with the
// fixed cost of `none`.
inline constexpr Coefficients kBlend2d{0.02864, 0.8070, 76.0};

// The cost parameters, from the scaling run in docs/benchmarks.md ( rings at 1024^2,
// `--aabench_scaling`): ssaa k = 1, 2, 3, 4, 6 took 13.1, 29.5, 51.6, 82.7, 167 ms, fitted
// exactly at k = 1, 3, 6 by A + B (sample rows per pixel row) + C (samples per pixel) with
// A = 5.38, B = 3.88, C = 3.84 (k = 2 and 4 within 4%); box-multiscan n = 1, 2, 3, 6, 12 took
// 13.8 .. 30.1 ms, 12.3 + 1.5 n; gauss-multiscan n = 1, 3, 6 took 15.0, 42.2, 81.7 ms,
// 1.66 + 13.34 n. Each factor is the fit at the setting over the fit at the default.
inline constexpr double kSsaaFixed = 5.38, kSsaaPerSampleRow = 3.88, kSsaaPerSample = 3.84;
inline constexpr double kBoxMultiscanFixed = 12.3, kBoxMultiscanPerLine = 1.5;
inline constexpr double kGaussMultiscanFixed = 1.66, kGaussMultiscanPerLine = 13.34;
// nishita-d's coefficients were fitted on the half-pixel lattice (2 sample rows and 4 samples
// per pixel); its default 1/3-px lattice takes 3 rows and 9 samples per pixel. With ssaa's
// fit above (the same sampler): (A + 3 B + 9 C) / (A + 2 B + 4 C) = 51.58 / 28.50.
inline constexpr double kNishitaDThirdFactor =
    (kSsaaFixed + 3 * kSsaaPerSampleRow + 9 * kSsaaPerSample) /
    (kSsaaFixed + 2 * kSsaaPerSampleRow + 4 * kSsaaPerSample);

// The grid-circle methods draw rings, which the cost-model run does not: their pixel cost is
// the fill `none` pays, their per-ring cost from the circle table of docs/methods-circles.md ("Does the table still
// pay?"), 188 .. 221 us per ring of radius 1024 for the three methods, divided by the ring's
// polygon's edge columns (its two contours span about 16 r columns): 13.5 ms per million.
inline constexpr Coefficients kGridCircleFill{0.02864, 0.2935, 0.0};
inline constexpr double kGridCircleMsPerMColumn = 13.5;

inline double linear_ms(const Coefficients& c, double pixels, double edges) {
    return c.fixed_ms + c.ms_per_mpixel * pixels * 1e-6 + c.ms_per_medge * edges * 1e-6;
}

// The three grid-circle methods' estimate: the fill, and the rings by their edge columns.
inline double grid_circle_ms(double pixels, double edge_columns) {
    return linear_ms(kGridCircleFill, pixels, 0.0) + kGridCircleMsPerMColumn * edge_columns * 1e-6;
}

}  // namespace aabench::cost_model
