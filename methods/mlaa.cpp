// mlaa — Morphological Antialiasing as a post-process over a registry method's image
// (methods/post_process.h: base, bands, luma, timing).
//
// Source: A. Reshetov, "Morphological Antialiasing", High Performance Graphics 2009; written
// from the paper, no code copied. The image is read as a staircase of separation lines:
//   1. Discontinuities: between two 4-neighbours whose encoded colour differs by more than
//      `threshold` (in any channel; a grey image: its encoded value), a separation segment (one
//      pixel long) on the boundary between them.
//   2. Runs: along each boundary between two rows, the maximal runs of horizontal segments
//      (and, the same transposed, between two columns). At each end of a run, the segment that
//      turns off it (a separation between the last pixel and the next, in the row above or in
//      the row below) gives the end's side: up, down, or none (no turn, or both: a crossing).
//   3. Shapes: a run with a turn at one end only is an L: the edge is taken as the line from
//      the middle of the turning segment (half a pixel off the boundary, on its side) to the
//      run's other end (on the boundary). A run with turns at both ends is a Z (opposite sides)
//      or a U (the same side): split at the run's middle into two L's, each from its turn to
//      the middle. A run with no turn is a straight edge: nothing to blend.
//   4. Blend: each pixel beside the run takes, from the pixel across the boundary, the share of
//      its area that the reconstructed line cuts off on its side (the trapezoid or triangle
//      between the line and the boundary within the pixel). A pixel's shares from its four
//      boundaries are summed (every share is computed on the base image, so the order of the
//      boundaries does not matter), capped at 1 by scaling them down when they exceed it.
//
// Readings where the paper leaves a choice:
//   - The discontinuity test: the paper finds separation lines between neighbours whose
//     colours differ by more than a threshold; how two colours are compared is this file's
//     reading: channel by channel, not through a luma. Two neighbours are discontinuous when
//     any channel of their encoded colour (sRGB-encoded by default, space=srgb, as the other
//     passes' thresholds) differs by more than `threshold`, i.e. the largest channel
//     difference, as SMAA's colour detector takes it; so an edge between two colours of equal
//     luma is found. On a grey image the one channel is the encoded value, tested as before
//     colour. 0.1 is the value the pass is usually run with in its later GPU forms. Once the
//     separation lines are found, every channel is blended with the same shares.
//   - An L's line runs to the far end of its run (not to its middle): for a long straight edge
//     that ends, the blend fades out along the whole run.
//   - Runs are not limited in length (the paper scans whole rows): an output row may depend on
//     any base row, so in bands each band renders the whole base (reach_rows = height).
//   - The blend mixes linear values (area weights on light); a pixel with two boundaries' shares
//     above 1 (only on one-pixel-wide features) is scaled down to a convex mix.
//
// Parameters: base (none), space (srgb), threshold 0.1.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "methods/post_process.h"

namespace aabench {
namespace {

// A turn's end lies half a pixel off the boundary (the middle of a one-pixel segment).
constexpr float kTurnOffsetPx = 0.5f;

// The integral over [u, v] of max(s * h(x), 0) for the linear h through (p0, h0), (p1, h1)
// (p0 < p1, u and v inside): h keeps one sign on each piece (it runs from a turn to 0).
float area_on_side(float p0, float h0, float p1, float h1, float u, float v, float s) {
    const float slope = (h1 - h0) / (p1 - p0);
    const float hu = s * (h0 + slope * (u - p0)), hv = s * (h0 + slope * (v - p0));
    if (hu <= 0.0f && hv <= 0.0f) return 0.0f;
    return 0.5f * (std::max(hu, 0.0f) + std::max(hv, 0.0f)) * (v - u);
}

class MlaaMethod : public PostProcessMethod {
public:
    explicit MlaaMethod(const ParamValues& p)
        : PostProcessMethod(p.get_choice("base")),
          srgb_(p.get_choice("space") == "srgb"),
          threshold_(static_cast<float>(p.get_real("threshold"))) {}

    int reach_rows(int height) const override { return height; }

    void pass_rows(const Image& in, Image& out, int row_lo, int row_hi) const override {
        thread_local Image luma;  // per-thread scratch, kept: a warm pass allocates nothing
        luma_rows(in, srgb_, luma, 0, in.height);
        pass_planes<1>({&in}, {&luma}, {&out}, row_lo, row_hi);
    }

    void pass_colour_rows(const ImagePlanes& in, ImagePlanes& out, int row_lo,
                          int row_hi) const override {
        thread_local ImagePlanes encoded;  // per-thread scratch, kept
        encoded_planes_rows(in, srgb_, encoded, 0, in.height());
        pass_planes<3>({&in[0], &in[1], &in[2]}, {&encoded[0], &encoded[1], &encoded[2]},
                       {&out[0], &out[1], &out[2]}, row_lo, row_hi);
    }

private:
    // The pass on kPlanes planes: `values` blended into `out`, discontinuities found on `test`
    // (the encoded planes: a grey image's one, a colour image's three, a discontinuity where
    // any channel differs by more than the threshold). Every share is found once and applied to
    // each plane; with one plane the arithmetic is the grey pass's, in its order.
    template <int kPlanes>
    void pass_planes(const std::array<const Image*, kPlanes>& values,
                     const std::array<const Image*, kPlanes>& test,
                     const std::array<Image*, kPlanes>& out, int row_lo, int row_hi) const {
        // Per-thread scratch, kept between renders: a warm pass allocates nothing.
        // Summed shares, and per plane the summed share x other value.
        thread_local std::vector<float> share;
        thread_local std::array<std::vector<float>, kPlanes> mixed;
        thread_local std::vector<int> run_start;
        const Image& first = *values[0];
        const int w = first.width, h = first.height;
        row_lo = std::max(row_lo, 0);
        row_hi = std::min(row_hi, h);
        if (row_lo >= row_hi) return;
        share.assign(static_cast<std::size_t>(w) * h, 0.0f);
        for (std::vector<float>& m : mixed) m.assign(static_cast<std::size_t>(w) * h, 0.0f);
        // The share `a` of pixel (x, y) takes the value of pixel (ox, oy) in every plane.
        const auto add = [&](int x, int y, float a, int ox, int oy) {
            if (y < row_lo || y >= row_hi || a <= 0.0f) return;
            share[static_cast<std::size_t>(y) * w + x] += a;
            for (int c = 0; c < kPlanes; ++c) {
                mixed[c][static_cast<std::size_t>(y) * w + x] += a * values[c]->at(ox, oy);
            }
        };
        const auto differ = [&](int x0, int y0, int x1, int y1) {
            for (int c = 0; c < kPlanes; ++c) {
                if (std::abs(test[c]->at(x0, y0) - test[c]->at(x1, y1)) > threshold_) return true;
            }
            return false;
        };
        const auto hdisc = [&](int x, int b) {  // between rows b and b + 1 at column x
            return differ(x, b, x, b + 1);
        };
        const auto vdisc = [&](int a, int y) {  // between columns a and a + 1 at row y
            return differ(a, y, a + 1, y);
        };
        // Horizontal runs on the boundaries that touch the band's rows.
        for (int b = std::max(row_lo - 1, 0); b < std::min(row_hi, h - 1); ++b) {
            int x = 0;
            while (x < w) {
                if (!hdisc(x, b)) {
                    ++x;
                    continue;
                }
                const int x0 = x;
                while (x < w && hdisc(x, b)) ++x;
                // The turn at each end: a separation in row b (up, -) or row b + 1 (down, +).
                const float left = x0 > 0 ? turn(vdisc(x0 - 1, b), vdisc(x0 - 1, b + 1)) : 0.0f;
                const float right = x < w ? turn(vdisc(x - 1, b), vdisc(x - 1, b + 1)) : 0.0f;
                blend_run(x0, x, left, right, [&](int i, float first_share, float second_share) {
                    add(i, b, first_share, i, b + 1);
                    add(i, b + 1, second_share, i, b);
                });
            }
        }
        // Vertical runs, found row by row (row-major reads) for every column boundary at once;
        // a run may start above the band and end below it.
        run_start.assign(std::max(w - 1, 0), -1);
        for (int y = 0; y <= h; ++y) {
            for (int a = 0; a + 1 < w; ++a) {
                const bool d = y < h && vdisc(a, y);
                int& start = run_start[a];
                if (d && start < 0) start = y;
                if (d || start < 0) continue;
                const int y0 = start;
                start = -1;
                if (y <= row_lo || y0 >= row_hi) continue;  // run [y0, y) misses the band
                const float top = y0 > 0 ? turn(hdisc(a, y0 - 1), hdisc(a + 1, y0 - 1)) : 0.0f;
                const float bottom = y < h ? turn(hdisc(a, y - 1), hdisc(a + 1, y - 1)) : 0.0f;
                blend_run(y0, y, top, bottom, [&](int j, float first_share, float second_share) {
                    add(a, j, first_share, a + 1, j);
                    add(a + 1, j, second_share, a, j);
                });
            }
        }
        for (int c = 0; c < kPlanes; ++c) {
            for (int y = row_lo; y < row_hi; ++y) {
                const float* src = values[c]->row(y);
                float* dst = out[c]->row(y);
                const float* s = share.data() + static_cast<std::size_t>(y) * w;
                const float* m = mixed[c].data() + static_cast<std::size_t>(y) * w;
                for (int x = 0; x < w; ++x) {
                    if (s[x] <= 0.0f) {
                        dst[x] = src[x];  // untouched: exactly the base value
                    } else if (s[x] <= 1.0f) {
                        dst[x] = (1.0f - s[x]) * src[x] + m[x];
                    } else {
                        dst[x] = m[x] / s[x];  // shares above 1 scaled down to a convex mix
                    }
                }
            }
        }
    }

    // The offset of a run's end from its boundary: -0.5 (a turn into the first row or column),
    // +0.5 (into the second), 0 (no turn, or a crossing: turns on both sides).
    static float turn(bool first, bool second) {
        return first == second ? 0.0f : first ? -kTurnOffsetPx : kTurnOffsetPx;
    }

    // The shares of the pixels beside a run [p0, p1) with end offsets `h0`, `h1` (step 3): for
    // each position i, `emit(i, share of the first-side pixel, share of the second-side one)`.
    template <class Emit>
    static void blend_run(int p0, int p1, float h0, float h1, const Emit& emit) {
        if (h0 == 0.0f && h1 == 0.0f) return;  // a straight edge
        const float a = static_cast<float>(p0), b = static_cast<float>(p1);
        // Pieces: an L from its turn to the far end, or two L's meeting at the middle at 0.
        const float mid = h0 != 0.0f && h1 != 0.0f ? 0.5f * (a + b) : (h0 != 0.0f ? b : a);
        for (int i = p0; i < p1; ++i) {
            const float u = static_cast<float>(i), v = u + 1.0f;
            float first = 0.0f, second = 0.0f;
            if (h0 != 0.0f && u < mid) {  // the piece from (a, h0) to (mid, 0)
                const float vv = std::min(v, mid);
                first += area_on_side(a, h0, mid, 0.0f, u, vv, -1.0f);
                second += area_on_side(a, h0, mid, 0.0f, u, vv, 1.0f);
            }
            if (h1 != 0.0f && v > mid) {  // the piece from (mid, 0) to (b, h1)
                const float uu = std::max(u, mid);
                first += area_on_side(mid, 0.0f, b, h1, uu, v, -1.0f);
                second += area_on_side(mid, 0.0f, b, h1, uu, v, 1.0f);
            }
            emit(i, first, second);
        }
    }

    bool srgb_;
    float threshold_;
};

}  // namespace

MethodTraits mlaa_traits() {
    // The pass's estimate besides the base: its pass_ms on the star at 128^2 (0.31 ms, on a
    // loaded machine), per pixel; scratch is a luma image and two float accumulators (12 bytes
    // per pixel).
    constexpr double kPassMsPerMpixel = 20.0, kScratchBytesPerPixel = 12.0;
    return post_process_traits(kPassMsPerMpixel, kScratchBytesPerPixel);
}

MethodInfo mlaa_method() {
    return {"mlaa",
            "morphological antialiasing (Reshetov 2009): separation lines, L/Z/U shapes, "
            "area-based blend, as a pass over the base method's image",
            {post_process_base_param(),
             post_process_space_param(),
             {"threshold", ParamKind::kReal, 0.1, 0.0, 1.0, {},
              "difference of the encoded value (of any channel, in colour) that makes two "
              "neighbours a discontinuity; 0.1, as the pass is usually run (the paper fixes no "
              "value)"}},
            [](const ParamValues& p) { return std::make_unique<MlaaMethod>(p); }};
}

}  // namespace aabench
