// The cost-model plot (harness/report/cost_plot.h). Hand-written SVG, as svg_plot.cpp: both
// axes log10 over whole decades, so every axis starts and ends on a labelled tick.
#include "harness/report/cost_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "harness/report/svg_plot.h"  // xml_escape

namespace aabench {
namespace {

constexpr double kWidth = 1100.0;  // room for method specs in the legend
constexpr double kLeft = 78.0, kRight = 560.0, kTop = 48.0, kBottom = 420.0;
constexpr double kLegendX = 580.0, kLegendLineHeight = 18.0;
// The same Tableau 10 hues as the accuracy-time plot; past ten methods, dashes tell apart.
constexpr std::array<const char*, 10> kColours = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2",
                                                  "#59a14f", "#edc948", "#b07aa1", "#ff9da7",
                                                  "#9c755f", "#7f7f7f"};

bool usable(const std::pair<double, double>& p) {
    return std::isfinite(p.first) && std::isfinite(p.second) && p.first > 0.0 && p.second > 0.0;
}

struct LogAxis {
    int first = 0, last = 1;  // decades
    double pixel_lo = 0.0, pixel_hi = 1.0;
    double at(double value) const {
        return pixel_lo + (std::log10(value) - first) / (last - first) * (pixel_hi - pixel_lo);
    }
};

LogAxis make_axis(double lo, double hi, double pixel_lo, double pixel_hi) {
    // The slack keeps a value that is a decade up to rounding from opening an empty decade.
    constexpr double kDecadeSlack = 1e-9;
    LogAxis axis;
    axis.first = static_cast<int>(std::floor(std::log10(lo) + kDecadeSlack));
    axis.last = static_cast<int>(std::ceil(std::log10(hi) - kDecadeSlack));
    if (axis.last <= axis.first) axis.last = axis.first + 1;
    axis.pixel_lo = pixel_lo;
    axis.pixel_hi = pixel_hi;
    return axis;
}

std::string decade_label(int decade, bool time_ms) {
    if (!time_ms) return decade >= 0 && decade <= 4 ? fmt::format("{}", std::pow(10.0, decade))
                                                    : fmt::format("1e{}", decade);
    // Times are in ms: show the unit that keeps the number short.
    const double ms = std::pow(10.0, decade);
    if (ms >= 1000.0) return fmt::format("{} s", ms / 1000.0);
    if (ms >= 1.0) return fmt::format("{} ms", ms);
    if (ms >= 1e-3) return fmt::format("{} us", ms * 1000.0);
    return fmt::format("{} ns", ms * 1e6);
}

}  // namespace

LogLogFit fit_log_log(const std::vector<std::pair<double, double>>& points) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& p : points) {
        if (!usable(p)) continue;
        const double lx = std::log(p.first), ly = std::log(p.second);
        n += 1;
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    const double denominator = n * sxx - sx * sx;
    // Fewer than two distinct sizes: no line (written so that 0/0 also gives NaN, not a slope).
    if (!(n >= 2 && denominator > 0.0)) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {nan, nan};
    }
    const double slope = (n * sxy - sx * sy) / denominator;
    return {slope, (sy - slope * sx) / n};
}

std::string cost_model_svg(const std::vector<CostSeries>& series, const std::string& x_label,
                           const std::string& title) {
    double x_lo = std::numeric_limits<double>::infinity(), x_hi = 0.0;
    double y_lo = std::numeric_limits<double>::infinity(), y_hi = 0.0;
    for (const CostSeries& s : series) {
        for (const auto& p : s.points) {
            if (!usable(p)) continue;
            x_lo = std::min(x_lo, p.first);
            x_hi = std::max(x_hi, p.first);
            y_lo = std::min(y_lo, p.second);
            y_hi = std::max(y_hi, p.second);
        }
    }
    if (!(x_hi > 0.0)) {  // nothing to draw: empty axes
        x_lo = y_lo = 1.0;
        x_hi = y_hi = 10.0;
    }
    const LogAxis ax = make_axis(x_lo, x_hi, kLeft, kRight);
    const LogAxis ay = make_axis(y_lo, y_hi, kBottom, kTop);
    const double height =
        std::max(kBottom + 60.0, kTop + kLegendLineHeight * (series.size() + 2.0));
    std::string svg = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
        "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\" font-size=\"12\">\n"
        "<rect width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n"
        "<text x=\"{2}\" y=\"24\" font-size=\"15\">{3}</text>\n",
        kWidth, height, kLeft, xml_escape(title));
    // Grid and decade labels.
    for (int d = ax.first; d <= ax.last; ++d) {
        const double x = ax.at(std::pow(10.0, d));
        svg += fmt::format(
            "<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#ddd\"/>\n"
            "<text x=\"{0:.1f}\" y=\"{3}\" text-anchor=\"middle\">{4}</text>\n",
            x, kTop, kBottom, kBottom + 16.0, decade_label(d, false));
    }
    for (int d = ay.first; d <= ay.last; ++d) {
        const double y = ay.at(std::pow(10.0, d));
        svg += fmt::format(
            "<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" stroke=\"#ddd\"/>\n"
            "<text x=\"{3}\" y=\"{4:.1f}\" text-anchor=\"end\">{5}</text>\n",
            kLeft, y, kRight, kLeft - 6.0, y + 4.0, decade_label(d, true));
    }
    svg += fmt::format(
        "<rect x=\"{0}\" y=\"{1}\" width=\"{2}\" height=\"{3}\" fill=\"none\" stroke=\"#444\"/>\n"
        "<text x=\"{4}\" y=\"{5}\" text-anchor=\"middle\">{6} (log)</text>\n"
        "<text x=\"16\" y=\"{7}\" transform=\"rotate(-90 16 {7})\" text-anchor=\"middle\">"
        "median time of one render (log)</text>\n",
        kLeft, kTop, kRight - kLeft, kBottom - kTop, 0.5 * (kLeft + kRight), kBottom + 36.0,
        xml_escape(x_label), 0.5 * (kTop + kBottom));
    for (std::size_t k = 0; k < series.size(); ++k) {
        const CostSeries& s = series[k];
        const char* colour = kColours[k % kColours.size()];
        const char* dash = k < kColours.size() ? "" : " stroke-dasharray=\"2 2\"";
        std::vector<std::pair<double, double>> pts;
        for (const auto& p : s.points) {
            if (usable(p)) pts.push_back(p);
        }
        std::sort(pts.begin(), pts.end());
        svg += fmt::format("<g class=\"series\" data-method=\"{}\">\n", xml_escape(s.method));
        std::string line;
        for (const auto& [x, t] : pts) line += fmt::format("{:.1f},{:.1f} ", ax.at(x), ay.at(t));
        svg += fmt::format(
            "<polyline class=\"curve\" points=\"{}\" fill=\"none\" stroke=\"{}\" "
            "stroke-width=\"1.5\"{}/>\n",
            line, colour, dash);
        for (const auto& [x, t] : pts) {
            svg += fmt::format("<circle class=\"point\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3\" "
                               "fill=\"{}\"><title>{}: {:g} ms at {:g}</title></circle>\n",
                               ax.at(x), ay.at(t), colour, xml_escape(s.method), t, x);
        }
        const LogLogFit fit = fit_log_log(pts);
        std::string slope_text = "no fit";
        if (std::isfinite(fit.slope)) {
            // The fitted line across the measured range only: no extrapolation drawn.
            auto fitted = [&](double x) {
                return std::exp(fit.intercept + fit.slope * std::log(x));
            };
            const double a = pts.front().first, b = pts.back().first;
            svg += fmt::format(
                "<line class=\"fit\" x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" "
                "stroke=\"{}\" stroke-dasharray=\"6 4\" opacity=\"0.7\"/>\n",
                ax.at(a), ay.at(fitted(a)), ax.at(b), ay.at(fitted(b)), colour);
            slope_text = fmt::format("slope {:.2f}", fit.slope);
        }
        const double ly = kTop + kLegendLineHeight * (k + 0.5);
        svg += fmt::format(
            "<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" stroke=\"{3}\" "
            "stroke-width=\"2\"{4}/>\n<text x=\"{5}\" y=\"{6:.1f}\">{7}  ({8})</text>\n</g>\n",
            kLegendX, ly, kLegendX + 20.0, colour, dash, kLegendX + 26.0, ly + 4.0,
            xml_escape(s.method), slope_text);
    }
    svg += "</svg>\n";
    return svg;
}

}  // namespace aabench
