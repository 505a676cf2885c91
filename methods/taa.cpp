// taa — temporal antialiasing: one jittered point sample per pixel per frame, blended into a
// history reprojected by the frame's motion vectors and rectified against the current frame.
//
// Sources: Karis 2014 (High-Quality Temporal Supersampling, SIGGRAPH course "Advances in
// Real-Time Rendering"): Halton (2, 3) jitter of 8 or 16 positions, exponential blend with the
// reprojected history, Catmull-Rom history fetch, neighbourhood clamping and clipping of the
// history towards the centre of the neighbourhood's box, luminance weighting of the blend;
// Yang, Liu & Salvi 2020 (A Survey of Temporal Antialiasing Techniques, Eurographics STAR): the
// same pipeline written as one formulation (sample accumulation with the exponential moving
// average, alpha = 1 / (t + 1) for the running mean of a still image; reprojection; history
// rectification by clamping, clipping or variance clipping); Salvi 2016 (An Excursion in
// Temporal Supersampling, GDC): variance clipping, the box mu +- gamma sigma of the
// neighbourhood's mean and standard deviation.
//
// Computes, for frame t of a sequence (render_frame), each pixel (x, y):
//   c      = the scene's visible value at (x + jx_t, y + jy_t) (methods/scan/sampling/point_sampling.h,
//            the tie rule of `none`), (jx_t, jy_t) the jitter position of frame t;
//   p      = (x + 0.5 - dx, y + 0.5 - dy), where the pixel's surface was in frame t - 1 (the
//            frame's motion vectors, methods/motion.h);
//   h      = the previous output fetched at p (history=bilinear|catmull), or nothing when p
//            lies outside the image (the pixel starts again from c);
//   h'     = h rectified against the 3 x 3 neighbourhood of current samples c (clamp=...);
//   out    = (1 - a) h' + a c, a = alpha, or 1 / (n + 1) with alpha=running, n the number of
//            frames the history at p holds. Frame 0 (and a pixel without history) is c.
// render() (a spatial run: any scene, any property test) is frame 0: c at the first jitter
// position, a point sampler offset from the pixel centre.
//
// Readings of what the papers leave open (each a choice made here, not a paper's statement):
//   - Jitter: samples = N takes the Halton (2, 3) points of indices 1..N (0.5, 1/3),
//     (0.25, 2/3), (0.75, 1/9), ... as positions in the pixel, frame t the point t mod N, the
//     same positions ssaa:pattern=halton,samples=N averages, so that a still sequence with
//     alpha=running converges to that ssaa exactly. Karis 2014 offsets the projection by the
//     Halton point minus 0.5 (about the pixel centre), which is the same set of positions.
//     samples = 1 is no jitter at all (the pixel centre, not the Halton point 1): then with
//     alpha = 1 taa is `none`.
//   - The image is one channel (the scene's value, linear). Karis clamps and clips in YCoCg to
//     an axis-aligned box of the colour space; on one channel the box is the interval
//     [min, max] of the 3 x 3 current samples, and clipping the history towards the box's
//     centre ends on the interval's bound the clamp gives: clip equals minmax (kept as a
//     parameter value computed by the clip formula, so that the equality is tested, not
//     assumed). Variance clipping (Salvi 2016) on one channel is a clamp to
//     [mu - gamma sigma, mu + gamma sigma], sigma the population standard deviation of the
//     nine samples; it is not intersected with [min, max] (Salvi's box replaces the min/max
//     box), so a large gamma can leave the history outside the samples' range.
//   - The neighbourhood is of the current, jittered samples (what a renderer has in the
//     frame), clipped at the image border (fewer than nine samples there), not unjittered.
//   - Reprojection takes the pixel's own motion vector; Karis 2014 takes the front-most of the
//     3 x 3 neighbours' (to keep edges of moving objects), a refinement for a depth buffer's
//     jittered vectors: the harness gives exact vectors at the pixel centre.
//   - History fetch: bilinear between the four previous outputs around p (pixel centres at
//     i + 0.5), taps outside the image clamped to the border; catmull: the separable 4 x 4
//     Catmull-Rom spline (Karis's 5-tap version is an approximation of it for hardware
//     bilinear taps), unclamped (the rectification is what bounds it). Both return the stored
//     value exactly when p is a pixel centre (an integer translation moves history exactly).
//   - A pixel whose p lies outside the image has no history; the papers leave it to the
//     renderer. Here it restarts from c, and under alpha=running its count restarts.
//   - alpha=running counts per pixel: n is the count stored at the nearest pixel to p plus one,
//     so a still sequence is the running mean of every frame and a moving one the running mean
//     since the pixel came into view. A fixed alpha blends from frame 1 on with no warm-up
//     (Karis and the survey give none): frame 1 is 0.9 of frame 0 at alpha = 0.1.
//   - weight=luma: Karis 2014's blend weighted by 1 / (1 + luma) (after Lottes), the current
//     sample by a / (1 + c) and the history by (1 - a) / (1 + h'), normalised; on one channel
//     the luma is the value itself. It damps bright outliers (flicker); on values in [0, 1] it
//     is mild.
//   - The filter approximated is the box (the running mean of samples uniformly spread over the
//     pixel is the box's Monte Carlo estimate), the own-filter reference "box".
//
// State (TaaState): the history (the last output), the current samples, and two per-pixel
// counts, all allocated by begin(); the point sampler's memory grows in frame 0 and is reused
// afterwards, so a frame after the first allocates nothing (for scenes no larger than the
// first).
//
// Parameters: samples (jitter positions), alpha, history, clamp, gamma, weight (see the table).
// Cost: one point sample per pixel per frame, plus a 3 x 3 neighbourhood and a 2 x 2 (bilinear)
// or 4 x 4 (catmull) history fetch per pixel.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/sampling/point_sampling.h"
#include "methods/scan/sampling/sample_patterns.h"

namespace aabench {
namespace {

enum class HistoryFetch { kBilinear, kCatmullRom };
enum class Rectify { kNone, kMinMax, kClip, kVariance };

struct TaaSettings {
    int samples = 8;
    double alpha = 0.1;
    bool running = false;  // alpha=running: 1 / (n + 1)
    HistoryFetch fetch = HistoryFetch::kBilinear;
    Rectify rectify = Rectify::kMinMax;
    double gamma = 1.0;
    bool luma_weight = false;
};

// Frame t's jitter is position t mod samples: the Halton (2, 3) points of indices 1..samples
// (methods/scan/sampling/sample_patterns.h, the positions of ssaa:pattern=halton), or the pixel
// centre for samples = 1 (see the readings above).
std::vector<std::array<double, 2>> jitter_positions(int samples) {
    if (samples == 1) return {{0.5, 0.5}};
    return halton_positions(samples);
}

// Catmull-Rom weights of the taps at -1, 0, 1, 2 for a fraction f in [0, 1); f = 0 gives
// exactly (0, 1, 0, 0).
std::array<double, 4> catmull_rom_weights(double f) {
    return {((-0.5 * f + 1.0) * f - 0.5) * f, (1.5 * f - 2.5) * f * f + 1.0,
            ((-1.5 * f + 2.0) * f + 0.5) * f, (0.5 * f - 0.5) * f * f};
}

class TaaState : public TemporalState {
public:
    TaaState(int width, int height)
        : width(width),
          height(height),
          history(pixels(width, height)),
          current(pixels(width, height)),
          count(pixels(width, height)),
          next_count(pixels(width, height)),
          xs(static_cast<std::size_t>(width)),
          values(static_cast<std::size_t>(width)) {}

    static std::size_t pixels(int width, int height) {
        return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    }

    int width, height;
    std::vector<float> history;  // the previous frame's output
    std::vector<float> current;  // this frame's jittered samples
    // Frames each pixel's history holds (alpha=running), and this frame's, swapped per frame.
    std::vector<std::uint32_t> count, next_count;
    std::vector<double> xs, values;  // one row of sample positions and values
    std::vector<double> lines;       // the sample rows, where curves cross exactly
    PointSampler sampler;
};

class TaaMethod : public Method {
public:
    explicit TaaMethod(const TaaSettings& settings)
        : settings_(settings), jitter_(jitter_positions(settings.samples)) {}

    std::unique_ptr<TemporalState> begin(int width, int height) const override {
        return std::make_unique<TaaState>(width, height);
    }

    // Its history is rectified in a colour space (Karis 2014), which a channel-by-channel
    // drawing would not have.
    std::string not_applicable(const Scene& scene) const override {
        return scene.channels == 3
                   ? "a colour scene: the history's colour rectification is not built yet"
                   : std::string();
    }

    void render_frame(const SceneInput& in, const MotionVectors& motion, int frame_index,
                      TemporalState* state, Image& out) const override {
        if (state == nullptr) {
            render(in, out);
            return;
        }
        const Scene& scene = in.scene();
        require_window_frame(scene, "taa");
        auto& s = dynamic_cast<TaaState&>(*state);
        if (scene.width != s.width || scene.height != s.height || out.width != s.width ||
            out.height != s.height ||
            (!motion.empty() && (motion.width != s.width || motion.height != s.height))) {
            throw std::invalid_argument("taa: a frame's size differs from its sequence's");
        }
        const std::array<double, 2>& jitter = jitter_[frame_index % jitter_.size()];
        sample_frame(scene, jitter, s);
        if (frame_index == 0) {
            std::copy(s.current.begin(), s.current.end(), out.data.begin());
            std::fill(s.next_count.begin(), s.next_count.end(), 1u);
        } else {
            for (int y = 0; y < s.height; ++y) resolve_row(s, motion, y, out);
        }
        std::copy(out.data.begin(), out.data.end(), s.history.begin());
        s.count.swap(s.next_count);
    }

protected:
    // Frame 0 without history: the samples at the first jitter position.
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        if (scene.channels == 3) {  // not applicable (not_applicable says why): no number
            for (int j = row_lo; j < row_hi; ++j) {
                std::fill_n(out.row(j), out.width, std::numeric_limits<float>::quiet_NaN());
            }
            return;
        }
        // Per-thread scratch (one Method may render from several threads at once), kept between
        // renders: a warm render allocates nothing.
        thread_local PointSampler sampler;
        thread_local std::vector<double> xs, values;
        thread_local std::vector<double> lines;  // a curve's exact crossings: its sample rows
        const std::array<double, 2>& jitter = jitter_.front();
        sample_lines(scene, row_lo, row_hi - 1, std::span(&jitter[1], 1), lines);
        sampler.reset(scene, 0.0, lines);
        xs.resize(scene.width);
        values.resize(scene.width);
        for (int i = 0; i < scene.width; ++i) xs[i] = i + jitter[0];
        for (int j = row_lo; j < row_hi; ++j) {
            sampler.sample_values(j + jitter[1], xs, values);
            float* row = out.row(j);
            for (int i = 0; i < scene.width; ++i) row[i] = static_cast<float>(values[i]);
        }
    }

private:
    void sample_frame(const Scene& scene, const std::array<double, 2>& jitter,
                      TaaState& s) const {
        sample_lines(scene, 0, s.height - 1, std::span(&jitter[1], 1), s.lines);
        s.sampler.reset(scene, 0.0, s.lines);
        for (int i = 0; i < s.width; ++i) s.xs[i] = i + jitter[0];
        for (int j = 0; j < s.height; ++j) {
            s.sampler.sample_values(j + jitter[1], s.xs, s.values);
            float* row = s.current.data() + static_cast<std::size_t>(j) * s.width;
            for (int i = 0; i < s.width; ++i) row[i] = static_cast<float>(s.values[i]);
        }
    }

    // The previous output at (u, v) in pixel-centre coordinates (pixel i's centre at u = i),
    // taps clamped to the image.
    double fetch_history(const TaaState& s, double u, double v) const {
        const int x0 = static_cast<int>(std::floor(u)), y0 = static_cast<int>(std::floor(v));
        const double fx = u - x0, fy = v - y0;
        auto tap = [&](int i, int j) {
            i = std::clamp(i, 0, s.width - 1);
            j = std::clamp(j, 0, s.height - 1);
            return static_cast<double>(s.history[static_cast<std::size_t>(j) * s.width + i]);
        };
        if (settings_.fetch == HistoryFetch::kBilinear) {
            return (1.0 - fy) * ((1.0 - fx) * tap(x0, y0) + fx * tap(x0 + 1, y0)) +
                   fy * ((1.0 - fx) * tap(x0, y0 + 1) + fx * tap(x0 + 1, y0 + 1));
        }
        const std::array<double, 4> wx = catmull_rom_weights(fx), wy = catmull_rom_weights(fy);
        double sum = 0.0;
        for (int b = 0; b < 4; ++b) {
            double row = 0.0;
            for (int a = 0; a < 4; ++a) row += wx[a] * tap(x0 - 1 + a, y0 - 1 + b);
            sum += wy[b] * row;
        }
        return sum;
    }

    // The history value rectified against the 3 x 3 current samples about (x, y).
    double rectify(const TaaState& s, int x, int y, double h) const {
        if (settings_.rectify == Rectify::kNone) return h;
        double lo = INFINITY, hi = -INFINITY, sum = 0.0, sum_sq = 0.0;
        int n = 0;
        for (int j = std::max(0, y - 1); j <= std::min(s.height - 1, y + 1); ++j) {
            for (int i = std::max(0, x - 1); i <= std::min(s.width - 1, x + 1); ++i) {
                const double c = s.current[static_cast<std::size_t>(j) * s.width + i];
                lo = std::min(lo, c);
                hi = std::max(hi, c);
                sum += c;
                sum_sq += c * c;
                ++n;
            }
        }
        switch (settings_.rectify) {
            case Rectify::kMinMax:
                return std::clamp(h, lo, hi);
            case Rectify::kClip: {
                // Karis 2014's clip: the segment from the box's centre to the history, cut at
                // the box. On one channel it ends on the bound the clamp gives.
                const double centre = 0.5 * (lo + hi), half_extent = 0.5 * (hi - lo);
                const double offset = h - centre;
                if (std::abs(offset) <= half_extent) return h;
                return centre + offset * (half_extent / std::abs(offset));
            }
            case Rectify::kVariance: {
                const double mean = sum / n;
                // Population variance; rounding can make it a hair negative on a flat patch.
                const double sigma = std::sqrt(std::max(0.0, sum_sq / n - mean * mean));
                return std::clamp(h, mean - settings_.gamma * sigma,
                                  mean + settings_.gamma * sigma);
            }
            case Rectify::kNone:
                break;
        }
        return h;
    }

    void resolve_row(TaaState& s, const MotionVectors& motion, int y, Image& out) const {
        float* out_row = out.row(y);
        for (int x = 0; x < s.width; ++x) {
            const std::size_t index = static_cast<std::size_t>(y) * s.width + x;
            const double c = s.current[index];
            const double dx = motion.empty() ? 0.0 : motion.dx[index];
            const double dy = motion.empty() ? 0.0 : motion.dy[index];
            // Where the surface was, in pixel-centre coordinates of the previous frame.
            const double u = x - dx, v = y - dy;
            if (!(u >= -0.5 && u < s.width - 0.5 && v >= -0.5 && v < s.height - 0.5)) {
                out_row[x] = static_cast<float>(c);  // no history: start again
                s.next_count[index] = 1;
                continue;
            }
            const double h = rectify(s, x, y, fetch_history(s, u, v));
            const std::uint32_t held =
                s.count[static_cast<std::size_t>(std::lround(v)) * s.width +
                        static_cast<std::size_t>(std::lround(u))];
            const double a = settings_.running ? 1.0 / (held + 1.0) : settings_.alpha;
            double w_current = a, w_history = 1.0 - a;
            if (settings_.luma_weight) {
                w_current /= 1.0 + std::abs(c);
                w_history /= 1.0 + std::abs(h);
            }
            out_row[x] = static_cast<float>((w_current * c + w_history * h) /
                                            (w_current + w_history));
            s.next_count[index] = held + 1;
        }
    }

    TaaSettings settings_;
    std::vector<std::array<double, 2>> jitter_;
};

std::unique_ptr<Method> make_taa(const ParamValues& p) {
    TaaSettings settings;
    settings.samples = p.get_int("samples");
    settings.running = p.get_choice("alpha") == "running";
    if (!settings.running) settings.alpha = p.get_real("alpha");
    settings.fetch = p.get_choice("history") == "catmull" ? HistoryFetch::kCatmullRom
                                                          : HistoryFetch::kBilinear;
    const std::string& clamp = p.get_choice("clamp");
    settings.rectify = clamp == "none"     ? Rectify::kNone
                       : clamp == "clip"     ? Rectify::kClip
                       : clamp == "variance" ? Rectify::kVariance
                                             : Rectify::kMinMax;
    settings.gamma = p.get_real("gamma");
    settings.luma_weight = p.get_choice("weight") == "luma";
    return std::make_unique<TaaMethod>(settings);
}

}  // namespace

// What the harness knows of `taa` (methods/method_traits.h).
MethodTraits taa_traits() {
    MethodTraits t;
    t.curves = "exact crossings of each sample row: the roots of y(t) = row, no flattening";
    t.temporal = true;
    t.own_visibility = true;
    t.affine_values = true;  // a z-buffer per sample in 3-D, as `none`
    t.working_bytes = [](const ParamValues&, const SceneSize& s) {
        // The edge table and a row (the sampler), and a sequence's state: the history and the
        // current samples (float) and two counts (uint32) per pixel.
        return memory_model::edge_table_and_rows_bytes(s, 3.0) + 16.0 * s.pixels();
    };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        // render() is one point sample per pixel, `none`'s work.
        return cost_model::linear_ms(cost_model::kNone, s.pixels(), s.vertices);
    };
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "point sampling: a sample on an edge flips when the edge moves by any amount"},
        {Invariant::kTranslation, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "2^20 + x rounds x by up to 2^-33 px: a sample exactly on an edge flips"},
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kSamplingArea,
         "one sample per pixel and frame: area is conserved only on average"},
    };
    // A single frame is one sample: a pixel crossed by one edge errs by up to the whole span.
    t.hard_cases.figures = [](const ParamValues&) { return BoundFigures{.edge_pixel_error = 1.0}; };
    return t;
}

MethodInfo taa_method() {
    return {"taa",
            "temporal antialiasing (Karis 2014): one Halton-jittered sample per pixel and frame, "
            "blended into the reprojected, rectified history",
            {{"samples", ParamKind::kInt, 8, 1, 64, {},
              "jitter positions, the Halton (2,3) points 1..N (8 and 16 are Karis's); 1: no "
              "jitter (the pixel centre)"},
             {"alpha", ParamKind::kReal, 0.1, 0.001, 1, {"running"},
              "weight of the current frame in the blend; running: 1/(n+1), the running mean"},
             {"history", ParamKind::kChoice, 0, 0, 0, {"bilinear", "catmull"},
              "history fetch at the reprojected position: bilinear or 4x4 Catmull-Rom"},
             {"clamp", ParamKind::kChoice, 0, 0, 0, {"minmax", "none", "clip", "variance"},
              "history rectification on the 3x3 current samples: min/max clamp, none, clip "
              "towards the centre (equals minmax on one channel), variance: mu +- gamma sigma"},
             {"gamma", ParamKind::kReal, 1.0, 0.1, 8, {},
              "variance clipping's width in standard deviations (clamp=variance only)"},
             {"weight", ParamKind::kChoice, 0, 0, 0, {"none", "luma"},
              "luma: Karis's 1/(1+luma) weights in the blend (the value on one channel)"}},
            make_taa};
}

}  // namespace aabench
