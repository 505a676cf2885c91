// ssaa on the k x k grid (methods/ssaa/ssaa.cpp says what it computes): the box filter, summed on
// flat scenes from the run ends of the k sample rows (methods/scan/sampling/run_sums.h) or from
// runs and cursors, per sample elsewhere; and the Gaussian, weighted per sample into three
// accumulation rows (methods/ssaa/accumulator_ring_p.h).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "methods/method.h"
#include "methods/scan/kernel/channel_values.h"
#include "methods/scan/sampling/point_sampling.h"
#include "methods/scan/sampling/run_sums.h"
#include "methods/ssaa/accumulator_ring_p.h"
#include "methods/ssaa/ssaa_p.h"

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
    explicit SsaaBoxMethod(int k) : k_(k), offsets_(sample_offsets(k)) {}

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        const int k = k_, width = scene.width;
        const std::vector<double>& offsets = offsets_;
        sample_xs(width);
        values.resize(xs.size());
        sums.resize(width);
        if (row_lo >= row_hi) return;  // no row: no line to sample
        // Only the edges that a sample row y = j + (b + 0.5)/k meets (EdgeTable's LineGrid with
        // the rows' own offsets, so a line is the one sampled bit for bit): a polygonised
        // circle's edges lie mostly between two of them.
        sampler.reset(scene, LineGrid{0.0, k, row_lo, row_hi - 1, offsets});
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

    // A flat colour scene: the k sample rows of a pixel row as runs of the shape each sample
    // sees (PointSampler::sample_top_runs), every pixel a run starts in or next to summed as
    // draw_rows_by_runs sums it, with each sample's colour for its value, the others copying
    // their left neighbour. Plane c is channel c's grey image bit for bit: whichever of the
    // three grey paths that channel takes (run sums, runs, per sample), its pixels are the sums
    // of the same sample values in the same order (run_sums.h, draw_rows_by_runs), and a pixel
    // marked here that the channel's runs would not mark has the samples of its left neighbour.
    // Scenes with depth or value planes are drawn per channel.
    void draw_colour_rows(const SceneInput& in, ImagePlanes& out, int row_lo,
                          int row_hi) const override {
        const Scene& scene = in.scene();
        const int k = k_, width = scene.width;
        if (width <= 0) return;  // no sample to take (a sample row needs one)
        sample_xs(width);
        sampler.reset(scene, LineGrid{0.0, k, row_lo, row_hi - 1, offsets_});
        if (!sampler.flat()) {
            Method::draw_colour_rows(in, out, row_lo, row_hi);
            return;
        }
        palette.resize(scene.shapes.size() + 1);  // entry 0 the background, k + 1 shape k
        palette[0] = {channel_background(scene, 0), channel_background(scene, 1),
                      channel_background(scene, 2)};
        for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
            const Shape& shape = scene.shapes[s];
            palette[s + 1] = {channel_value(shape, 0), channel_value(shape, 1),
                              channel_value(shape, 2)};
        }
        top_runs.resize(k);
        marked.resize(width);
        const double inv_count = 1.0 / (static_cast<double>(k) * k);
        for (int j = row_lo; j < row_hi; ++j) {
            for (int b = 0; b < k; ++b) sampler.sample_top_runs(j + offsets_[b], xs, top_runs[b]);
            std::fill(marked.begin(), marked.end(), 0);
            marked[0] = 1;
            for (int b = 0; b < k; ++b) {
                mark_pixels_at_starts(top_runs[b].changes(), k, 0, k, marked);
            }
            std::vector<TopRuns>& row_runs = top_runs;
            const PlaneSink planes{{out[0].row(j), out[1].row(j), out[2].row(j)}};
            for_marked_runs(
                marked,
                [&](std::size_t i) {
                    ChannelValues sum;
                    for (int b = 0; b < k; ++b) {
                        const std::size_t first = i * k;
                        ChannelValues row_sum;
                        for (int a = 0; a < k; ++a) {
                            row_sum += palette[static_cast<std::size_t>(
                                row_runs[b].at(first + a) + 1)];
                        }
                        sum += row_sum;
                    }
                    return (sum * inv_count).rounded();
                },
                [&](std::size_t first, std::size_t end, const ColourPixel& pixel) {
                    planes.fill(first, end - first, pixel);
                });
        }
    }

private:
    // Sample x of every pixel's k columns, (a + 0.5)/k right of its left border.
    void sample_xs(int width) const {
        const int k = k_;
        xs.resize(static_cast<std::size_t>(width) * k);
        for (int i = 0; i < width; ++i) {
            for (int a = 0; a < k; ++a) xs[static_cast<std::size_t>(i) * k + a] = i + offsets_[a];
        }
    }

    // Flat scenes whose values are integers in one power-of-two unit (0 and 1 in the built-in
    // patterns; methods/scan/sampling/run_sums.h): the k sample rows of a pixel row taken as runs
    // between crossings, and each pixel's sum of k^2 samples counted from the run ends: a
    // change of value at sample s of a row (s in pixel p = s div k, r = s mod k samples of p
    // left of it) adds (k - r) new values to pixel p and r more to p + 1, the whole k to every
    // pixel after, which a difference array over the pixels says with two entries. The sum is
    // an integer in units of 2^exponent, the same number the per-sample sum below gives (every
    // partial sum of such values is exact in double), so the image is the same bit for bit;
    // the cost is the crossings of k lines, two additions per change and a fill per run of
    // equal pixels. Where a pixel row's k sample rows meet the same chains in the same order
    // (PointSampler::sample_rows_changes: on a grating every row), the crossings are walked
    // once for all k rows, and a crossing lying in one pixel on every row adds one pair of
    // steps: the same integers.
    void draw_rows_by_sums(const DyadicValues& dyadic, int width, Image& out, int row_lo,
                           int row_hi) const {
        const int k = k_;
        runs.resize(k);
        sums_by_pixel.reset(width);
        const DivideBy divide(k, xs.size());
        // sum * 2^exponent * (1/k^2) in one rounding, as sum_double * inv_count: scaling by a
        // power of two is exact (DyadicValues keeps the exponent far from the ends of double).
        const double unit = std::ldexp(1.0 / (static_cast<double>(k) * k), dyadic.exponent);
        const RowDifferences::Writer steps = sums_by_pixel.writer();
        row_ys.resize(k);
        for (int j = row_lo; j < row_hi; ++j) {
            std::int64_t first = 0;  // pixel 0's sum before the steps (the rows' first values)
            const auto add_step = [&](std::size_t n, double before, double after) {
                const std::int64_t step = dyadic.units(after) - dyadic.units(before);
                const auto s = static_cast<std::uint32_t>(n);
                const std::uint32_t p = divide(s);
                const std::int64_t left = s - p * static_cast<std::uint32_t>(k);
                steps.add(p, step * (k - left));
                if (left != 0) steps.add(p + 1, step * left);  // p + 1 <= width
            };
            for (int b = 0; b < k; ++b) row_ys[b] = j + offsets_[b];
            // A crossing's k rows at once (a step at sample 0 is one on `first`: the same
            // sum). Where it lies in one pixel p on every row (on a grating nearly always),
            // its steps are summed before the two cells are written.
            const auto add_rows = [&](const std::uint32_t* n, double before, double after) {
                const std::uint32_t p = divide(n[0]);
                std::int64_t lefts = 0;
                bool one_pixel = true;
                for (int b = 0; b < k; ++b) {
                    one_pixel = one_pixel && n[b] < xs.size() && divide(n[b]) == p;
                    lefts += n[b] - p * static_cast<std::uint32_t>(k);
                }
                if (!one_pixel) {
                    for (int b = 0; b < k; ++b) {
                        if (n[b] < xs.size()) add_step(n[b], before, after);
                    }
                    return;
                }
                const std::int64_t step = dyadic.units(after) - dyadic.units(before);
                steps.add(p, step * (static_cast<std::int64_t>(k) * k - lefts));
                if (lefts != 0) steps.add(p + 1, step * lefts);  // p + 1 <= width
            };
            // The k sample rows in one pass over the active edges when they meet the same
            // chains in the same order.
            double start = 0.0;
            if (sampler.sample_rows_changes(row_ys, xs, start, add_rows)) {
                first = dyadic.units(start) * k * k;
            } else {
                for (int b = 0; b < k; ++b) {
                    const double first_value = sampler.sample_changes(row_ys[b], xs, add_step);
                    first += dyadic.units(first_value) * k;
                }
            }
            sums_by_pixel.resolve_and_clear(first, out.row(j), [&](std::size_t, std::int64_t sum) {
                return static_cast<float>(static_cast<double>(sum) * unit);
            });
        }
    }

    // Flat scenes with other values (constant values, no depth): the k sample rows of a pixel row
    // are taken as runs between crossings (nothing written per sample), and only the pixels where
    // some row changes value inside them or between them and their left neighbour are summed; the
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
                        const double* v =
                            &values[b * row_samples + static_cast<std::size_t>(i) * k];
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
    static thread_local std::vector<double> row_ys;   // a pixel row's sample rows
    static thread_local std::vector<ValueRuns> runs;  // per sample row
    static thread_local std::vector<TopRuns> top_runs;         // per sample row (colour)
    static thread_local std::vector<ChannelValues> palette;    // colour: background, shapes
    static thread_local std::vector<char> marked;
    static thread_local RowDifferences sums_by_pixel;
    static thread_local PointSampler sampler;

    int k_;
    std::vector<double> offsets_;
};

thread_local std::vector<double> SsaaBoxMethod::xs, SsaaBoxMethod::values, SsaaBoxMethod::sums;
thread_local std::vector<double> SsaaBoxMethod::row_ys;
thread_local std::vector<ValueRuns> SsaaBoxMethod::runs;
thread_local std::vector<TopRuns> SsaaBoxMethod::top_runs;
thread_local std::vector<ChannelValues> SsaaBoxMethod::palette;
thread_local std::vector<char> SsaaBoxMethod::marked;
thread_local RowDifferences SsaaBoxMethod::sums_by_pixel;
thread_local PointSampler SsaaBoxMethod::sampler;

class SsaaGaussianMethod : public Method {
public:
    SsaaGaussianMethod(int k, const Filter& filter)
        : k_(k), filter_(filter), offsets_(sample_offsets(k)) {
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
        thread_local SampleRowRing acc;
        thread_local PointSampler sampler;
        xs.resize(columns);
        for (int q = -1; q <= width; ++q) {
            for (int a = 0; a < k; ++a) xs[(q + 1) * k + a] = q + offsets[a];
        }
        values.resize(columns);
        acc.reset(width);
        // One pixel of margin: the border pixels' windows reach into pixel rows -1 and height.
        thread_local std::vector<double> lines;  // the sample rows: curves cross them exactly
        sample_lines(scene, row_lo - 1, row_hi, offsets, lines);
        sampler.reset(scene, 1.0, lines);
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
                const double w =
                    filter_.profile_on_lattice(static_cast<double>(u * u + v * v), 2.0 * k);
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
    Filter filter_;
    std::vector<double> offsets_;
    std::vector<Chord> chords_;  // per window row, [0, 3k)
};

}  // namespace

std::unique_ptr<Method> make_ssaa_grid_box(int k) { return std::make_unique<SsaaBoxMethod>(k); }

std::unique_ptr<Method> make_ssaa_grid_gaussian(int k, const Filter& filter) {
    return std::make_unique<SsaaGaussianMethod>(k, filter);
}

}  // namespace aabench
