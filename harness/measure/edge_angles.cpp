// Jagged edges by edge angle (harness/measure/edge_angles.h).
#include "harness/measure/edge_angles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "harness/measure/segment_band.h"
#include "harness/measure/symptoms.h"

namespace aabench {

int edge_angle_bin(Point a, Point b) {
    const double angle_deg =
        std::atan2(std::abs(b.y - a.y), std::abs(b.x - a.x)) * 180.0 / std::numbers::pi;
    // 90° itself belongs to the last bin (closed at its top).
    return std::clamp(static_cast<int>(angle_deg / kEdgeAngleBinDeg), 0, kEdgeAngleBins - 1);
}

double edge_angle_bin_centre_deg(int bin) { return (bin + 0.5) * kEdgeAngleBinDeg; }

Raster<std::int8_t> edge_angle_bins(const Scene& scene) {
    require_window_frame(scene, "edge_angle_bins");
    Raster<std::int8_t> bins(scene.width, scene.height, kNoAngleBin);
    for (const Shape& shape : scene.shapes) {
        for (const Contour& contour : shape.contours) {
            for (std::size_t k = 0; k < contour.size(); ++k) {
                const Point a = contour[k];
                const Point b = contour[(k + 1) % contour.size()];
                if (a == b) continue;  // no direction
                const auto bin = static_cast<std::int8_t>(edge_angle_bin(a, b));
                segment_band::for_each_pixel_near(
                    a, b, kEdgeBandPx, bins.width, bins.height,
                    [&](int i, int j) {
                        const std::int8_t v = bins.at(i, j);
                        return v == bin || v == kMixedAngleBins;
                    },
                    [&](int i, int j) {
                        std::int8_t& v = bins.at(i, j);
                        v = v == kNoAngleBin ? bin : kMixedAngleBins;
                    });
            }
        }
    }
    return bins;
}

EdgeAngleErrors edge_errors_by_angle(const Image& rendered, const Coverage& reference,
                                     const Raster<std::int8_t>& bins) {
    if (rendered.width != reference.width || rendered.height != reference.height ||
        bins.width != rendered.width || bins.height != rendered.height) {
        throw std::invalid_argument("edge_errors_by_angle: image sizes differ");
    }
    std::vector<double> sum(kEdgeAngleBins, 0.0);
    EdgeAngleErrors out;
    out.pixels.assign(kEdgeAngleBins, 0);
    for (std::size_t k = 0; k < bins.data.size(); ++k) {
        const int bin = bins.data[k];
        if (bin < 0) continue;
        const double e = static_cast<double>(rendered.data[k]) - reference.data[k];
        sum[bin] += e * e;  // a NaN pixel makes its bin NaN: it must never look small
        ++out.pixels[bin];
    }
    out.rmse.resize(kEdgeAngleBins);
    for (int b = 0; b < kEdgeAngleBins; ++b) {
        out.rmse[b] = out.pixels[b] > 0 ? std::sqrt(sum[b] / static_cast<double>(out.pixels[b]))
                                        : std::numeric_limits<double>::quiet_NaN();
    }
    return out;
}

}  // namespace aabench
