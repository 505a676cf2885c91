// ssaa on any sample pattern (rgss, msaa, halton, listed positions; methods/ssaa/ssaa.cpp says what
// it computes): one sample row per sample, box or radius-1 Gaussian.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "methods/method.h"
#include "methods/scan/sampling/point_sampling.h"
#include "methods/scan/sampling/sample_patterns.h"
#include "methods/ssaa/accumulator_ring_p.h"
#include "methods/ssaa/ssaa_p.h"

namespace aabench {
namespace {

// Any sample pattern (rgss, msaa, halton, listed positions): the same two filters as the grid
// (methods/ssaa/ssaa_grid.cpp), one sample row per sample (the positions need not share rows), the
// Gaussian's radius test in integers.
class SsaaPatternMethod : public Method {
public:
    SsaaPatternMethod(SamplePattern pattern, const Filter& filter)
        : pattern_(std::move(pattern)), filter_(filter) {
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
        for (std::size_t s = 0; s < pattern_.size(); ++s) row_offsets_.push_back(pattern_.y(s));
        if (!filter_.is_box()) build_weights();
    }

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        if (!filter_.is_box()) return render_gaussian(scene, out, row_lo, row_hi);
        const int width = scene.width;
        const std::size_t n = pattern_.size();
        thread_local std::vector<double> xs, values,
            sums;  // per thread, kept: warm renders allocate nothing
        thread_local std::vector<std::uint32_t> starts;
        thread_local PointSampler sampler;
        thread_local std::vector<double> lines;  // the sample rows: curves cross them exactly
        xs.resize(width);
        values.resize(width);
        sums.resize(width);
        sample_lines(scene, row_lo, row_hi - 1, row_offsets_, lines);
        sampler.reset(scene, 0.0, lines);
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
                    w[s] = filter_.profile_r2(r2);
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
        thread_local std::vector<double> xs,
            values;  // per thread, kept: warm renders allocate nothing
        thread_local std::vector<std::uint32_t> starts;
        thread_local SampleRowRing acc;
        thread_local PointSampler sampler;
        thread_local std::vector<double> lines;  // the sample rows: curves cross them exactly
        xs.resize(width + 2);
        values.resize(width + 2);
        acc.reset(width);
        sample_lines(scene, row_lo - 1, row_hi, row_offsets_, lines);
        sampler.reset(scene, 1.0, lines);  // the border pixels reach one pixel out
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
    std::vector<double> row_offsets_;  // pattern_.y(s) per sample: the rows' offsets in a pixel
    Filter filter_;  // the box or a radius-1 Gaussian
    std::array<std::vector<double>, 9> weights_;
};

}  // namespace

std::unique_ptr<Method> make_ssaa_pattern(SamplePattern pattern, const Filter& filter) {
    return std::make_unique<SsaaPatternMethod>(std::move(pattern), filter);
}

}  // namespace aabench
