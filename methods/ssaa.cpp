// ssaa — regular supersampling: k x k point samples per pixel, box- or Gaussian-filtered.
//
// Computes: the scene's visible value (methods/scan/point_sampling.h, the tie rule of `none`) at the
// sample points (i + (a + 0.5)/k, j + (b + 0.5)/k), a, b in [0, k), and from them
//   filter=box:      out(i, j) = (1/k^2) sum over the pixel's own k^2 samples;
//   filter=gaussian: out(i, j) = sum_s w(s) v(s) over the samples s of the pixel and its eight
//                    neighbours that lie within distance 1 of the pixel centre (r <= 1,
//                    inclusive), w(s) = exp(-r^2 / (2 sigma^2)) / W, where W is the sum of
//                    exp(-r^2 / (2 sigma^2)) over those same samples: the weights are
//                    normalised to sum to 1 over the samples inside the radius, so a constant
//                    scene gives its value and the result is a weighted mean (never outside
//                    the scene's value range).
// Source: the supersampling the papers compare against — Nishita & Nakamae 1984, §2.1 (B-2.1,
// "subpixels averaged or weighted") and §4 (method D is ssaa's Gaussian with k = 3 on a
// lattice through the pixel borders, see nishita_d.cpp); Kato & Kameyama §2 ("Supersampling").
// box: the k = 1 case is `none` bit for bit; the error of a pixel crossed by one straight edge
// is at most 1/k (docs/methods-sampling.md, "ssaa error bound").
// gaussian: approximates the radius-1 truncated Gaussian of sigma `sigma`, the filter of
// Nishita & Nakamae's method C (§2.2.2), whose exact reference is
// "gaussian:sigma=S,radius=1". Samples on the circle r = 1 itself are counted (the test
// r^2 <= 1 is done in exact integers, in units of 1/(2k)); for odd k they are the four
// neighbour centres.
//
// Parameters:
//   k      int, default 3, range 1..64. Samples per pixel side. 3 and 5 are the cases the suite
//          reports (3 matches the papers' n = 3 and method D's 3 x 3); the cost is O(k^2) per
//          pixel, and at 64 (4096 samples per pixel, error <= 1/64 per edge) a 1024^2 image
//          already takes seconds: more buys nothing a benchmark can use.
//   filter box|gaussian, default box. box approximates area coverage (reference "box").
//   sigma  real, default 0.5, range 0.05..10 px; used by filter=gaussian only. 0.5 is the
//          suite's default Gaussian (the papers give no sigma); below 0.05 px the filter is a
//          tenth of a pixel wide (at k = 3 every sample but the nearest weighs < e^-20 of it:
//          a point sampler), above 10 px it is flat to 0.5% over r <= 1 (a disc filter).
//
// Cost: O(k^2 * pixels) samples (about pi k^2 weights per pixel for gaussian), plus the edge
// crossings of each sample row, found once per row (not per sample).
#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "methods/method.h"
#include "methods/scan/point_sampling.h"

namespace aabench {
namespace {

// Sample offsets (a + 0.5)/k inside a pixel, a in [0, k).
std::vector<double> sample_offsets(int k) {
    std::vector<double> offsets(k);
    for (int a = 0; a < k; ++a) offsets[a] = (a + 0.5) / k;
    return offsets;
}

class SsaaBoxMethod : public Method {
public:
    explicit SsaaBoxMethod(int k) : k_(k) {}

    void render(const Scene& scene, Image& out) const override {
        if (has_origin(scene)) return render(in_window_frame(scene), out);  // scene.h
        const int k = k_, width = scene.width;
        const std::vector<double> offsets = sample_offsets(k);
        std::vector<double> xs(static_cast<std::size_t>(width) * k);
        for (int i = 0; i < width; ++i) {
            for (int a = 0; a < k; ++a) xs[static_cast<std::size_t>(i) * k + a] = i + offsets[a];
        }
        std::vector<double> values(xs.size()), sums(width);
        PointSampler sampler(scene);
        const double inv_count = 1.0 / (static_cast<double>(k) * k);
        for (int j = 0; j < scene.height; ++j) {
            std::fill(sums.begin(), sums.end(), 0.0);
            for (int b = 0; b < k; ++b) {
                sampler.sample_values(j + offsets[b], xs, values);
                const double* v = values.data();
                for (int i = 0; i < width; ++i, v += k) {
                    double row_sum = 0.0;
                    for (int a = 0; a < k; ++a) row_sum += v[a];
                    sums[i] += row_sum;
                }
            }
            float* row = out.row(j);
            // k = 1: 0 + v, times 1.0, is v exactly, so the result is `none` bit for bit.
            for (int i = 0; i < width; ++i) row[i] = static_cast<float>(sums[i] * inv_count);
        }
    }

private:
    int k_;
};

class SsaaGaussianMethod : public Method {
public:
    SsaaGaussianMethod(int k, double sigma) : k_(k), sigma_(sigma) { build_weights(); }

    std::string reference_filter() const override {
        return fmt::format("gaussian:sigma={},radius=1", format_real(sigma_));
    }

    void render(const Scene& scene, Image& out) const override {
        if (has_origin(scene)) return render(in_window_frame(scene), out);  // scene.h
        const int k = k_, width = scene.width, height = scene.height;
        const std::vector<double> offsets = sample_offsets(k);
        // Sample columns of pixel columns -1..width: sample (q, a) of pixel column q is at index
        // (q + 1) k + a, so the window of pixel i (window column c in [0, 3k)) starts at i k.
        const int columns = (width + 2) * k;
        std::vector<double> xs(columns);
        for (int q = -1; q <= width; ++q) {
            for (int a = 0; a < k; ++a) xs[(q + 1) * k + a] = q + offsets[a];
        }
        std::vector<double> values(columns);
        Coverage acc(width, height, 0.0);
        // One pixel of margin: the border pixels' windows reach into pixel rows -1 and height.
        PointSampler sampler(scene, 1.0);
        for (int p = -1; p <= height; ++p) {
            for (int b = 0; b < k; ++b) {
                sampler.sample_values(p + offsets[b], xs, values);
                // This sample row is window row (p - j + 1) k + b of the pixel rows j = p-1..p+1.
                for (int j = std::max(0, p - 1); j <= std::min(height - 1, p + 1); ++j) {
                    const Chord& chord = chords_[(p - j + 1) * k + b];
                    double* acc_row = acc.row(j);
                    for (int i = 0; i < width; ++i) {
                        const double* v = values.data() + static_cast<std::size_t>(i) * k;
                        double sum = 0.0;
                        for (int c = chord.first; c < chord.last; ++c) {
                            sum += chord.weights[c - chord.first] * v[c];
                        }
                        acc_row[i] += sum;
                    }
                }
            }
        }
        for (std::size_t n = 0; n < acc.data.size(); ++n) {
            out.data[n] = static_cast<float>(acc.data[n]);
        }
    }

private:
    // The nonzero weights of one window row: the disc is convex, so they are one run of
    // window columns [first, last).
    struct Chord {
        int first = 0, last = 0;
        std::vector<double> weights;
    };

    void build_weights() {
        const int k = k_, span = 3 * k;
        // Offsets from the pixel centre in units of 1/(2k): window index c gives
        // u = 2c + 1 - 3k (the sample (c mod k + 0.5)/k - 0.5 + (c div k - 1) pixels away), an
        // odd integer; the test u^2 + v^2 <= (2k)^2 is then exact, so samples on the circle
        // r = 1 are counted the same way on every side.
        const long long radius2 = 4LL * k * k;
        const double scale = 1.0 / (4.0 * k * k * 2.0 * sigma_ * sigma_);
        double total = 0.0;
        chords_.assign(span, {});
        for (int r = 0; r < span; ++r) {
            const long long v = 2LL * r + 1 - 3 * k;
            Chord& chord = chords_[r];
            chord.first = span;
            for (int c = 0; c < span; ++c) {
                const long long u = 2LL * c + 1 - 3 * k;
                if (u * u + v * v > radius2) continue;
                if (chord.first == span) chord.first = c;
                chord.last = c + 1;
                const double w = std::exp(-static_cast<double>(u * u + v * v) * scale);
                chord.weights.push_back(w);
                total += w;
            }
            if (chord.weights.empty()) chord.first = chord.last = 0;
        }
        for (Chord& chord : chords_) {
            for (double& w : chord.weights) w /= total;
        }
    }

    int k_;
    double sigma_;
    std::vector<Chord> chords_;  // per window row, [0, 3k)
};

}  // namespace

MethodInfo ssaa_method() {
    return {"ssaa",
            "regular supersampling, k x k samples per pixel, box or radius-1 Gaussian filter",
            {{"k", ParamKind::kInt, 3, 1, 64, {},
              "samples per pixel side; 3 and 5 are the reported cases, cost O(k^2)"},
             {"filter", ParamKind::kChoice, 0, 0, 0, {"box", "gaussian"},
              "box: mean of the pixel's samples; gaussian: radius-1 Gaussian over the pixel "
              "and its neighbours, weights normalised over the samples inside the radius"},
             {"sigma", ParamKind::kReal, 0.5, 0.05, 10, {},
              "Gaussian sigma in px (filter=gaussian only); 0.5 is the suite's default"}},
            [](const ParamValues& p) -> std::unique_ptr<Method> {
                if (p.get_choice("filter") == "gaussian") {
                    return std::make_unique<SsaaGaussianMethod>(p.get_int("k"),
                                                                p.get_real("sigma"));
                }
                return std::make_unique<SsaaBoxMethod>(p.get_int("k"));
            },
            "k", {1, 2, 3, 4, 5, 8, 16}};
}

}  // namespace aabench
