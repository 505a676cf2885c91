// The edge stage: seed 002's operators and corrections on the depth image, with OpenCV.
//
// Neighbours are named as in the paper's Fig. 4 (A B C / D X E / F G H: A above left, H below
// right). cv::filter2D correlates (dst(x, y) = sum k(i, j) src(x + i - 1, y + j - 1)), so each
// kernel below is written as the paper writes its sum, top row first:
//     eq. 3  g = (|A + 2B + C - F - 2G - H| + |C + 2E + H - A - 2D - F|) / 8
//     eq. 4  g = (|A + B + C - F - G - H| + |C + E + H - A - D - F|) / 6
//     eq. 5  l = 4X - B - D - E - G
//     eq. 6  l = (8X - A - B - C - D - E - F - G - H) / 3
// The divisors make g the surface slope on a plane and |l| = 2 where two planes at 45 degrees
// to the screen meet at a right angle (the paper's normalisation). With z_s = f^2 / z_v larger
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

// The depth image with a one-pixel frame continued linearly (an image 1 pixel wide or high
// repeats its pixel that way instead: there is no slope to continue).
cv::Mat continued(const cv::Mat& z) {
    const int w = z.cols, h = z.rows;
    cv::Mat p(h + 2, w + 2, CV_32F);
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
    return p;
}

// Correlation of the continued image with a 3x3 kernel, cropped back to the image.
cv::Mat correlate(const cv::Mat& padded, const cv::Mat& kernel) {
    cv::Mat dst;
    cv::filter2D(padded, dst, CV_32F, kernel, cv::Point(-1, -1), 0.0, cv::BORDER_REPLICATE);
    return dst(cv::Rect(1, 1, padded.cols - 2, padded.rows - 2)).clone();
}

// eq. 3 / eq. 4: the sum of the absolute vertical and horizontal differences, normalised.
void first_derivative(const cv::Mat& depth, const std::string& op, cv::Mat& g) {
    const float c = op == "sobel" ? 2.0f : 1.0f;        // the centre weight of each side
    const float norm = op == "sobel" ? 8.0f : 6.0f;     // 2 (1 + c + 1)
    const cv::Mat top_minus_bottom =
        (cv::Mat_<float>(3, 3) << 1, c, 1, 0, 0, 0, -1, -c, -1) / norm;
    const cv::Mat right_minus_left =
        (cv::Mat_<float>(3, 3) << -1, 0, 1, -c, 0, c, -1, 0, 1) / norm;
    g = cv::abs(correlate(depth, top_minus_bottom)) + cv::abs(correlate(depth, right_minus_left));
}

// eq. 5 / eq. 6.
void second_derivative(const cv::Mat& depth, const std::string& op, cv::Mat& l) {
    if (op == "none") {
        l = cv::Mat::zeros(depth.rows - 2, depth.cols - 2, CV_32F);
        return;
    }
    const cv::Mat kernel =
        op == "laplacian4"
            ? cv::Mat((cv::Mat_<float>(3, 3) << 0, -1, 0, -1, 4, -1, 0, -1, 0))
            : cv::Mat((cv::Mat_<float>(3, 3) << -1, -1, -1, -1, 8, -1, -1, -1, -1) / 3.0f);
    l = correlate(depth, kernel);
}

float clamp01(float v) { return std::clamp(v, 0.0f, 1.0f); }

}  // namespace

EdgeImages enhance_edges(const Image& depth, const Image& shaded, const EdgesSpec& spec) {
    if (shaded.width != depth.width || shaded.height != depth.height) {
        throw InputError(fmt::format("edge stage: the shaded image is {}x{}, the depth image {}x{}",
                                     shaded.width, shaded.height, depth.width, depth.height));
    }
    const int w = depth.width, h = depth.height;
    EdgeImages out{Image(w, h), Image(w, h), Image(w, h), Image(w, h), Image(w, h), Image(w, h)};
    const cv::Mat z = continued(as_mat(depth));
    cv::Mat g, l, g_max, g_min;
    first_derivative(z, spec.contour, g);
    second_derivative(z, spec.crease, l);
    const cv::Mat box3 = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3));
    cv::dilate(g, g_max, box3, cv::Point(-1, -1), 1, cv::BORDER_REPLICATE);
    cv::erode(g, g_min, box3, cv::Point(-1, -1), 1, cv::BORDER_REPLICATE);
    g.copyTo(as_mat(out.g));
    l.copyTo(as_mat(out.l));

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
    return out;
}

}  // namespace aabench
