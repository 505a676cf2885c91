// Ink against angle (circle_angle.h).
#include "harness/measure/circle_angle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace aabench {

std::optional<ConcentricCurves> concentric_curves(const Scene& scene) {
    if (scene.shapes.empty()) return std::nullopt;
    ConcentricCurves out;
    bool first = true;
    for (const Shape& s : scene.shapes) {
        if (!s.circle) return std::nullopt;
        if (first) {
            out = {s.circle->center, s.circle->inner, s.circle->outer};
            first = false;
        } else if (!(s.circle->center == out.center)) {
            return std::nullopt;
        }
        out.inner = std::min(out.inner, s.circle->inner);
        out.outer = std::max(out.outer, s.circle->outer);
    }
    return out;
}

AngleProfile angle_profile(const Image& rendered, const Coverage& reference,
                           const ConcentricCurves& curves, int bins) {
    std::vector<double> ink(bins, 0.0), exact(bins, 0.0), err(bins, 0.0);
    std::vector<long long> count(bins, 0);
    const double lo = std::max(0.0, curves.inner - 1.5), hi = curves.outer + 1.5;
    for (int j = 0; j < rendered.height; ++j) {
        for (int i = 0; i < rendered.width; ++i) {
            const double dx = std::abs(i + 0.5 - curves.center.x);
            const double dy = std::abs(j + 0.5 - curves.center.y);
            const double r = std::hypot(dx, dy);
            if (r < lo || r > hi) continue;
            const double theta = std::atan2(std::min(dx, dy), std::max(dx, dy));
            const int b = std::min(bins - 1, static_cast<int>(theta / (0.25 * std::numbers::pi) * bins));
            ink[b] += rendered.at(i, j);
            exact[b] += reference.at(i, j);
            err[b] += rendered.at(i, j) - reference.at(i, j);
            ++count[b];
        }
    }
    AngleProfile p;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int b = 0; b < bins; ++b) {
        p.angle_deg.push_back((b + 0.5) * 45.0 / bins);
        p.ink_ratio.push_back(count[b] > 0 && exact[b] > 0.0 ? ink[b] / exact[b] : nan);
        p.mean_error.push_back(count[b] > 0 ? err[b] / count[b] : nan);
    }
    return p;
}

}  // namespace aabench
