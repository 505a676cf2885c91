// Errors a viewer sees, beside the linear ones (docs/metrics.md). Pure functions: no I/O.
//
// ꟻLIP (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström & Fairchild 2020, "ꟻLIP: A
// Difference Evaluator for Alternating Images"), the LDR form, written from the paper:
//   colour   both images filtered by the contrast sensitivity functions of the opponent channels
//            (sums of Gaussians, in YCxCz), clamped to the RGB cube, taken to CIELAB, Hunt-
//            adjusted (a, b scaled by 0.01 L), compared by HyAB (|ΔL| + |Δ(a, b)|), raised to
//            q_c = 0.7 and redistributed onto [0, 1] against the largest difference, green
//            against blue (p_c = 0.4 of it maps to p_t = 0.95);
//   features edge (first derivative of a Gaussian) and point (second derivative) detectors on
//            the luminance, the larger difference of their magnitudes, scaled by 1/sqrt(2) and
//            raised to q_f = 0.5;
//   ꟻLIP     per pixel colour^(1 - feature), in [0, 1].
// A grey image (one channel of linear values) enters the pipeline as grey, R = G = B = the value (clamped to [0, 1], the range LDR-ꟻLIP is defined on), already linear, so the
// paper's sRGB decoding is skipped. Grey has no chroma: Cx = Cz = 0, so only the achromatic
// filter acts, a = b = 0 after the Hunt adjustment, and HyAB is |ΔL*|; the code still runs the
// colour pipeline's building blocks, which the tests check on colours too. A colour scene's
// images (linear R, G, B planes) enter as their colours, each component clamped to [0, 1]:
// ꟻLIP as the paper defines it on colour, chroma and all.
//
// srgb_rmse: the rmse of the sRGB-encoded values (IEC 61966-2-1, values clamped to [0, 1], not
// quantised): the error in what a display shows, where FXAA, SMAA and TAA are tuned.
#pragma once

#include <array>
#include <vector>

#include "methods/scan/kernel/image.h"

namespace aabench::flip {

// The viewing conditions of the paper's default: a 0.7 m wide 3840 px monitor at 0.7 m.
inline constexpr double kMonitorDistanceM = 0.7;
inline constexpr double kMonitorWidthM = 0.7;
inline constexpr double kMonitorWidthPx = 3840.0;
// Pixels per degree of visual angle: distance * (px / width) * pi / 180, 67.02 by default.
double pixels_per_degree(double distance_m = kMonitorDistanceM, double width_m = kMonitorWidthM,
                         double width_px = kMonitorWidthPx);

using Vec3 = std::array<double, 3>;

// Colour transforms of the pipeline (linear sRGB primaries, D65 white).
Vec3 linear_rgb_to_xyz(const Vec3& rgb);
Vec3 xyz_to_linear_rgb(const Vec3& xyz);
Vec3 xyz_to_ycxcz(const Vec3& xyz);
Vec3 ycxcz_to_xyz(const Vec3& ycxcz);
Vec3 xyz_to_lab(const Vec3& xyz);
// (L, 0.01 L a, 0.01 L b): the Hunt effect, colourfulness falling with lightness.
Vec3 hunt_adjust(const Vec3& lab);
// |L1 - L2| + sqrt((a1 - a2)^2 + (b1 - b2)^2).
double hyab(const Vec3& lab1, const Vec3& lab2);
// HyAB of the Hunt-adjusted green and blue primaries raised to q_c: the largest colour error.
double max_colour_error();
// A HyAB difference raised to q_c, mapped onto [0, 1] (piecewise linear: p_c of the largest to
// p_t).
double redistribute_colour_error(double powered_hyab, double max_error);

// A square kernel, row-major, side 2 * radius + 1.
struct Kernel {
    int radius = 0;
    std::vector<double> weights;
    int side() const { return 2 * radius + 1; }
    double at(int dx, int dy) const {
        return weights[static_cast<std::size_t>(dy + radius) * side() + (dx + radius)];
    }
};

// The contrast sensitivity filter of an opponent channel (0 achromatic, 1 red-green, 2
// blue-yellow): sum of a * sqrt(pi / b) * exp(-pi^2 r^2 / b), r in degrees, normalised to sum
// 1; one radius for all three, from the widest Gaussian.
Kernel csf_kernel(int channel, double ppd);
// The feature detectors along x (the y ones are their transposes): first (edge) or second
// (point) derivative of a Gaussian of sd 0.5 * 0.082 degrees, positive weights normalised to
// sum 1 and negative ones to -1.
Kernel feature_kernel(bool point, double ppd);
// The same kernels rebuilt from the separable factors that the map filters by (sum over terms
// of scale * x[dx] * y[dy]): equal to csf_kernel / feature_kernel up to rounding.
Kernel csf_kernel_from_factors(int channel, double ppd);
Kernel feature_kernel_from_factors(bool point, double ppd);

// The reference's half of the map, which every image scored against it shares: its filtered
// CIELAB and its feature magnitudes at `ppd` (prepare_flip_reference). Made once per scene,
// the map of each image costs half as much, and is the same to the bit.
struct FlipReference {
    int width = 0, height = 0;
    double ppd = 0.0;
    std::vector<Vec3> lab;
    std::vector<double> edge, point;
};
FlipReference prepare_flip_reference(const Coverage& reference, double ppd);
// A colour scene's reference, its three planes (linear R, G, B, each clamped to [0, 1]): the
// paper's colour pipeline on its colours (one plane: the grey one above).
FlipReference prepare_flip_reference(const CoveragePlanes& reference, double ppd);

// The per-pixel ꟻLIP map of `test` against `reference`, both linear grey (see above); same
// size (std::invalid_argument otherwise). NaN pixels of test make the map NaN there.
Coverage flip_map(const Image& test, const Coverage& reference, double ppd);
Coverage flip_map(const Image& test, const FlipReference& reference);
// A colour image against a colour reference: the paper's ꟻLIP in colour (one plane: grey).
Coverage flip_map(const ImagePlanes& test, const FlipReference& reference);
double mean_flip(const ImagePlanes& test, const FlipReference& reference);
// mean(flip_map) at the default viewing conditions; NaN when test has a non-finite pixel.
double mean_flip(const Image& test, const Coverage& reference);
// The same against a prepared reference (made at pixels_per_degree(); else invalid_argument).
double mean_flip(const Image& test, const FlipReference& reference);

// sRGB encoding (IEC 61966-2-1) of a linear value clamped to [0, 1], not quantised.
double srgb_encode(double linear);
// sqrt(mean((srgb_encode(test) - srgb_encode(reference))^2)); NaN when test has a non-finite
// pixel.
double srgb_rmse(const Image& test, const Coverage& reference);

}  // namespace aabench::flip
