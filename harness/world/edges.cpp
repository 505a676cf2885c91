// The edge stage: Saito & Takahashi 1990's operators and corrections on the depth image, with
// OpenCV. Its intermediate images are per-thread buffers reused between calls (edges.h).
//
// Neighbours are named as in the paper's Fig. 4 (A B C / D X E / F G H: A above left, H below
// right). cv::filter2D correlates (dst(x, y) = sum k(i, j) src(x + i - 1, y + j - 1)), so each
// kernel below is written as the paper writes its sum, top row first:
//     eq. 3  g = (|A + 2B + C - F - 2G - H| + |C + 2E + H - A - 2D - F|) / 8
//     eq. 4  g = (|A + B + C - F - G - H| + |C + E + H - A - D - F|) / 6
//     eq. 5  l = 4X - B - D - E - G
//     eq. 6  l = (8X - A - B - C - D - E - F - G - H) / 3
// The divisors make g the surface slope on a plane and |l| = 2 where two planes at 45 degrees
// to the screen meet at a right angle (the paper's normalisation). With z_s = f d / z_v larger
// means nearer, so a convex crease is a ridge of z_s and l > 0 there.
//     eq. 7  p = (g - g_min) / max(g_max - g_min, k_p)
//     eq. 8  e = l                        when g_max <= k_l,
//            e = l / (g_max / k_l)^2      otherwise (contours, where g is large, fade from l)
// g_max and g_min are the 3x3 local maximum and minimum of g (cv::dilate / cv::erode with a
// 3x3 rectangle, over the pixels that exist). Past the frame the depth image is continued
// linearly (z(-1) = 2 z(0) - z(1), rows then columns): a plane cut by the frame continues as
// itself, so the frame is neither a contour nor a crease (repeating the border pixel would make
// every slanted face crease along the frame).
//
// Compositing (§3.4 leaves the combination open; our reading, written down in docs/edges.md):
//     "black" (Fig. 3 h'):  L = clamp(w_c p + w_k |e|, 0, 1),   composite = shaded (1 - L)
//     "white-convex" (h):   D = clamp(w_c p + w_k max(0, -e), 0, 1),  W = clamp(w_k max(0, e), 0, 1)
//                           composite = s + (1 - s) W with s = shaded (1 - D); lines = W - D
// with w_c = contour_weight, w_k = crease_weight.
#include "harness/world/edges.h"

#include "patterns/scene/scene.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

namespace aabench {
namespace {

// A view of an Image as a CV_32F matrix (no copy; the Image must outlive it).
cv::Mat as_mat(Image& image) {
    return cv::Mat(image.height, image.width, CV_32F, image.data.data());
}
cv::Mat as_mat(const Image& image) {
    return cv::Mat(image.height, image.width, CV_32F, const_cast<float*>(image.data.data()));
}

// The stage's intermediate images, kept per thread between calls (edges.h: fresh full-size
// buffers cost more in page faults than the filtering). cv::Mat::create keeps a buffer whose
// size and type already match, and cv::filter2D / dilate / erode create their dst that way.
struct Scratch {
    cv::Mat padded;        // the depth image continued one pixel past the frame
    cv::Mat first, second; // a 3x3 correlation of `padded`, (h + 2) x (w + 2)
    cv::Mat g_max, g_min;  // g's 3x3 local maximum and minimum, h x w
};
Scratch& scratch() {
    thread_local Scratch s;
    return s;
}

// Writes the depth image with a one-pixel frame continued linearly into `p` (an image 1 pixel
// wide or high repeats its pixel that way instead: there is no slope to continue).
void continue_past_frame(const cv::Mat& z, cv::Mat& p) {
    const int w = z.cols, h = z.rows;
    p.create(h + 2, w + 2, CV_32F);
    z.copyTo(p(cv::Rect(1, 1, w, h)));
    for (int r = 1; r <= h; ++r) {
        float* row = p.ptr<float>(r);
        row[0] = w >= 2 ? 2 * row[1] - row[2] : row[1];
        row[w + 1] = w >= 2 ? 2 * row[w] - row[w - 1] : row[w];
    }
    for (int c = 0; c < w + 2; ++c) {
        p.at<float>(0, c) = h >= 2 ? 2 * p.at<float>(1, c) - p.at<float>(2, c) : p.at<float>(1, c);
        p.at<float>(h + 1, c) =
            h >= 2 ? 2 * p.at<float>(h, c) - p.at<float>(h - 1, c) : p.at<float>(h, c);
    }
}

// Correlation of the continued image with a 3x3 kernel into `dst` ((h + 2) x (w + 2)); the
// image's own pixels are dst's interior (the frame's are not used). The whole padded image is
// filtered, as before the buffers were kept, so that every pixel takes the same code path in
// OpenCV (vector body or scalar tail) and the results stay bit-identical.
void correlate(const cv::Mat& padded, const cv::Mat& kernel, cv::Mat& dst) {
    cv::filter2D(padded, dst, CV_32F, kernel, cv::Point(-1, -1), 0.0, cv::BORDER_REPLICATE);
}

cv::Mat interior(const cv::Mat& padded) {
    return padded(cv::Rect(1, 1, padded.cols - 2, padded.rows - 2));
}

// eq. 3 / eq. 4: the sum of the absolute vertical and horizontal differences, normalised.
void first_derivative(const cv::Mat& depth, const std::string& op, Scratch& s, cv::Mat& g) {
    const float c = op == "sobel" ? 2.0f : 1.0f;        // the centre weight of each side
    const float norm = op == "sobel" ? 8.0f : 6.0f;     // 2 (1 + c + 1)
    const cv::Mat top_minus_bottom =
        (cv::Mat_<float>(3, 3) << 1, c, 1, 0, 0, 0, -1, -c, -1) / norm;
    const cv::Mat right_minus_left =
        (cv::Mat_<float>(3, 3) << -1, 0, 1, -c, 0, c, -1, 0, 1) / norm;
    correlate(depth, top_minus_bottom, s.first);
    correlate(depth, right_minus_left, s.second);
    const cv::Mat a = interior(s.first), b = interior(s.second);
    for (int y = 0; y < g.rows; ++y) {
        const float* ar = a.ptr<float>(y);
        const float* br = b.ptr<float>(y);
        float* gr = g.ptr<float>(y);
        for (int x = 0; x < g.cols; ++x) gr[x] = std::abs(ar[x]) + std::abs(br[x]);
    }
}

// eq. 5 / eq. 6.
void second_derivative(const cv::Mat& depth, const std::string& op, Scratch& s, cv::Mat& l) {
    if (op == "none") {
        l.setTo(0.0f);
        return;
    }
    const cv::Mat kernel =
        op == "laplacian4"
            ? cv::Mat((cv::Mat_<float>(3, 3) << 0, -1, 0, -1, 4, -1, 0, -1, 0))
            : cv::Mat((cv::Mat_<float>(3, 3) << -1, -1, -1, -1, 8, -1, -1, -1, -1) / 3.0f);
    correlate(depth, kernel, s.first);
    interior(s.first).copyTo(l);
}

float clamp01(float v) { return std::clamp(v, 0.0f, 1.0f); }

// `image` with the size w x h, its buffer kept when it has it.
void fit(Image& image, int w, int h) {
    if (image.width != w || image.height != h || image.data.size() != std::size_t(w) * h) {
        image = Image(w, h);
    }
}

}  // namespace

EdgeImages enhance_edges(const Image& depth, const Image& shaded, const EdgesSpec& spec) {
    EdgeImages out;
    enhance_edges(depth, shaded, spec, out);
    return out;
}

void enhance_edges(const Image& depth, const Image& shaded, const EdgesSpec& spec,
                   EdgeImages& out) {
    if (shaded.width != depth.width || shaded.height != depth.height) {
        throw InputError(fmt::format("edge stage: the shaded image is {}x{}, the depth image {}x{}",
                                     shaded.width, shaded.height, depth.width, depth.height));
    }
    const int w = depth.width, h = depth.height;
    for (Image* image : {&out.g, &out.l, &out.p, &out.e, &out.lines, &out.composite}) {
        fit(*image, w, h);
    }
    Scratch& buffers = scratch();
    continue_past_frame(as_mat(depth), buffers.padded);
    cv::Mat g = as_mat(out.g), l = as_mat(out.l);  // views: written in place
    first_derivative(buffers.padded, spec.contour, buffers, g);
    second_derivative(buffers.padded, spec.crease, buffers, l);
    const cv::Mat box3 = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3));
    cv::dilate(g, buffers.g_max, box3, cv::Point(-1, -1), 1, cv::BORDER_REPLICATE);
    cv::erode(g, buffers.g_min, box3, cv::Point(-1, -1), 1, cv::BORDER_REPLICATE);
    const cv::Mat& g_max = buffers.g_max;
    const cv::Mat& g_min = buffers.g_min;

    const float kp = static_cast<float>(spec.kp), kl = static_cast<float>(spec.kl);
    const float wc = static_cast<float>(spec.contour_weight);
    const float wk = static_cast<float>(spec.crease_weight);
    const bool black = spec.style == "black";
    for (int y = 0; y < h; ++y) {
        const float* gr = g.ptr<float>(y);
        const float* lr = l.ptr<float>(y);
        const float* hi = g_max.ptr<float>(y);
        const float* lo = g_min.ptr<float>(y);
        for (int x = 0; x < w; ++x) {
            const float p = (gr[x] - lo[x]) / std::max(hi[x] - lo[x], kp);   // eq. 7
            const float ratio = hi[x] / kl;
            const float e = hi[x] <= kl ? lr[x] : lr[x] / (ratio * ratio);  // eq. 8
            const float s = shaded.at(x, y);
            out.p.at(x, y) = p;
            out.e.at(x, y) = e;
            if (black) {
                const float dark = clamp01(wc * p + wk * std::abs(e));
                out.lines.at(x, y) = dark;
                out.composite.at(x, y) = s * (1.0f - dark);
            } else {
                const float dark = clamp01(wc * p + wk * std::max(0.0f, -e));
                const float light = clamp01(wk * std::max(0.0f, e));
                const float darkened = s * (1.0f - dark);
                out.lines.at(x, y) = light - dark;
                out.composite.at(x, y) = darkened + (1.0f - darkened) * light;
            }
        }
    }
}

}  // namespace aabench
