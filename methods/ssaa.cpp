// ssaa — supersampling: point samples per pixel in a regular k x k grid (the default), a rotated
// grid or the standard multisample pattern of the GPUs, box- or Gaussian-filtered.
//
// Computes: the scene's visible value (methods/scan/point_sampling.h, the tie rule of `none`)
// at the sample points of the pattern — pattern=grid: (i + (a + 0.5)/k, j + (b + 0.5)/k),
// a, b in [0, k); rgss and msaa: methods/scan/sample_patterns.h — and from them
//   filter=box:      out(i, j) = (1/k^2) sum over the pixel's own k^2 samples;
//   filter=gaussian: out(i, j) = sum_s w(s) v(s) over the samples s of the pixel and its eight
//                    neighbours that lie within distance 1 of the pixel centre (r <= 1,
//                    inclusive), w(s) = exp(-r^2 / (2 sigma^2)) / W, where W is the sum of
//                    exp(-r^2 / (2 sigma^2)) over those same samples: the weights are
//                    normalised to sum to 1 over the samples inside the radius, so a constant
//                    scene gives its value and the result is a weighted mean (never outside
//                    the scene's value range).
// Source: the supersampling the papers compare against — Nishita & Nakamae 1984, §2.1 (B-2.1,
// "subpixels averaged or weighted") and §4 (method D is ssaa's Gaussian with k = 3 but a square
// 5 x 5 window of the samples, without the four at r = 1, see nishita_d.cpp); Kato & Kameyama
// §2 ("Supersampling").
// box: the k = 1 case is `none` bit for bit; the error of a pixel crossed by one straight edge
// is at most 1/k (docs/methods-sampling.md, "ssaa error bound").
// gaussian: approximates the radius-1 truncated Gaussian of sigma `sigma`, the filter of
// Nishita & Nakamae's method C (§2.2.2), whose exact reference is
// "gaussian:sigma=S,radius=1". Samples on the circle r = 1 itself are counted (the test
// r^2 <= 1 is done in exact integers, in units of 1/(2k)); for odd k they are the four
// neighbour centres.
//
// 3-D scenes (a ScreenScene with depth planes; Method::own_visibility()): each sample is the
// shape nearest at it by its depth plane (a depth per sample: a multisample z-buffer,
// methods/scan/point_sampling.h); affine values are taken at the sample.
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
//   pattern grid|rgss|msaa|halton, default grid (the method as it always was, bit for bit).
//          grid: k x k regular. rgss: k x k on a grid rotated by atan(1/k), every sample in its
//          own row and column of the k^2 x k^2 sub-grid (k = 2: the classic 4x RGSS). msaa: the
//          Direct3D / Vulkan standard multisample positions, k = 2, 4, 8 or 16 samples (k is
//          the sample count here, not the side; any other k is an error); what a GPU's MSAA
//          resolve with a box filter gives for coverage, without its shading shortcuts. Both
//          show what a sample arrangement is worth against a grid of the same cost: near-
//          horizontal and near-vertical edges get k^2 (rgss) or k (msaa) coverage levels
//          instead of k. halton: the Halton (2, 3) points of indices 1..samples
//          (methods/scan/sample_patterns.h): the positions a temporal method jitters through,
//          so this is the still image it converges to.
//   samples int, default 16, range 1..64; used by pattern=halton only.
//   positions  text `X/Y;X/Y;...`, default none: any list of sample positions in [0, 1)^2 (y down
//          from the pixel's top-left corner, decimals of at most 8 digits after the point),
//          equal weights, either filter. Replaces `pattern` (giving both is an error).
//
// Cost: O(k^2 * pixels) samples (about pi k^2 weights per pixel for gaussian), plus the edge
// crossings of each sample row, found once per row (not per sample).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/point_sampling.h"
#include "methods/scan/run_sums.h"
#include "methods/scan/sample_patterns.h"

namespace aabench {
namespace {

// Sample offsets (a + 0.5)/k inside a pixel, a in [0, k).
std::vector<double> sample_offsets(int k) {
    std::vector<double> offsets(k);
    for (int a = 0; a < k; ++a) offsets[a] = (a + 0.5) / k;
    return offsets;
}

// The Gaussian variants' accumulation: sample row p feeds pixel rows p - 1 .. p + 1 only, so
// three rows of doubles suffice (not the whole image). Each pixel receives the same terms in the
// same order as with a full-image accumulator, so the result is the same bit for bit. Row j is
// complete, rounded to float32 and written out, before sample row j + 2 starts.
class AccumulatorRing {
public:
    void reset(int width) {
        width_ = width;
        rows_.assign(3 * static_cast<std::size_t>(width), 0.0);
    }
    double* row(int j) { return rows_.data() + static_cast<std::size_t>(j % 3) * width_; }
    // Before sample row p (p >= row_lo - 1) of a band whose first pixel row is row_lo:
    // writes out pixel row p - 2 and clears its slot for p + 1.
    void begin_sample_row(int p, int row_lo, Image& out) {
        if (p - 2 >= row_lo) flush(p - 2, out);
        if (p + 1 >= row_lo) std::fill(row(p + 1), row(p + 1) + width_, 0.0);
    }
    // After the last sample row (row_hi, which wrote out row row_hi - 2 and reused its slot):
    // the band's last pixel row.
    void finish(int row_hi, Image& out) {
        if (row_hi >= 1) flush(row_hi - 1, out);
    }

private:
    void flush(int j, Image& out) {
        const double* acc = row(j);
        float* dst = out.row(j);
        for (int i = 0; i < width_; ++i) dst[i] = static_cast<float>(acc[i]);
    }
    int width_ = 0;
    std::vector<double> rows_;
};

class SsaaBoxMethod : public Method {
public:
    explicit SsaaBoxMethod(int k) : k_(k), offsets_(sample_offsets(k)) {}

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        const int k = k_, width = scene.width;
        const std::vector<double>& offsets = offsets_;
        xs.resize(static_cast<std::size_t>(width) * k);
        for (int i = 0; i < width; ++i) {
            for (int a = 0; a < k; ++a) xs[static_cast<std::size_t>(i) * k + a] = i + offsets[a];
        }
        values.resize(xs.size());
        sums.resize(width);
        sampler.reset(scene);
        const double inv_count = 1.0 / (static_cast<double>(k) * k);
        if (sampler.flat()) {
            const DyadicValues dyadic = DyadicValues::of(sampler.table());
            if (dyadic.exact) return draw_rows_by_sums(dyadic, width, out, row_lo, row_hi);
            return draw_rows_by_runs(width, out, row_lo, row_hi);
        }
        for (int j = row_lo; j < row_hi; ++j) {
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
    // Flat scenes whose values are integers in one power-of-two unit (0 and 1 in the built-in
    // patterns; methods/scan/run_sums.h): the k sample rows of a pixel row taken as runs
    // between crossings, and each pixel's sum of k^2 samples counted from the run ends: a
    // change of value at sample s of a row (s in pixel p = s div k, r = s mod k samples of p
    // left of it) adds (k - r) new values to pixel p and r more to p + 1, the whole k to every
    // pixel after, which a difference array over the pixels says with two entries. The sum is
    // an integer in units of 2^exponent, the same number the per-sample sum below gives (every
    // partial sum of such values is exact in double), so the image is the same bit for bit;
    // the cost is the crossings of k lines, two additions per change and a fill per run of
    // equal pixels.
    void draw_rows_by_sums(const DyadicValues& dyadic, int width, Image& out, int row_lo,
                           int row_hi) const {
        const int k = k_;
        runs.resize(k);
        sums_by_pixel.reset(width);
        const DivideBy divide(k, xs.size());
        // sum * 2^exponent * (1/k^2) in one rounding, as sum_double * inv_count: scaling by a
        // power of two is exact (DyadicValues keeps the exponent far from the ends of double).
        const double unit = std::ldexp(1.0 / (static_cast<double>(k) * k), dyadic.exponent);
        const RowDifferences::Steps steps = sums_by_pixel.steps();
        for (int j = row_lo; j < row_hi; ++j) {
            std::int64_t first = 0;  // pixel 0's sum before the steps (the rows' first values)
            std::size_t changes = 0;
            for (int b = 0; b < k; ++b) {
                ValueRuns& row_runs = runs[b];
                sampler.sample_runs(j + offsets_[b], xs, row_runs);
                const std::vector<std::uint32_t>& starts = row_runs.starts;
                const std::vector<double>& values = row_runs.values;
                std::int64_t before = dyadic.units(values[0]);
                first += before * k;
                for (std::size_t r = 1; r < starts.size(); ++r) {
                    const std::int64_t after = dyadic.units(values[r]);
                    const std::int64_t step = after - before;
                    before = after;
                    const std::uint32_t s = starts[r];
                    const std::uint32_t p = divide(s);
                    const std::int64_t left = s - p * static_cast<std::uint32_t>(k);
                    steps.add(p, step * (k - left));
                    if (left != 0) steps.add(p + 1, step * left);  // p + 1 <= width
                }
                changes += starts.size() - 1;
            }
            // Past a change every other pixel, resolving every pixel beats searching the marks.
            const bool dense = 2 * changes > static_cast<std::size_t>(width);
            sums_by_pixel.write_row(first, dense, out.row(j), [&](std::size_t, std::int64_t sum) {
                return static_cast<float>(static_cast<double>(sum) * unit);
            });
        }
    }

    // Flat scenes with other values (constant values, no depth): the k sample rows of a pixel row are taken as
    // runs between crossings (nothing written per sample), and only the pixels where some row
    // changes value inside them or between them and their left neighbour are summed; the
    // others copy their neighbour, whose samples are the same values (point_sampling.h,
    // mark_pixels_at_starts). The sum of a pixel is the one above term by term, so the image
    // is the same bit for bit; the cost is the crossings of k lines and a copy per pixel, plus
    // k^2 additions per pixel an edge passes through, not k^2 samples walked per pixel.
    void draw_rows_by_runs(int width, Image& out, int row_lo, int row_hi) const {
        const int k = k_;
        runs.resize(k);
        marked.resize(width);
        const double inv_count = 1.0 / (static_cast<double>(k) * k);
        for (int j = row_lo; j < row_hi; ++j) {
            std::size_t changes = 0;
            for (int b = 0; b < k; ++b) {
                sampler.sample_runs(j + offsets_[b], xs, runs[b]);
                changes += runs[b].changes().size();
            }
            if (dense_changes(changes, static_cast<std::size_t>(k), width)) {
                // Every pixel summed from the values written out, as on a scene with planes.
                const std::size_t row_samples = xs.size();
                values.resize(row_samples * k);
                for (int b = 0; b < k; ++b) {
                    runs[b].write({values.data() + b * row_samples, row_samples});
                }
                float* row = out.row(j);
                for (int i = 0; i < width; ++i) {
                    double sum = 0.0;
                    for (int b = 0; b < k; ++b) {
                        const double* v = &values[b * row_samples + static_cast<std::size_t>(i) * k];
                        double row_sum = 0.0;
                        for (int a = 0; a < k; ++a) row_sum += v[a];
                        sum += row_sum;
                    }
                    row[i] = static_cast<float>(sum * inv_count);
                }
                continue;
            }
            std::fill(marked.begin(), marked.end(), 0);
            marked[0] = 1;
            for (int b = 0; b < k; ++b) mark_pixels_at_starts(runs[b].changes(), k, 0, k, marked);
            std::vector<ValueRuns>& row_runs = runs;
            write_marked_row(marked, out.row(j), [&](std::size_t i) {
                double sum = 0.0;
                for (int b = 0; b < k; ++b) {
                    const std::size_t first = i * k;
                    double row_sum = 0.0;
                    for (int a = 0; a < k; ++a) row_sum += row_runs[b].at(first + a);
                    sum += row_sum;
                }
                return static_cast<float>(sum * inv_count);
            });
        }
    }

    // Per-thread scratch (one Method may render from several threads at once), kept between
    // renders: a warm render allocates nothing.
    static thread_local std::vector<double> xs, values, sums;
    static thread_local std::vector<ValueRuns> runs;  // per sample row
    static thread_local std::vector<char> marked;
    static thread_local RowDifferences sums_by_pixel;
    static thread_local PointSampler sampler;

    int k_;
    std::vector<double> offsets_;
};

thread_local std::vector<double> SsaaBoxMethod::xs, SsaaBoxMethod::values, SsaaBoxMethod::sums;
thread_local std::vector<ValueRuns> SsaaBoxMethod::runs;
thread_local std::vector<char> SsaaBoxMethod::marked;
thread_local RowDifferences SsaaBoxMethod::sums_by_pixel;
thread_local PointSampler SsaaBoxMethod::sampler;

class SsaaGaussianMethod : public Method {
public:
    SsaaGaussianMethod(int k, double sigma) : k_(k), sigma_(sigma), offsets_(sample_offsets(k)) {
        build_weights();
    }

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        const int k = k_, width = scene.width;
        const std::vector<double>& offsets = offsets_;
        // Sample columns of pixel columns -1..width: sample (q, a) of pixel column q is at index
        // (q + 1) k + a, so the window of pixel i (window column c in [0, 3k)) starts at i k.
        const int columns = (width + 2) * k;
        thread_local std::vector<double> xs, values;
        thread_local std::vector<std::uint32_t> starts;  // sample_value_runs' (unused here)
        thread_local AccumulatorRing acc;
        thread_local PointSampler sampler;
        xs.resize(columns);
        for (int q = -1; q <= width; ++q) {
            for (int a = 0; a < k; ++a) xs[(q + 1) * k + a] = q + offsets[a];
        }
        values.resize(columns);
        acc.reset(width);
        // One pixel of margin: the border pixels' windows reach into pixel rows -1 and height.
        sampler.reset(scene, 1.0);
        // Sample rows row_lo - 1..row_hi: the pixel rows of the band and their neighbours.
        for (int p = row_lo - 1; p <= row_hi; ++p) {
            acc.begin_sample_row(p, row_lo, out);
            for (int b = 0; b < k; ++b) {
                if (sampler.flat()) {
                    sampler.sample_value_runs(p + offsets[b], xs, values, starts);
                } else {
                    sampler.sample_values(p + offsets[b], xs, values);
                }
                // This sample row is window row (p - j + 1) k + b of the pixel rows j = p-1..p+1.
                for (int j = std::max(row_lo, p - 1); j <= std::min(row_hi - 1, p + 1); ++j) {
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
        acc.finish(row_hi, out);
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
    std::vector<double> offsets_;
    std::vector<Chord> chords_;  // per window row, [0, 3k)
};

// Any sample pattern (rgss, msaa, halton, listed positions): the same two filters as the grid classes above, one sample
// row per sample (the positions need not share rows), the Gaussian's radius test in integers.
class SsaaPatternMethod : public Method {
public:
    SsaaPatternMethod(SamplePattern pattern, bool gaussian, double sigma)
        : pattern_(std::move(pattern)), gaussian_(gaussian), sigma_(sigma) {
        // Samples taken top to bottom (then left to right): each pixel row's sample lines then
        // come in ascending y, so the point sampler carries its active edge list from one to
        // the next (edge_sweep.h) instead of seeking back, which gathers and sorts the line's
        // edges afresh. The standard 8- and 16-sample patterns list their samples out of y
        // order; sorted, `ssaa:k=8,pattern=msaa` on rings at 1024^2 went from 3.5-3.9 to
        // 2.5-2.6 times the time of `ssaa:k=2` (alternating runs, one process each). The
        // order of a pattern's samples means nothing else (their sum only rounds differently).
        std::vector<std::size_t> order(pattern_.size());
        for (std::size_t s = 0; s < order.size(); ++s) order[s] = s;
        const auto& offsets = pattern_.offsets;
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return offsets[a][1] < offsets[b][1] ||
                   (offsets[a][1] == offsets[b][1] && offsets[a][0] < offsets[b][0]);
        });
        SamplePattern sorted = pattern_;
        for (std::size_t s = 0; s < order.size(); ++s) {
            sorted.offsets[s] = pattern_.offsets[order[s]];
            sorted.positions[s] = pattern_.positions[order[s]];
        }
        pattern_ = std::move(sorted);
        if (gaussian_) build_weights();
    }

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        if (gaussian_) return render_gaussian(scene, out, row_lo, row_hi);
        const int width = scene.width;
        const std::size_t n = pattern_.size();
        thread_local std::vector<double> xs, values, sums;  // per thread, kept: see SsaaBoxMethod
        thread_local std::vector<std::uint32_t> starts;
        thread_local PointSampler sampler;
        xs.resize(width);
        values.resize(width);
        sums.resize(width);
        sampler.reset(scene);
        // Flat scenes: each sample row written as runs between crossings (the same values).
        const bool runs = sampler.flat();
        for (int j = row_lo; j < row_hi; ++j) {
            std::fill(sums.begin(), sums.end(), 0.0);
            for (std::size_t s = 0; s < n; ++s) {
                for (int i = 0; i < width; ++i) xs[i] = i + pattern_.x(s);
                if (runs) {
                    sampler.sample_value_runs(j + pattern_.y(s), xs, values, starts);
                } else {
                    sampler.sample_values(j + pattern_.y(s), xs, values);
                }
                for (int i = 0; i < width; ++i) sums[i] += values[i];
            }
            float* row = out.row(j);
            for (int i = 0; i < width; ++i) row[i] = static_cast<float>(sums[i] / n);
        }
    }

private:
    // Sample s of the pixel (di, dj) away from the target pixel, for the samples within r <= 1 of
    // the target's centre: weights_[(dj + 1) * 3 + di + 1][s], 0 outside.
    void build_weights() {
        const long long d = pattern_.denominator;
        double total = 0.0;
        for (int dj = -1; dj <= 1; ++dj) {
            for (int di = -1; di <= 1; ++di) {
                std::vector<double>& w = weights_[(dj + 1) * 3 + di + 1];
                w.assign(pattern_.size(), 0.0);
                for (std::size_t s = 0; s < pattern_.size(); ++s) {
                    const long long u = pattern_.offsets[s][0] + di * d;
                    const long long v = pattern_.offsets[s][1] + dj * d;
                    if (u * u + v * v > d * d) continue;  // exact: on the circle counts
                    const double r2 =
                        static_cast<double>(u * u + v * v) / static_cast<double>(d * d);
                    w[s] = std::exp(-r2 / (2.0 * sigma_ * sigma_));
                    total += w[s];
                }
            }
        }
        for (auto& w : weights_) {
            for (double& x : w) x /= total;
        }
    }

    void render_gaussian(const Scene& scene, Image& out, int row_lo, int row_hi) const {
        const int width = scene.width;
        // Pixel columns -1..width: column q's sample at index q + 1.
        thread_local std::vector<double> xs, values;  // per thread, kept: see SsaaBoxMethod
        thread_local std::vector<std::uint32_t> starts;
        thread_local AccumulatorRing acc;
        thread_local PointSampler sampler;
        xs.resize(width + 2);
        values.resize(width + 2);
        acc.reset(width);
        sampler.reset(scene, 1.0);  // the border pixels reach one pixel out
        for (int p = row_lo - 1; p <= row_hi; ++p) {
            acc.begin_sample_row(p, row_lo, out);
            for (std::size_t s = 0; s < pattern_.size(); ++s) {
                for (int q = -1; q <= width; ++q) xs[q + 1] = q + pattern_.x(s);
                if (sampler.flat()) {
                    sampler.sample_value_runs(p + pattern_.y(s), xs, values, starts);
                } else {
                    sampler.sample_values(p + pattern_.y(s), xs, values);
                }
                for (int j = std::max(row_lo, p - 1); j <= std::min(row_hi - 1, p + 1); ++j) {
                    double* acc_row = acc.row(j);
                    for (int di = -1; di <= 1; ++di) {
                        const double w = weights_[(p - j + 1) * 3 + di + 1][s];
                        if (w == 0.0) continue;
                        for (int i = 0; i < width; ++i) acc_row[i] += w * values[i + di + 1];
                    }
                }
            }
        }
        acc.finish(row_hi, out);
    }

    SamplePattern pattern_;
    bool gaussian_;
    double sigma_;
    std::array<std::vector<double>, 9> weights_;
};

// `samples`: empty (not given) is 16; else an integer in 1..kMaxHaltonSamples.
int halton_samples(const ParamValues& p) {
    constexpr int kDefaultHaltonSamples = 16;
    const std::string& text = p.get_choice("samples");
    if (text.empty()) return kDefaultHaltonSamples;
    int n = 0;
    const bool digits = text.size() <= 2 && std::all_of(text.begin(), text.end(), [](char c) {
                            return c >= '0' && c <= '9';
                        });
    if (digits) n = std::stoi(text);
    if (!digits || n < 1 || n > kMaxHaltonSamples) {
        throw InputError(fmt::format("method 'ssaa': samples={} is not an integer in 1..{}", text,
                                     kMaxHaltonSamples));
    }
    return n;
}

std::unique_ptr<Method> make_ssaa(const ParamValues& p) {
    const int halton_n = halton_samples(p);  // checked whatever the pattern
    const bool gaussian = p.get_choice("filter") == "gaussian";
    const int k = p.get_int("k");
    const std::string& pattern = p.get_choice("pattern");
    const std::string& positions = p.get_choice("positions");
    if (!positions.empty()) {
        if (pattern != "grid") {
            throw InputError(fmt::format(
                "method 'ssaa': positions= replaces pattern={}; give one of the two", pattern));
        }
        return std::make_unique<SsaaPatternMethod>(
            parse_sample_positions(positions, "method 'ssaa'"), gaussian, p.get_real("sigma"));
    }
    if (pattern == "halton") {
        return std::make_unique<SsaaPatternMethod>(halton_pattern(halton_n), gaussian,
                                                   p.get_real("sigma"));
    }
    if (pattern == "rgss") {
        return std::make_unique<SsaaPatternMethod>(rotated_grid_pattern(k), gaussian,
                                                   p.get_real("sigma"));
    }
    if (pattern == "msaa") {
        if (std::find(kStandardMsaaCounts.begin(), kStandardMsaaCounts.end(), k) ==
            kStandardMsaaCounts.end()) {
            throw InputError(fmt::format(
                "method 'ssaa': pattern=msaa takes k = 2, 4, 8 or 16 (the standard multisample "
                "counts), not {}",
                k));
        }
        return std::make_unique<SsaaPatternMethod>(standard_msaa_pattern(k), gaussian,
                                                   p.get_real("sigma"));
    }
    if (gaussian) return std::make_unique<SsaaGaussianMethod>(k, p.get_real("sigma"));
    return std::make_unique<SsaaBoxMethod>(k);
}

}  // namespace

namespace {

// Samples per pixel and sample rows per pixel row: k^2 and k for the grid; for the patterns
// one row per sample, k^2 samples (rgss) or k (msaa: k is the sample count, not the side).
struct SsaaSampling {
    double samples = 0.0;
    double sample_rows = 0.0;
    bool grid = true;
};
SsaaSampling ssaa_sampling(const ParamValues& p) {
    const double k = p.get_int("k");
    const std::string& pattern = p.get_choice("pattern");
    if (!p.get_choice("positions").empty()) {
        const double n = static_cast<double>(
            parse_sample_positions(p.get_choice("positions"), "method 'ssaa'").size());
        return {n, n, false};
    }
    if (pattern == "halton") {
        const double n = halton_samples(p);
        return {n, n, false};
    }
    if (pattern == "msaa") return {k, k, false};
    if (pattern == "rgss") return {k * k, k * k, false};
    return {k * k, k, true};
}

}  // namespace

// What the harness knows of `ssaa` (methods/method_traits.h).
MethodTraits ssaa_traits() {
    MethodTraits t;
    t.own_visibility = true;
    t.affine_values = true;  // a depth per sample in 3-D
    t.filter = [](const ParamValues& p) {
        return p.get_choice("filter") == "gaussian" ? FilterSpec::gaussian(p.get_real("sigma"), 1.0)
                                                    : FilterSpec::box();
    };
    t.working_bytes = [](const ParamValues& p, const SceneSize& s) {
        const SsaaSampling sampling = ssaa_sampling(p);
        // Sample positions and values of one sample row (double, two pixels of margin for the
        // Gaussian): k per pixel on the grid, one per pixel for a pattern (a row per sample);
        // for the Gaussian its accumulator rows, at most a double per pixel.
        const double per_pixel = sampling.grid ? std::sqrt(sampling.samples) : 1.0;
        double bytes = memory_model::edge_table_bytes(s) + 2.0 * 8.0 * per_pixel * (s.width + 2) +
                       (sampling.grid ? 0.0 : 8.0 * s.width);  // the pattern's sums
        if (p.get_choice("filter") == "gaussian") bytes += 8.0 * s.pixels();
        return bytes;
    };
    t.time_ms = [](const ParamValues& p, const SceneSize& s) {
        using namespace cost_model;
        const SsaaSampling sampling = ssaa_sampling(p);
        // The Gaussian weighs about pi k^2 samples per pixel where the box adds k^2 (its cost
        // per sample from the operation count, not measured).
        const double weights = p.get_choice("filter") == "gaussian" ? std::numbers::pi : 1.0;
        const double cost = kSsaaFixed + kSsaaPerSampleRow * sampling.sample_rows +
                            kSsaaPerSample * sampling.samples * weights;
        const double at_default = kSsaaFixed + kSsaaPerSampleRow * 3 + kSsaaPerSample * 9;
        return linear_ms(kSsaa, s.pixels(), s.vertices) * cost / at_default;
    };
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "point sampling: a sample on an edge flips when the edge moves by any amount"},
        {Invariant::kTranslation, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "2^20 + x rounds x by up to 2^-33 px: a sample exactly on an edge flips"},
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kSamplingArea,
         "k x k samples per pixel: a pixel crossed by one edge errs by up to 1/k"},
    };
    t.hard_cases.figures = [](const ParamValues& p) {
        // The grid's 1/k is proved (docs/methods-sampling.md, "ssaa error bound"); the rotated
        // grid and the MSAA positions have no proof here, so only locality: the whole span.
        const SsaaSampling sampling = ssaa_sampling(p);
        return BoundFigures{.edge_pixel_error =
                                sampling.grid ? 1.0 / std::sqrt(sampling.samples) : 1.0};
    };
    t.hard_cases.heavy = [](const ParamValues& p) { return p.get_int("k") >= 32; };
    t.hard_cases.maximum_settings = {"k=64"};
    return t;
}

MethodInfo ssaa_method() {
    return {"ssaa",
            "supersampling, k x k samples per pixel (regular or rotated grid), the standard "
            "k-sample MSAA pattern, Halton points or listed positions, box or radius-1 Gaussian "
            "filter",
            {{"k", ParamKind::kInt, 3, 1, 64, {},
              "samples per pixel side; 3 and 5 are the reported cases, cost O(k^2)"},
             {"filter", ParamKind::kChoice, 0, 0, 0, {"box", "gaussian"},
              "box: mean of the pixel's samples; gaussian: radius-1 Gaussian over the pixel "
              "and its neighbours, weights normalised over the samples inside the radius"},
             {"sigma", ParamKind::kReal, 0.5, 0.05, 10, {},
              "Gaussian sigma in px (filter=gaussian only); 0.5 is the suite's default"},
             {"pattern", ParamKind::kChoice, 0, 0, 0, {"grid", "rgss", "msaa", "halton"},
              "grid: k x k regular; rgss: k x k rotated grid (k=2: 4x RGSS); msaa: the D3D/Vulkan "
              "standard positions, k = 2, 4, 8, 16 samples; halton: the first `samples` Halton "
              "(2,3) points"},
             // Free text (a choice without choices, params.h): left out of the spec when not
             // given, so the specs recorded before these two existed stay the same.
             {"samples", ParamKind::kChoice, 0, 0, 0, {},
              "integer 1..64, default 16: the sample count of pattern=halton (only); 16 is what "
              "a temporal jitter cycles through"},
             {"positions", ParamKind::kChoice, 0, 0, 0, {},
              "X/Y;X/Y;... sample positions in [0,1)^2, y down from the pixel's top-left corner, "
              "equal weights (replaces pattern)"}},
            make_ssaa,
            "k", {1, 2, 3, 4, 5, 8, 16}};
}

}  // namespace aabench
