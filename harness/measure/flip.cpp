// ꟻLIP and the sRGB rmse (harness/measure/flip.h). The constants are the paper's (Andersson et
// al. 2020, section 3 and its supplement); filtering is OpenCV's sepFilter2D on the kernels'
// separable factors (csf_kernel and feature_kernel below are their products), with mirrored
// borders (edge pixel repeated, as the paper's reference code pads).
#include "harness/measure/flip.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

namespace aabench::flip {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kNaN = __builtin_nan("");

// Linear sRGB to XYZ (D65), the exact rationals the paper's code uses.
constexpr double kRgbToXyz[3][3] = {
    {10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0},
    {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0},
    {1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0}};

// Colour pipeline: the exponent on HyAB and where the redistribution bends (p_c of the largest
// error maps to p_t).
constexpr double kColourExponent = 0.7;  // q_c
constexpr double kColourBend = 0.4;      // p_c
constexpr double kColourBendTo = 0.95;   // p_t
// Feature pipeline: detector width in degrees (its sd is half of it) and the exponent.
constexpr double kFeatureWidthDeg = 0.082;  // w
constexpr double kFeatureExponent = 0.5;    // q_f

// The contrast sensitivity functions: a1, b1, a2, b2 of each opponent channel (b in deg^2).
struct CsfParams {
    double a1, b1, a2, b2;
};
constexpr CsfParams kCsf[3] = {{1.0, 0.0047, 0.0, 1e-5},    // achromatic
                               {1.0, 0.0053, 0.0, 1e-5},    // red-green
                               {34.1, 0.04, 13.5, 0.025}};  // blue-yellow
constexpr double kWidestCsfB = 0.04;

Vec3 multiply(const double m[3][3], const Vec3& v) {
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
            m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

const Vec3& white() {
    static const Vec3 w = linear_rgb_to_xyz({1.0, 1.0, 1.0});
    return w;
}

// A kernel as a sum of separable terms: weight(dx, dy) = sum of scale * x[dx] * y[dy]. The
// CSF kernels are sums of two Gaussians (one term each), the feature detectors a derivative
// along x times a Gaussian along y: filtering by the factors costs 2 (2 r + 1) per pixel and
// term instead of (2 r + 1)^2.
struct SeparableTerm {
    double scale = 1.0;
    cv::Mat x, y;  // 1 x (2 r + 1), CV_64F
};

cv::Mat row_of(const std::vector<double>& v) {
    cv::Mat m(1, static_cast<int>(v.size()), CV_64F);
    std::copy(v.begin(), v.end(), m.ptr<double>());
    return m;
}

int csf_radius(double ppd) {
    // Three standard deviations of the widest Gaussian (sd = sqrt(b / 2) / pi degrees).
    return static_cast<int>(std::ceil(3.0 * std::sqrt(kWidestCsfB / (2.0 * kPi * kPi)) * ppd));
}

// csf_kernel's factors: each Gaussian a sqrt(pi / b) exp(-pi^2 (dx^2 + dy^2) / (ppd^2 b)) is
// e(dx) e(dy); the 2-D sum is sum of a sqrt(pi / b) (sum of e)^2.
std::vector<SeparableTerm> csf_terms(int channel, double ppd) {
    const int radius = csf_radius(ppd);
    const CsfParams& s = kCsf[channel];
    std::vector<SeparableTerm> terms;
    double sum = 0.0;
    for (const auto [a, b] : {std::pair{s.a1, s.b1}, std::pair{s.a2, s.b2}}) {
        if (a == 0.0) continue;
        std::vector<double> e;
        double e_sum = 0.0;
        for (int d = -radius; d <= radius; ++d) {
            e.push_back(std::exp(-kPi * kPi * (d * d) / (ppd * ppd) / b));
            e_sum += e.back();
        }
        const double amplitude = a * std::sqrt(kPi / b);
        sum += amplitude * e_sum * e_sum;
        terms.push_back({amplitude, row_of(e), row_of(e)});
    }
    for (SeparableTerm& t : terms) t.scale /= sum;
    return terms;
}

// feature_kernel's factors: h(dx) g(dy), h = -dx g (edge) or (dx^2 / sd^2 - 1) g (point). The
// sign of a weight is h's, so normalising the positive weights to 1 and the negative ones to
// -1 divides h's positive and negative parts by their sums and g by its own.
SeparableTerm feature_term(bool point, double ppd, bool transposed) {
    const double sd = 0.5 * kFeatureWidthDeg * ppd;  // in pixels
    const int radius = static_cast<int>(std::ceil(3.0 * sd));
    std::vector<double> h, g;
    double positive = 0.0, negative = 0.0, g_sum = 0.0;
    for (int d = -radius; d <= radius; ++d) {
        const double gd = std::exp(-(d * d) / (2.0 * sd * sd));
        const double hd = point ? (d * d / (sd * sd) - 1.0) * gd : -d * gd;
        g.push_back(gd);
        h.push_back(hd);
        g_sum += gd;
        (hd > 0.0 ? positive : negative) += hd;
    }
    for (double& v : h) v = v > 0.0 ? v / positive : v / -negative;
    for (double& v : g) v /= g_sum;
    SeparableTerm t{1.0, row_of(h), row_of(g)};
    if (transposed) std::swap(t.x, t.y);
    return t;
}

cv::Mat filtered(const cv::Mat& image, const std::vector<SeparableTerm>& terms) {
    cv::Mat sum;
    for (const SeparableTerm& t : terms) {
        cv::Mat out;
        cv::sepFilter2D(image, out, CV_64F, t.x, t.y, cv::Point(-1, -1), 0.0,
                        cv::BORDER_REFLECT);
        if (t.scale != 1.0) out *= t.scale;
        if (sum.empty()) {
            sum = out;
        } else {
            sum += out;
        }
    }
    return sum;
}

// Per pixel, the edge and point feature magnitudes of a luminance image.
struct Features {
    cv::Mat edge;
    cv::Mat point;
};

Features features(const cv::Mat& luminance, double ppd) {
    const auto along = [&](bool point, bool transposed) {
        return filtered(luminance, {feature_term(point, ppd, transposed)});
    };
    Features f;
    cv::magnitude(along(false, false), along(false, true), f.edge);
    cv::magnitude(along(true, false), along(true, true), f.point);
    return f;
}

// The Hunt-adjusted CIELAB of each pixel after the CSF filtering, from the three YCxCz planes.
std::vector<Vec3> filtered_lab(const std::array<cv::Mat, 3>& ycxcz, double ppd) {
    std::array<cv::Mat, 3> planes;
    for (int c = 0; c < 3; ++c) planes[c] = filtered(ycxcz[c], csf_terms(c, ppd));
    std::vector<Vec3> lab(planes[0].total());
    for (std::size_t p = 0; p < lab.size(); ++p) {
        Vec3 rgb = xyz_to_linear_rgb(ycxcz_to_xyz(
            {planes[0].ptr<double>()[p], planes[1].ptr<double>()[p], planes[2].ptr<double>()[p]}));
        for (double& v : rgb) v = std::clamp(v, 0.0, 1.0);  // back into the RGB cube
        lab[p] = hunt_adjust(xyz_to_lab(linear_rgb_to_xyz(rgb)));
    }
    return lab;
}

// Grey values as YCxCz planes: R = G = B = the value clamped to [0, 1]; NaN stays NaN.
template <class T>
std::array<cv::Mat, 3> grey_ycxcz(const Raster<T>& image) {
    std::array<cv::Mat, 3> planes;
    for (cv::Mat& m : planes) m.create(image.height, image.width, CV_64F);
    for (std::size_t p = 0; p < image.pixel_count(); ++p) {
        const double v = image.data[p];
        const double g = std::isnan(v) ? v : std::clamp(v, 0.0, 1.0);
        const Vec3 y = xyz_to_ycxcz(linear_rgb_to_xyz({g, g, g}));
        for (int c = 0; c < 3; ++c) planes[c].ptr<double>()[p] = y[c];
    }
    return planes;
}

// Colour planes (linear R, G, B) as YCxCz planes, each component clamped to [0, 1] (the RGB
// cube LDR-ꟻLIP is defined on); a pixel with a NaN component is NaN in every plane.
template <class T>
std::array<cv::Mat, 3> colour_ycxcz(const Planes<T>& image) {
    std::array<cv::Mat, 3> planes;
    for (cv::Mat& m : planes) m.create(image.height(), image.width(), CV_64F);
    const std::size_t n = image[0].pixel_count();
    for (std::size_t p = 0; p < n; ++p) {
        Vec3 rgb{};
        bool nan = false;
        for (int c = 0; c < 3; ++c) {
            const double v = image[c].data[p];
            nan = nan || std::isnan(v);
            rgb[static_cast<std::size_t>(c)] = std::clamp(v, 0.0, 1.0);
        }
        const Vec3 y = xyz_to_ycxcz(linear_rgb_to_xyz(rgb));
        for (int c = 0; c < 3; ++c) {
            planes[c].ptr<double>()[p] = nan ? std::nan("") : y[static_cast<std::size_t>(c)];
        }
    }
    return planes;
}

// Relative luminance Y / Yn from the YCxCz luminance plane: the feature pipeline's input.
cv::Mat luminance(const cv::Mat& y_plane) { return (y_plane + 16.0) / 116.0; }

}  // namespace

double pixels_per_degree(double distance_m, double width_m, double width_px) {
    return distance_m * (width_px / width_m) * kPi / 180.0;
}

Vec3 linear_rgb_to_xyz(const Vec3& rgb) { return multiply(kRgbToXyz, rgb); }

Vec3 xyz_to_linear_rgb(const Vec3& xyz) {
    static const cv::Matx33d inverse = cv::Matx33d(&kRgbToXyz[0][0]).inv();
    const cv::Vec3d out = inverse * cv::Vec3d(xyz[0], xyz[1], xyz[2]);
    return {out[0], out[1], out[2]};
}

Vec3 xyz_to_ycxcz(const Vec3& xyz) {
    const Vec3& w = white();
    const double x = xyz[0] / w[0], y = xyz[1] / w[1], z = xyz[2] / w[2];
    return {116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z)};
}

Vec3 ycxcz_to_xyz(const Vec3& ycxcz) {
    const Vec3& w = white();
    const double y = (ycxcz[0] + 16.0) / 116.0;
    return {(ycxcz[1] / 500.0 + y) * w[0], y * w[1], (y - ycxcz[2] / 200.0) * w[2]};
}

Vec3 xyz_to_lab(const Vec3& xyz) {
    const Vec3& w = white();
    constexpr double kDelta = 6.0 / 29.0;
    const auto f = [](double t) {
        return t > kDelta * kDelta * kDelta ? std::cbrt(t)
                                            : t / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
    };
    const double fx = f(xyz[0] / w[0]), fy = f(xyz[1] / w[1]), fz = f(xyz[2] / w[2]);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

Vec3 hunt_adjust(const Vec3& lab) {
    return {lab[0], 0.01 * lab[0] * lab[1], 0.01 * lab[0] * lab[2]};
}

double hyab(const Vec3& lab1, const Vec3& lab2) {
    return std::abs(lab1[0] - lab2[0]) + std::hypot(lab1[1] - lab2[1], lab1[2] - lab2[2]);
}

double max_colour_error() {
    const Vec3 green = hunt_adjust(xyz_to_lab(linear_rgb_to_xyz({0.0, 1.0, 0.0})));
    const Vec3 blue = hunt_adjust(xyz_to_lab(linear_rgb_to_xyz({0.0, 0.0, 1.0})));
    return std::pow(hyab(green, blue), kColourExponent);
}

double redistribute_colour_error(double powered_hyab, double max_error) {
    const double bend = kColourBend * max_error;
    if (powered_hyab < bend) return kColourBendTo / bend * powered_hyab;
    return kColourBendTo + (powered_hyab - bend) / (max_error - bend) * (1.0 - kColourBendTo);
}

Kernel csf_kernel(int channel, double ppd) {
    if (channel < 0 || channel > 2) throw std::invalid_argument("csf_kernel: channel is 0..2");
    Kernel k;
    k.radius = csf_radius(ppd);
    const CsfParams& s = kCsf[channel];
    double sum = 0.0;
    for (int dy = -k.radius; dy <= k.radius; ++dy) {
        for (int dx = -k.radius; dx <= k.radius; ++dx) {
            const double r2 = (dx * dx + dy * dy) / (ppd * ppd);  // degrees^2
            const double g = s.a1 * std::sqrt(kPi / s.b1) * std::exp(-kPi * kPi * r2 / s.b1) +
                             s.a2 * std::sqrt(kPi / s.b2) * std::exp(-kPi * kPi * r2 / s.b2);
            k.weights.push_back(g);
            sum += g;
        }
    }
    for (double& w : k.weights) w /= sum;
    return k;
}

Kernel feature_kernel(bool point, double ppd) {
    const double sd = 0.5 * kFeatureWidthDeg * ppd;  // in pixels
    Kernel k;
    k.radius = static_cast<int>(std::ceil(3.0 * sd));
    double positive = 0.0, negative = 0.0;
    for (int dy = -k.radius; dy <= k.radius; ++dy) {
        for (int dx = -k.radius; dx <= k.radius; ++dx) {
            const double g = std::exp(-(dx * dx + dy * dy) / (2.0 * sd * sd));
            const double w = point ? (dx * dx / (sd * sd) - 1.0) * g : -dx * g;
            k.weights.push_back(w);
            (w > 0.0 ? positive : negative) += w;
        }
    }
    // Positive weights to sum 1 and negative ones to -1: a detector's response is a fraction of
    // the largest step it can see, whatever the viewing distance.
    for (double& w : k.weights) w = w > 0.0 ? w / positive : w / -negative;
    return k;
}

namespace {

Kernel from_terms(const std::vector<SeparableTerm>& terms) {
    Kernel k;
    k.radius = terms.front().x.cols / 2;
    k.weights.assign(static_cast<std::size_t>(k.side()) * k.side(), 0.0);
    for (const SeparableTerm& t : terms) {
        for (int dy = 0; dy < k.side(); ++dy) {
            for (int dx = 0; dx < k.side(); ++dx) {
                k.weights[static_cast<std::size_t>(dy) * k.side() + dx] +=
                    t.scale * t.x.at<double>(0, dx) * t.y.at<double>(0, dy);
            }
        }
    }
    return k;
}

}  // namespace

Kernel csf_kernel_from_factors(int channel, double ppd) {
    if (channel < 0 || channel > 2) throw std::invalid_argument("csf_kernel: channel is 0..2");
    return from_terms(csf_terms(channel, ppd));
}

Kernel feature_kernel_from_factors(bool point, double ppd) {
    return from_terms({feature_term(point, ppd, false)});
}

namespace {

FlipReference prepare_from_ycxcz(const std::array<cv::Mat, 3>& ycxcz, int width, int height,
                                 double ppd) {
    FlipReference out;
    out.width = width;
    out.height = height;
    out.ppd = ppd;
    out.lab = filtered_lab(ycxcz, ppd);
    const Features f = features(luminance(ycxcz[0]), ppd);
    const auto copy = [](const cv::Mat& m) {
        return std::vector<double>(m.ptr<double>(), m.ptr<double>() + m.total());
    };
    out.edge = copy(f.edge);
    out.point = copy(f.point);
    return out;
}

Coverage map_from_ycxcz(const std::array<cv::Mat, 3>& test_ycxcz, int width, int height,
                        const FlipReference& reference) {
    if (width != reference.width || height != reference.height) {
        throw std::invalid_argument("flip_map: image sizes differ");
    }
    const double ppd = reference.ppd;
    const std::vector<Vec3> test_lab = filtered_lab(test_ycxcz, ppd);
    const Features test_f = features(luminance(test_ycxcz[0]), ppd);
    const double max_error = max_colour_error();
    Coverage map(width, height);
    for (std::size_t p = 0; p < map.pixel_count(); ++p) {
        const double colour = redistribute_colour_error(
            std::pow(hyab(reference.lab[p], test_lab[p]), kColourExponent), max_error);
        const double edge = std::abs(reference.edge[p] - test_f.edge.ptr<double>()[p]);
        const double point = std::abs(reference.point[p] - test_f.point.ptr<double>()[p]);
        const double feature = std::pow(std::max(edge, point) / std::sqrt(2.0), kFeatureExponent);
        map.data[p] = std::pow(colour, 1.0 - feature);
    }
    return map;
}

double mean_of(const Coverage& map) {
    double sum = 0.0;
    for (double v : map.data) sum += v;
    return map.data.empty() ? kNaN : sum / static_cast<double>(map.data.size());
}

}  // namespace

FlipReference prepare_flip_reference(const Coverage& reference, double ppd) {
    return prepare_from_ycxcz(grey_ycxcz(reference), reference.width, reference.height, ppd);
}

FlipReference prepare_flip_reference(const CoveragePlanes& reference, double ppd) {
    if (reference.channels() == 1) return prepare_flip_reference(reference[0], ppd);
    return prepare_from_ycxcz(colour_ycxcz(reference), reference.width(), reference.height(),
                              ppd);
}

Coverage flip_map(const Image& test, const FlipReference& reference) {
    return map_from_ycxcz(grey_ycxcz(test), test.width, test.height, reference);
}

Coverage flip_map(const ImagePlanes& test, const FlipReference& reference) {
    if (test.channels() == 1) return flip_map(test[0], reference);
    return map_from_ycxcz(colour_ycxcz(test), test.width(), test.height(), reference);
}

Coverage flip_map(const Image& test, const Coverage& reference, double ppd) {
    return flip_map(test, prepare_flip_reference(reference, ppd));  // it checks the sizes
}

double mean_flip(const Image& test, const FlipReference& reference) {
    if (reference.ppd != pixels_per_degree()) {
        throw std::invalid_argument("mean_flip: the reference was prepared at another ppd");
    }
    for (float v : test.data) {
        if (!std::isfinite(v)) return kNaN;
    }
    return mean_of(flip_map(test, reference));
}

double mean_flip(const ImagePlanes& test, const FlipReference& reference) {
    if (reference.ppd != pixels_per_degree()) {
        throw std::invalid_argument("mean_flip: the reference was prepared at another ppd");
    }
    for (const Image& plane : test.planes) {
        for (float v : plane.data) {
            if (!std::isfinite(v)) return kNaN;
        }
    }
    return mean_of(flip_map(test, reference));
}

double mean_flip(const Image& test, const Coverage& reference) {
    return mean_flip(test, prepare_flip_reference(reference, pixels_per_degree()));
}

double srgb_encode(double linear) {
    const double v = std::clamp(linear, 0.0, 1.0);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

double srgb_rmse(const Image& test, const Coverage& reference) {
    if (test.width != reference.width || test.height != reference.height) {
        throw std::invalid_argument("srgb_rmse: image sizes differ");
    }
    double sum = 0.0;
    for (std::size_t p = 0; p < test.pixel_count(); ++p) {
        if (!std::isfinite(test.data[p])) return kNaN;
        const double d = srgb_encode(test.data[p]) - srgb_encode(reference.data[p]);
        sum += d * d;
    }
    return test.data.empty() ? kNaN : std::sqrt(sum / static_cast<double>(test.pixel_count()));
}

}  // namespace aabench::flip
