#include "harness/measure/metrics.h"

#include <cmath>
#include <stdexcept>

#include <opencv2/core.hpp>

namespace aabench {

ErrorStats compare_to_reference(const Image& rendered, const Coverage& reference) {
    if (rendered.width != reference.width || rendered.height != reference.height) {
        throw std::invalid_argument("compare_to_reference: image sizes differ");
    }
    ErrorStats stats;
    // Wrap the buffers without copying; all sums run in double (CV_64F) so that float32
    // rounding of a long sum never shows in the figures.
    const cv::Mat rendered_f(rendered.height, rendered.width, CV_32F,
                             const_cast<float*>(rendered.data.data()));
    const cv::Mat ref(reference.height, reference.width, CV_64F,
                      const_cast<double*>(reference.data.data()));
    cv::Mat rendered_d;
    rendered_f.convertTo(rendered_d, CV_64F);
    for (float v : rendered.data) stats.nonfinite += std::isfinite(v) ? 0 : 1;

    const cv::Mat diff = rendered_d - ref;
    const double pixels = static_cast<double>(diff.total());
    stats.rmse = cv::norm(diff, cv::NORM_L2) / std::sqrt(pixels);
    stats.bias = cv::mean(diff)[0];
    const cv::Mat abs_diff = cv::abs(diff);
    cv::Point max_loc;
    cv::minMaxLoc(abs_diff, nullptr, &stats.max_abs, nullptr, &max_loc);
    stats.max_x = max_loc.x;
    stats.max_y = max_loc.y;
    if (stats.nonfinite > 0) {
        // minMaxLoc skips NaN; a NaN pixel must never look like a small error.
        stats.max_abs = stats.rmse = stats.bias = std::numeric_limits<double>::quiet_NaN();
    }

    const cv::Mat candidates = ref > kDropoutCoverage;
    const cv::Mat dropped = candidates & (rendered_d < kDropoutRendered);
    stats.dropout_candidates = cv::countNonZero(candidates);
    stats.dropout_pixels = cv::countNonZero(dropped);
    stats.dropout = stats.dropout_candidates > 0
                        ? static_cast<double>(stats.dropout_pixels) / stats.dropout_candidates
                        : 0.0;
    return stats;
}

}  // namespace aabench
