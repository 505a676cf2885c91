// The ink-against-angle plot (angle_plot.h).
#include "harness/report/angle_plot.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "harness/report/svg_plot.h"

namespace aabench {
namespace {

constexpr double kWidth = 640, kHeight = 400;
constexpr double kLeft = 60, kRight = 190, kTop = 40, kBottom = 50;  // margins (legend right)
constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                    "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};

}  // namespace

std::string angle_profile_svg(const std::vector<AngleSeries>& series, const std::string& title) {
    double y_lo = 0.6, y_hi = 1.1;  // always shows 1 and cos 45° = 0.707
    for (const AngleSeries& s : series) {
        for (double v : s.profile.ink_ratio) {
            if (std::isfinite(v)) {
                y_lo = std::min(y_lo, v);
                y_hi = std::max(y_hi, v);
            }
        }
    }
    y_lo = std::floor(y_lo * 10.0) / 10.0;
    y_hi = std::ceil(y_hi * 10.0) / 10.0;
    const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
    auto px = [&](double deg) { return kLeft + deg / 45.0 * pw; };
    auto py = [&](double v) { return kTop + (y_hi - v) / (y_hi - y_lo) * ph; };
    std::string svg = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" "
        "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
        "fill=\"white\"/>\n<text x=\"{}\" y=\"22\" font-size=\"14\">{}</text>\n",
        kWidth, kHeight, kWidth, kHeight, kLeft, xml_escape(title));
    for (int deg = 0; deg <= 45; deg += 5) {
        svg += fmt::format(
            "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#eee\"/>"
            "<text x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\">{4}°</text>\n",
            px(deg), kTop, kTop + ph, kTop + ph + 16, deg);
    }
    for (double v = y_lo; v <= y_hi + 1e-9; v += 0.1) {
        svg += fmt::format(
            "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#eee\"/>"
            "<text x=\"{3:.1f}\" y=\"{4:.1f}\" text-anchor=\"end\">{5:.1f}</text>\n",
            kLeft, py(v), kLeft + pw, kLeft - 6, py(v) + 4, v);
    }
    svg += fmt::format(
        "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">angle along the circle, folded "
        "into one octant (0° axes, 45° diagonals)</text>\n"
        "<text transform=\"translate(16,{:.1f}) rotate(-90)\" text-anchor=\"middle\">ink / exact "
        "ink</text>\n",
        kLeft + pw / 2, kHeight - 12, kTop + ph / 2);
    // The exact answer and the one-unit-per-row prediction, dashed.
    std::string cos_line;
    for (int deg = 0; deg <= 45; ++deg) {
        cos_line += fmt::format("{:.1f},{:.1f} ", px(deg), py(std::cos(deg * std::numbers::pi / 180.0)));
    }
    svg += fmt::format(
        "<line class=\"exact\" x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" "
        "stroke=\"black\" stroke-dasharray=\"2,3\"/>\n<polyline class=\"cos\" points=\"{}\" "
        "fill=\"none\" stroke=\"#888\" stroke-dasharray=\"6,4\"/>\n",
        kLeft, py(1.0), kLeft + pw, py(1.0), cos_line);
    double legend_y = kTop + 10;
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" fill=\"#888\">- - cos θ (1 per row)</text>\n",
                       kLeft + pw + 12, legend_y);
    legend_y += 18;
    for (std::size_t k = 0; k < series.size(); ++k) {
        const char* colour = kColours[k % std::size(kColours)];
        std::string points;
        for (std::size_t b = 0; b < series[k].profile.angle_deg.size(); ++b) {
            const double v = series[k].profile.ink_ratio[b];
            if (!std::isfinite(v)) continue;
            points += fmt::format("{:.1f},{:.1f} ", px(series[k].profile.angle_deg[b]), py(v));
        }
        svg += fmt::format(
            "<g class=\"series\"><title>{0}</title><polyline points=\"{1}\" fill=\"none\" "
            "stroke=\"{2}\" stroke-width=\"1.5\"/></g>\n<text x=\"{3:.1f}\" y=\"{4:.1f}\" "
            "fill=\"{2}\">{5}</text>\n",
            xml_escape(series[k].method), points, colour, kLeft + pw + 12, legend_y,
            xml_escape(series[k].method.substr(0, 26)));
        legend_y += 16;
    }
    return svg + "</svg>\n";
}

}  // namespace aabench
