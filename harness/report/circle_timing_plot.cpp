// The time-per-circle plot (circle_timing_plot.h).
#include "harness/report/circle_timing_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "harness/report/svg_plot.h"

namespace aabench {
namespace {

constexpr double kWidth = 680, kHeight = 420;
constexpr double kLeft = 70, kRight = 250, kTop = 40, kBottom = 50;  // margins (legend right)
constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                    "#8c564b", "#e377c2", "#17becf"};

std::string ns_label(double ns) {
    if (ns >= 1e9) return fmt::format("{:g} s", ns / 1e9);
    if (ns >= 1e6) return fmt::format("{:g} ms", ns / 1e6);
    if (ns >= 1e3) return fmt::format("{:g} µs", ns / 1e3);
    return fmt::format("{:g} ns", ns);
}

}  // namespace

double circle_timing_slope(const CircleTimingSeries& series) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
    for (const CircleTimingPoint& p : series.points) {
        if (p.radius < 1 || !(p.ns_per_circle > 0.0)) continue;
        const double lx = std::log(p.radius), ly = std::log(p.ns_per_circle);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
        n += 1;
    }
    const double den = n * sxx - sx * sx;
    if (n < 2 || !(den > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    return (n * sxy - sx * sy) / den;
}

std::string circle_timing_svg(const std::vector<CircleTimingSeries>& series,
                              const std::string& title) {
    double x_hi = 1, y_lo = INFINITY, y_hi = 0;
    for (const CircleTimingSeries& s : series) {
        for (const CircleTimingPoint& p : s.points) {
            if (p.radius < 1 || !(p.ns_per_circle > 0.0)) continue;
            x_hi = std::max<double>(x_hi, p.radius);
            y_lo = std::min(y_lo, p.ns_per_circle);
            y_hi = std::max(y_hi, p.ns_per_circle);
        }
    }
    if (!(y_hi > 0.0)) y_lo = y_hi = 1.0;
    const double dx0 = 0, dx1 = std::max(1.0, std::ceil(std::log10(x_hi)));
    const double dy0 = std::floor(std::log10(y_lo)), dy1 = std::max(dy0 + 1, std::ceil(std::log10(y_hi)));
    const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
    auto px = [&](double r) { return kLeft + (std::log10(r) - dx0) / (dx1 - dx0) * pw; };
    auto py = [&](double ns) { return kTop + (dy1 - std::log10(ns)) / (dy1 - dy0) * ph; };
    std::string svg = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" "
        "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
        "fill=\"white\"/>\n<text x=\"{}\" y=\"22\" font-size=\"14\">{}</text>\n",
        kWidth, kHeight, kWidth, kHeight, kLeft, xml_escape(title));
    for (double d = dx0; d <= dx1 + 1e-9; d += 1) {
        const double r = std::pow(10.0, d);
        svg += fmt::format(
            "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#eee\"/>"
            "<text x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\">{4:g}</text>\n",
            px(r), kTop, kTop + ph, kTop + ph + 16, r);
    }
    for (double d = dy0; d <= dy1 + 1e-9; d += 1) {
        const double ns = std::pow(10.0, d);
        svg += fmt::format(
            "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#eee\"/>"
            "<text x=\"{3:.1f}\" y=\"{4:.1f}\" text-anchor=\"end\">{5}</text>\n",
            kLeft, py(ns), kLeft + pw, kLeft - 6, py(ns) + 4, ns_label(ns));
    }
    svg += fmt::format(
        "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">radius (px), log</text>\n"
        "<text transform=\"translate(16,{:.1f}) rotate(-90)\" text-anchor=\"middle\">time per "
        "circle, log</text>\n",
        kLeft + pw / 2, kHeight - 12, kTop + ph / 2);
    double legend_y = kTop + 10;
    for (std::size_t k = 0; k < series.size(); ++k) {
        const char* colour = kColours[k % std::size(kColours)];
        std::string points, marks;
        for (const CircleTimingPoint& p : series[k].points) {
            if (p.radius < 1 || !(p.ns_per_circle > 0.0)) continue;
            points += fmt::format("{:.1f},{:.1f} ", px(p.radius), py(p.ns_per_circle));
            marks += fmt::format(
                "<circle class=\"point\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3\" fill=\"{}\">"
                "<title>r = {}: {}</title></circle>",
                px(p.radius), py(p.ns_per_circle), colour, p.radius, ns_label(p.ns_per_circle));
        }
        const double slope = circle_timing_slope(series[k]);
        std::string label = series[k].variant;
        if (std::isfinite(slope)) label += fmt::format("  slope {:.2f}", slope);
        if (series[k].table_bytes > 0) {
            label += fmt::format("  table {:.2f} MiB", series[k].table_bytes / (1024.0 * 1024.0));
        }
        svg += fmt::format(
            "<g class=\"series\"><title>{0}</title><polyline points=\"{1}\" fill=\"none\" "
            "stroke=\"{2}\" stroke-width=\"1.5\"/>{3}</g>\n<text x=\"{4:.1f}\" y=\"{5:.1f}\" "
            "fill=\"{2}\">{6}</text>\n",
            xml_escape(series[k].variant), points, colour, marks, kLeft + pw + 12, legend_y,
            xml_escape(label));
        legend_y += 16;
    }
    return svg + "</svg>\n";
}

}  // namespace aabench
