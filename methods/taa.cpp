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
//   - Colour. A grey scene's image is one channel (the scene's value, linear); a colour scene's
//     (Scene::channels == 3, docs/colour.md) three, linear R, G, B, each sampled from its
//     channel scene at the frame's one jitter position, and the history holds the three.
//     Karis clamps and clips in YCoCg, an axis-aligned box of the colour space; space=ycocg
//     takes YCoCg of the *linear* colour (Karis's frame is tone-mapped and gamma-encoded
//     before the resolve; here the images and the references are linear, and a transform of
//     the encoded colour would make the box and the blend non-linear in the scene's values),
//     space=rgb the linear RGB itself (methods/taa_colour_p.h). The history is fetched per
//     plane in RGB (the fetch is linear, so fetching YCoCg is the same up to rounding), taken
//     into the space with the nine current samples, rectified there, blended there (the
//     blend is linear: any space gives the same colour up to rounding; only the box differs)
//     and taken back to linear RGB planes.
//     minmax clamps each component to [min, max] of the nine. clip is Karis's clip_aabb: the
//     history moved along the segment towards the box's centre to where it leaves the box.
//     On one channel that ends on the bound the clamp gives: clip equals minmax there (kept
//     as a parameter value computed by the clip formula, so that the equality is tested, not
//     assumed). In colour it does not: a history outside in one component is clamped in that
//     component alone, but clipped in all three at once, towards the centre's hue.
//     variance (Salvi 2016) is the box mu +- gamma sigma per component, sigma the population
//     standard deviation of the nine samples, in the same space; the history is clamped to it
//     per component (on one channel, a clamp to [mu - gamma sigma, mu + gamma sigma]; Salvi's
//     slides hand the box to clip_aabb, the clip reading left for another parameter). It is
//     not intersected with [min, max] (Salvi's box replaces the min/max box), so a large
//     gamma can leave the history outside the samples' range.
//     On a colour scene whose every colour is grey (R = G = B), YCoCg is exact ((v, 0, 0) and
//     back) and each plane is the grey sequence's image bit for bit, but for weight=luma,
//     whose Rec. 709 weights sum to 1 only within a double's rounding
//     (tests/taa_colour_test.cpp).
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
//     the luma is the value itself, in colour the Rec. 709 luminance of the linear colour (not
//     YCoCg's Y, whose weights 1/4, 1/2, 1/4 are not luminance's). It damps bright outliers (flicker); on values in [0, 1] it
//     is mild.
//   - The filter approximated is the box (the running mean of samples uniformly spread over the
//     pixel is the box's Monte Carlo estimate), the own-filter reference "box".
//
// State (TaaState): the history (the last output), the current samples, and two per-pixel
// counts, all allocated by begin() (a colour sequence's three planes of each by its frame 0); the point sampler's memory grows in frame 0 and is reused
// afterwards, so a frame after the first allocates nothing (for scenes no larger than the
// first).
//
// Parameters: samples (jitter positions), alpha, history, clamp, gamma, weight, space (see the
// table).
// Cost: one point sample per pixel per frame, plus a 3 x 3 neighbourhood and a 2 x 2 (bilinear)
// or 4 x 4 (catmull) history fetch per pixel.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/sampling/point_sampling.h"
#include "methods/scan/sampling/sample_patterns.h"
#include "methods/taa_colour_p.h"

namespace aabench {
namespace {

enum class HistoryFetch { kBilinear, kCatmullRom };
enum class Rectify { kNone, kMinMax, kClip, kVariance };
enum class BoxSpace { kYCoCg, kRgb };
using taa_colour::Vec3;

struct TaaSettings {
    int samples = 8;
    double alpha = 0.1;
    bool running = false;  // alpha=running: 1 / (n + 1)
    HistoryFetch fetch = HistoryFetch::kBilinear;
    Rectify rectify = Rectify::kMinMax;
    double gamma = 1.0;
    bool luma_weight = false;
    BoxSpace space = BoxSpace::kYCoCg;  // colour scenes only
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
    // A colour sequence's history and samples, linear R, G, B: made by its frame 0 (begin()
    // does not know the channels), empty in a grey sequence.
    std::array<std::vector<float>, 3> history_rgb, current_rgb;
};

class TaaMethod : public Method {
public:
    explicit TaaMethod(const TaaSettings& settings)
        : settings_(settings), jitter_(jitter_positions(settings.samples)) {}

    std::unique_ptr<TemporalState> begin(int width, int height) const override {
        return std::make_unique<TaaState>(width, height);
    }

    void render_frame(const SceneInput& in, const MotionVectors& motion, int frame_index,
                      TemporalState* state, Image& out) const override {
        if (state == nullptr) {
            render(in, out);
            return;
        }
        const Scene& scene = in.scene();
        TaaState& s = frame_state(scene, out.width, out.height, motion, *state);
        const std::array<double, 2>& jitter = jitter_[frame_index % jitter_.size()];
        sample_frame(scene, jitter, s, s.current);
        if (frame_index == 0) {
            std::copy(s.current.begin(), s.current.end(), out.data.begin());
            std::fill(s.next_count.begin(), s.next_count.end(), 1u);
        } else {
            for (int y = 0; y < s.height; ++y) resolve_row(s, motion, y, out);
        }
        std::copy(out.data.begin(), out.data.end(), s.history.begin());
        s.count.swap(s.next_count);
    }

    // The sequence's state, checked against this frame: the scene in its window frame, the
    // scene, the output and the motion vectors of the sequence's size.
    static TaaState& frame_state(const Scene& scene, int out_width, int out_height,
                                 const MotionVectors& motion, TemporalState& state) {
        require_window_frame(scene, "taa");
        auto& s = dynamic_cast<TaaState&>(state);
        if (scene.width != s.width || scene.height != s.height || out_width != s.width ||
            out_height != s.height ||
            (!motion.empty() && (motion.width != s.width || motion.height != s.height))) {
            throw std::invalid_argument("taa: a frame's size differs from its sequence's");
        }
        return s;
    }

    // A colour frame: the three planes sampled at one jitter position, the history rectified
    // as one colour in settings_.space (see the readings above). A grey scene's one plane is
    // the grey frame, code and all.
    void render_frame(const SceneInput& in, const MotionVectors& motion, int frame_index,
                      TemporalState* state, ImagePlanes& out) const override {
        if (out.channels() == 1) {
            render_frame(in, motion, frame_index, state, out[0]);
            return;
        }
        if (state == nullptr) {
            render(in, out);
            return;
        }
        const Scene& scene = in.scene();
        if (out.channels() != 3) {
            throw std::invalid_argument("taa: a frame's size differs from its sequence's");
        }
        TaaState& s = frame_state(scene, out.width(), out.height(), motion, *state);
        if (s.current_rgb[0].empty()) {  // the sequence's first colour frame
            for (int c = 0; c < 3; ++c) {
                s.current_rgb[c].resize(TaaState::pixels(s.width, s.height));
                s.history_rgb[c].resize(TaaState::pixels(s.width, s.height));
            }
        }
        const std::array<double, 2>& jitter = jitter_[frame_index % jitter_.size()];
        for (int c = 0; c < 3; ++c) {
            std::optional<Scene> made;
            sample_frame(channel_input(in, c, made).scene(), jitter, s, s.current_rgb[c]);
        }
        if (frame_index == 0) {
            for (int c = 0; c < 3; ++c) {
                std::copy(s.current_rgb[c].begin(), s.current_rgb[c].end(), out[c].data.begin());
            }
            std::fill(s.next_count.begin(), s.next_count.end(), 1u);
        } else {
            for (int y = 0; y < s.height; ++y) resolve_colour_row(s, motion, y, out);
        }
        for (int c = 0; c < 3; ++c) {
            std::copy(out[c].data.begin(), out[c].data.end(), s.history_rgb[c].begin());
        }
        s.count.swap(s.next_count);
    }

protected:
    // Frame 0 without history: the samples at the first jitter position.
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
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
    void sample_frame(const Scene& scene, const std::array<double, 2>& jitter, TaaState& s,
                      std::vector<float>& samples) const {
        sample_lines(scene, 0, s.height - 1, std::span(&jitter[1], 1), s.lines);
        s.sampler.reset(scene, 0.0, s.lines);
        for (int i = 0; i < s.width; ++i) s.xs[i] = i + jitter[0];
        for (int j = 0; j < s.height; ++j) {
            s.sampler.sample_values(j + jitter[1], s.xs, s.values);
            float* row = samples.data() + static_cast<std::size_t>(j) * s.width;
            for (int i = 0; i < s.width; ++i) row[i] = static_cast<float>(s.values[i]);
        }
    }

    // The previous output at (u, v) in pixel-centre coordinates (pixel i's centre at u = i),
    // taps clamped to the image.
    double fetch_history(const TaaState& s, const std::vector<float>& history, double u,
                         double v) const {
        const int x0 = static_cast<int>(std::floor(u)), y0 = static_cast<int>(std::floor(v));
        const double fx = u - x0, fy = v - y0;
        auto tap = [&](int i, int j) {
            i = std::clamp(i, 0, s.width - 1);
            j = std::clamp(j, 0, s.height - 1);
            return static_cast<double>(history[static_cast<std::size_t>(j) * s.width + i]);
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
            const double h = rectify(s, x, y, fetch_history(s, s.history, u, v));
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

    // A linear RGB colour in the box's space and back.
    Vec3 to_space(const Vec3& rgb) const {
        return settings_.space == BoxSpace::kYCoCg ? taa_colour::to_ycocg(rgb) : rgb;
    }
    Vec3 from_space(const Vec3& colour) const {
        return settings_.space == BoxSpace::kYCoCg ? taa_colour::from_ycocg(colour) : colour;
    }
    static Vec3 current_at(const TaaState& s, std::size_t index) {
        return {s.current_rgb[0][index], s.current_rgb[1][index], s.current_rgb[2][index]};
    }

    // The history colour `h` (in the box's space) rectified against the 3 x 3 current samples
    // about (x, y) in that space: rectify() per component, but clip moves all three together.
    Vec3 rectify_colour(const TaaState& s, int x, int y, const Vec3& h) const {
        if (settings_.rectify == Rectify::kNone) return h;
        taa_colour::Box3 box{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
        Vec3 sum{}, sum_sq{};
        int n = 0;
        for (int j = std::max(0, y - 1); j <= std::min(s.height - 1, y + 1); ++j) {
            for (int i = std::max(0, x - 1); i <= std::min(s.width - 1, x + 1); ++i) {
                const Vec3 c = to_space(current_at(s, static_cast<std::size_t>(j) * s.width + i));
                for (int k = 0; k < 3; ++k) {
                    box.lo[k] = std::min(box.lo[k], c[k]);
                    box.hi[k] = std::max(box.hi[k], c[k]);
                    sum[k] += c[k];
                    sum_sq[k] += c[k] * c[k];
                }
                ++n;
            }
        }
        switch (settings_.rectify) {
            case Rectify::kMinMax:
                return taa_colour::clamp_to_box(h, box);
            case Rectify::kClip:
                return taa_colour::clip_to_box(h, box);
            case Rectify::kVariance: {
                for (int k = 0; k < 3; ++k) {
                    const double mean = sum[k] / n;
                    // Population variance, as on one channel.
                    const double sigma = std::sqrt(std::max(0.0, sum_sq[k] / n - mean * mean));
                    box.lo[k] = mean - settings_.gamma * sigma;
                    box.hi[k] = mean + settings_.gamma * sigma;
                }
                return taa_colour::clamp_to_box(h, box);
            }
            case Rectify::kNone:
                break;
        }
        return h;
    }

    // resolve_row in colour: the same reprojection, counts and weights; the blend of the two
    // colours in the box's space (the same blend in any space the transform is linear to, up
    // to rounding), converted back to linear RGB.
    void resolve_colour_row(TaaState& s, const MotionVectors& motion, int y,
                            ImagePlanes& out) const {
        for (int x = 0; x < s.width; ++x) {
            const std::size_t index = static_cast<std::size_t>(y) * s.width + x;
            const Vec3 c_rgb = current_at(s, index);
            const double dx = motion.empty() ? 0.0 : motion.dx[index];
            const double dy = motion.empty() ? 0.0 : motion.dy[index];
            const double u = x - dx, v = y - dy;
            if (!(u >= -0.5 && u < s.width - 0.5 && v >= -0.5 && v < s.height - 0.5)) {
                for (int k = 0; k < 3; ++k) out[k].row(y)[x] = static_cast<float>(c_rgb[k]);
                s.next_count[index] = 1;
                continue;
            }
            Vec3 h_rgb;
            for (int k = 0; k < 3; ++k) h_rgb[k] = fetch_history(s, s.history_rgb[k], u, v);
            const Vec3 c = to_space(c_rgb);
            const Vec3 h = rectify_colour(s, x, y, to_space(h_rgb));
            const std::uint32_t held =
                s.count[static_cast<std::size_t>(std::lround(v)) * s.width +
                        static_cast<std::size_t>(std::lround(u))];
            const double a = settings_.running ? 1.0 / (held + 1.0) : settings_.alpha;
            double w_current = a, w_history = 1.0 - a;
            if (settings_.luma_weight) {
                // Karis's weights on the luminance (Rec. 709), not on YCoCg's Y.
                w_current /= 1.0 + std::abs(luminance(c_rgb));
                w_history /= 1.0 + std::abs(luminance(from_space(h)));
            }
            Vec3 blend;
            for (int k = 0; k < 3; ++k) {
                blend[k] = (w_current * c[k] + w_history * h[k]) / (w_current + w_history);
            }
            const Vec3 o = from_space(blend);
            for (int k = 0; k < 3; ++k) out[k].row(y)[x] = static_cast<float>(o[k]);
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
    settings.space = p.get_choice("space") == "rgb" ? BoxSpace::kRgb : BoxSpace::kYCoCg;
    return std::make_unique<TaaMethod>(settings);
}

}  // namespace

// What the harness knows of `taa` (methods/method_traits.h).
MethodTraits taa_traits() {
    MethodTraits t;
    t.curves = "exact crossings of each sample row: the roots of y(t) = row, no flattening";
    t.colour = "three planes sampled per frame; the history rectified in YCoCg or RGB (space)";
    t.temporal = true;
    t.own_visibility = true;
    t.affine_values = true;  // a z-buffer per sample in 3-D, as `none`
    t.working_bytes = [](const ParamValues&, const SceneSize& s) {
        // The edge table and a row (the sampler), and a sequence's state: the history and the
        // current samples (float) and two counts (uint32) per pixel. (A colour sequence's
        // state holds three planes of each float buffer besides: 24 bytes per pixel more;
        // SceneSize carries no channels, and a spatial run keeps no state.)
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
              "towards the box centre (equals minmax on one channel only), variance: mu +- "
              "gamma sigma"},
             {"gamma", ParamKind::kReal, 1.0, 0.1, 8, {},
              "variance clipping's width in standard deviations (clamp=variance only)"},
             {"weight", ParamKind::kChoice, 0, 0, 0, {"none", "luma"},
              "luma: Karis's 1/(1+luma) weights in the blend (the value on one channel, the "
              "Rec. 709 luminance in colour)"},
             {"space", ParamKind::kChoice, 0, 0, 0, {"ycocg", "rgb"},
              "colour scenes: the space of the neighbourhood box, YCoCg of the linear colour "
              "(Karis) or linear RGB; no effect on one channel"}},
            make_taa};
}

}  // namespace aabench
