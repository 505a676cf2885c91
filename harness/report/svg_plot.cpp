// The accuracy-time plot (harness/report/svg_plot.h). Hand-written SVG: no library would add
// anything but a dependency, and the elements carry classes that tests and readers can count.
//
// Geometry: both axes are log10, mapped linearly onto the plot area. The data range is widened
// to whole decades, so every axis starts and ends on a labelled tick, plus a small pad so that
// markers on a decade do not sit on the frame.
#include "harness/report/svg_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>

#include "harness/report/label_layout.h"

namespace aabench {
namespace {

// Canvas and plot area, in SVG user units (px). The legend sits right of the plot area.
constexpr double kWidth = 880.0;
constexpr double kMinHeight = 500.0;
constexpr double kLeft = 78.0;
constexpr double kRight = 610.0;
constexpr double kTop = 48.0;
constexpr double kBottom = 420.0;
constexpr double kLegendX = 630.0;
constexpr double kLegendLineHeight = 18.0;
// A twelfth of a decade of margin each side: a marker on a decade stays inside the frame.
constexpr double kPadDecades = 1.0 / 12.0;

// When the floor lies more than kMaxGapDecades below the smallest error above it, the empty
// decades between are cut out: the y axis breaks below its first decade, and the floor gets a
// band of its own, kFloorSlotDecades tall, points drawn kFloorDepthDecades below the first
// decade. Without the break, `exact` at 1e-7 would squeeze every other method into the top
// third of the plot.
constexpr double kMaxGapDecades = 2.0;
constexpr double kFloorSlotDecades = 1.0;
constexpr double kFloorDepthDecades = 0.75;
constexpr double kBreakDepthDecades = 0.35;

constexpr double kPointRadius = 3.5;
constexpr double kDefaultRadius = 6.0;
constexpr double kRingRadius = 10.0;
constexpr double kLabelFontPx = 10.0;  // the labels' <g font-size>

// Tableau 10: distinct hues of similar weight; the marker shape varies too, so that two series
// stay apart in grey print and for colour-blind readers.
constexpr std::array<const char*, 10> kColours = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2",
                                                  "#59a14f", "#edc948", "#b07aa1", "#ff9da7",
                                                  "#9c755f", "#7f7f7f"};
constexpr int kShapes = 6;

struct Axis {
    int first_decade = 0;  // log10 of the first labelled tick
    int last_decade = 1;
    double lo = 0.0;  // log10 at the start of the axis (pad included)
    double hi = 1.0;
    double pixel_lo = 0.0;  // where lo and hi land on the canvas
    double pixel_hi = 1.0;

    double to_pixel(double value) const { return log_to_pixel(std::log10(value)); }
    double log_to_pixel(double log_value) const {
        return pixel_lo + (log_value - lo) / (hi - lo) * (pixel_hi - pixel_lo);
    }
};

Axis make_axis(double min_value, double max_value, double pixel_lo, double pixel_hi) {
    Axis axis;
    // The small epsilon keeps a value that is a decade up to rounding (log10(1e-3) is not
    // exactly -3) from opening a whole empty decade.
    constexpr double kDecadeSlack = 1e-9;
    axis.first_decade = static_cast<int>(std::floor(std::log10(min_value) + kDecadeSlack));
    axis.last_decade = static_cast<int>(std::ceil(std::log10(max_value) - kDecadeSlack));
    if (axis.last_decade <= axis.first_decade) axis.last_decade = axis.first_decade + 1;
    axis.lo = axis.first_decade - kPadDecades;
    axis.hi = axis.last_decade + kPadDecades;
    axis.pixel_lo = pixel_lo;
    axis.pixel_hi = pixel_hi;
    return axis;
}

std::string superscript(int exponent) {
    static constexpr std::array<const char*, 10> kDigits = {"⁰", "¹", "²", "³", "⁴",
                                                            "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::string out = exponent < 0 ? "⁻" : "";
    for (char c : std::to_string(std::abs(exponent))) out += kDigits[c - '0'];
    return out;
}

std::string error_tick_label(int decade) {
    if (decade == 0) return "1";
    if (decade == 1) return "10";
    return "10" + superscript(decade);
}

// Time decades in the unit a reader thinks in: 1 ns ... 100 ns, 1 µs ..., 1 s, 10 s, ...
std::string time_tick_label(int decade_ns) {
    if (decade_ns < 0) return fmt::format("10{} ns", superscript(decade_ns));
    static constexpr std::array<const char*, 4> kUnits = {"ns", "µs", "ms", "s"};
    const int unit = std::min(decade_ns / 3, 3);
    const int exponent = decade_ns - 3 * unit;
    return fmt::format("{:.0f} {}", std::pow(10.0, exponent), kUnits[unit]);
}

std::string format_time(double ns) {
    if (ns < 1e3) return fmt::format("{:.3g} ns", ns);
    if (ns < 1e6) return fmt::format("{:.3g} µs", ns * 1e-3);
    if (ns < 1e9) return fmt::format("{:.3g} ms", ns * 1e-6);
    return fmt::format("{:.3g} s", ns * 1e-9);
}

// A marker of one of kShapes shapes centred on (x, y), radius r, as an SVG path.
std::string marker_path(int shape, double x, double y, double r) {
    switch (shape % kShapes) {
        case 0:  // circle, as two arcs so that every marker is a <path>
            return fmt::format(
                "M{:.1f},{:.1f}a{r:.1f},{r:.1f} 0 1,0 {d:.1f},0a{r:.1f},{r:.1f} "
                "0 1,0 -{d:.1f},0z",
                x - r, y, fmt::arg("r", r), fmt::arg("d", 2 * r));
        case 1: {  // square, of the same area as the circle
            const double h = r * 0.886;
            return fmt::format("M{:.1f},{:.1f}h{:.1f}v{:.1f}h-{:.1f}z", x - h, y - h, 2 * h, 2 * h,
                               2 * h);
        }
        case 2:  // triangle up
            return fmt::format("M{:.1f},{:.1f}L{:.1f},{:.1f}L{:.1f},{:.1f}z", x, y - 1.3 * r,
                               x + 1.15 * r, y + 0.7 * r, x - 1.15 * r, y + 0.7 * r);
        case 3:  // diamond
            return fmt::format("M{:.1f},{:.1f}L{:.1f},{:.1f}L{:.1f},{:.1f}L{:.1f},{:.1f}z", x,
                               y - 1.25 * r, x + 1.25 * r, y, x, y + 1.25 * r, x - 1.25 * r, y);
        case 4:  // triangle down
            return fmt::format("M{:.1f},{:.1f}L{:.1f},{:.1f}L{:.1f},{:.1f}z", x, y + 1.3 * r,
                               x + 1.15 * r, y - 0.7 * r, x - 1.15 * r, y - 0.7 * r);
        default: {  // plus, thick
            const double a = r * 1.2;
            const double b = r * 0.4;
            return fmt::format(
                "M{:.1f},{:.1f}h{b2:.1f}v{ab:.1f}h{ab:.1f}v{b2:.1f}h-{ab:.1f}v{ab:.1f}h-{b2:.1f}"
                "v-{ab:.1f}h-{ab:.1f}v-{b2:.1f}h{ab:.1f}z",
                x - b, y - a, fmt::arg("b2", 2 * b), fmt::arg("ab", a - b));
        }
    }
}

// The parameter a point stands for, e.g. "n=6"; empty when the row has no cost parameter.
std::string point_label(const ResultRow& row) {
    if (row.cost_param.empty()) return {};
    return fmt::format("{}={:g}", row.cost_param, row.cost_value);
}

struct PlotPoint {
    std::size_t row = 0;
    double time_ns = 0.0;
    double error = 0.0;  // clamped to kPlotErrorFloor
    bool clamped = false;
};

// The rows that can be drawn, and the series they make.
struct PlotData {
    std::vector<PlotPoint> points;
    std::size_t left_out = 0;  // rows without a finite positive time or a finite error
    bool any_clamped = false;
    std::vector<std::string> series_ids;  // method ids in order of first appearance
    std::map<std::string, std::vector<std::size_t>> series_points;  // indices into `points`
};

PlotData collect_points(const std::vector<ResultRow>& rows) {
    // Points that can be drawn; the others are counted in a note.
    PlotData data;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const double time_ns = rows[r][metric::kTimeMedianNs];
        const double error = rows[r][metric::kBoxRmse];
        if (!(time_ns > 0.0) || !std::isfinite(time_ns) || !std::isfinite(error)) {
            ++data.left_out;
            continue;
        }
        // `!(error >= floor)` also catches -0 and denormals: all of them go to the floor.
        const bool clamped = !(error >= kPlotErrorFloor);
        data.any_clamped = data.any_clamped || clamped;
        data.points.push_back({r, time_ns, clamped ? kPlotErrorFloor : error, clamped});
    }

    // Series: method ids in order of first appearance, each point list ordered by cost.
    for (std::size_t p = 0; p < data.points.size(); ++p) {
        const std::string& id = rows[data.points[p].row].method_id;
        if (!data.series_points.count(id)) data.series_ids.push_back(id);
        data.series_points[id].push_back(p);
    }
    for (auto& [id, members] : data.series_points) {
        std::stable_sort(members.begin(), members.end(), [&](std::size_t a, std::size_t b) {
            return rows[data.points[a].row].cost_value < rows[data.points[b].row].cost_value;
        });
    }
    return data;
}

// Where things land on the canvas: both axes, whether the y axis breaks, and the floor line.
struct PlotFrame {
    Axis x_axis;
    Axis y_axis;
    bool broken = false;
    double floor_y = 0.0;

    double px(const PlotPoint& p) const { return x_axis.to_pixel(p.time_ns); }
    double py(const PlotPoint& p) const { return p.clamped ? floor_y : y_axis.to_pixel(p.error); }
};

// The frame of a plot with at least one point.
PlotFrame make_frame(const PlotData& data) {
    const std::vector<PlotPoint>& points = data.points;
    double min_t = points[0].time_ns, max_t = min_t, max_e = points[0].error;
    double min_e = std::numeric_limits<double>::infinity();  // of the points above the floor
    for (const PlotPoint& p : points) {
        min_t = std::min(min_t, p.time_ns);
        max_t = std::max(max_t, p.time_ns);
        max_e = std::max(max_e, p.error);
        if (!p.clamped) min_e = std::min(min_e, p.error);
    }
    const bool all_clamped = !std::isfinite(min_e);
    PlotFrame frame;
    frame.broken = data.any_clamped && !all_clamped &&
                   std::floor(std::log10(min_e)) - std::log10(kPlotErrorFloor) > kMaxGapDecades;
    frame.x_axis = make_axis(min_t, max_t, kLeft, kRight);
    frame.y_axis = make_axis(frame.broken || !data.any_clamped ? min_e : kPlotErrorFloor, max_e,
                             kBottom, kTop);  // y grows down
    if (frame.broken) frame.y_axis.lo = frame.y_axis.first_decade - kFloorSlotDecades;
    frame.floor_y = frame.broken
                        ? frame.y_axis.log_to_pixel(frame.y_axis.first_decade - kFloorDepthDecades)
                        : frame.y_axis.to_pixel(kPlotErrorFloor);
    return frame;
}

// The <svg> element's opening, the white background and the title.
std::string svg_head(const std::string& title, double height) {
    return fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w:.0f}\" height=\"{h:.0f}\" "
        "viewBox=\"0 0 {w:.0f} {h:.0f}\" font-family=\"DejaVu Sans, Verdana, sans-serif\" "
        "font-size=\"12\">\n"
        "<title>{t}</title>\n<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n"
        "<text x=\"{x:.0f}\" y=\"24\" font-size=\"15\" font-weight=\"bold\">{t}</text>\n",
        fmt::arg("w", kWidth), fmt::arg("h", height), fmt::arg("t", xml_escape(title)),
        fmt::arg("x", kLeft));
}

// Grid, frame, decade tick labels and the axis titles.
std::string axes(const PlotFrame& frame) {
    const Axis& x_axis = frame.x_axis;
    const Axis& y_axis = frame.y_axis;
    // Grid and ticks: a line and a label at each decade, lighter lines at 2..9 times it.
    std::string svg = "<g class=\"grid\" stroke=\"#e4e4e4\" stroke-width=\"1\">\n";
    for (int d = x_axis.first_decade; d <= x_axis.last_decade; ++d) {
        for (int m = 1; m <= 9 && (m == 1 || d < x_axis.last_decade); ++m) {
            const double x = x_axis.to_pixel(m * std::pow(10.0, d));
            svg +=
                fmt::format("<line x1=\"{x:.1f}\" y1=\"{:.1f}\" x2=\"{x:.1f}\" y2=\"{:.1f}\"{}/>\n",
                            kTop, kBottom, m == 1 ? " stroke=\"#c8c8c8\"" : "", fmt::arg("x", x));
        }
    }
    for (int d = y_axis.first_decade; d <= y_axis.last_decade; ++d) {
        for (int m = 1; m <= 9 && (m == 1 || d < y_axis.last_decade); ++m) {
            const double y = y_axis.to_pixel(m * std::pow(10.0, d));
            svg +=
                fmt::format("<line x1=\"{:.1f}\" y1=\"{y:.1f}\" x2=\"{:.1f}\" y2=\"{y:.1f}\"{}/>\n",
                            kLeft, kRight, m == 1 ? " stroke=\"#c8c8c8\"" : "", fmt::arg("y", y));
        }
    }
    svg += "</g>\n";
    svg += fmt::format(
        "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" "
        "fill=\"none\" stroke=\"#444\"/>\n",
        kLeft, kTop, kRight - kLeft, kBottom - kTop);
    svg += "<g class=\"ticks\" fill=\"#222\">\n";
    for (int d = x_axis.first_decade; d <= x_axis.last_decade; ++d) {
        svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n",
                           x_axis.to_pixel(std::pow(10.0, d)), kBottom + 17, time_tick_label(d));
    }
    for (int d = y_axis.first_decade; d <= y_axis.last_decade; ++d) {
        svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{}</text>\n",
                           kLeft - 6, y_axis.to_pixel(std::pow(10.0, d)) + 4, error_tick_label(d));
    }
    svg += "</g>\n";
    svg += fmt::format(
        "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">time of one render (median, one "
        "thread; log scale)</text>\n",
        0.5 * (kLeft + kRight), kBottom + 38);
    svg += fmt::format(
        "<text transform=\"translate({:.1f},{:.1f}) rotate(-90)\" text-anchor=\"middle\">"
        "box_rmse against the exact box reference (log scale)</text>\n",
        kLeft - 52, 0.5 * (kTop + kBottom));
    return svg;
}

// The floor line, for a plot with a point on it, and the axis break when the y axis breaks.
std::string floor_marks(const PlotFrame& frame) {
    const double floor_y = frame.floor_y;
    // The floor, when a point sits on it: say so where the points are. The label goes at the
    // left, where the slow exact methods that sit on the floor rarely are.
    std::string svg = fmt::format(
        "<g class=\"floor\"><line x1=\"{:.1f}\" y1=\"{y:.1f}\" x2=\"{:.1f}\" y2=\"{y:.1f}\" "
        "stroke=\"#888\" stroke-dasharray=\"4 3\"/><text x=\"{:.1f}\" y=\"{:.1f}\" "
        "font-size=\"10\" fill=\"#555\">floor {:g}: smaller errors (float32 rounding) "
        "and 0 drawn here</text>",
        kLeft, kRight, kLeft + 4, floor_y - 5, kPlotErrorFloor, fmt::arg("y", floor_y));
    if (frame.broken) {
        // The tick names the floor; the break mark (a gap and two slashes on both sides of
        // the frame) says that the decades between are cut out.
        const double y = frame.y_axis.log_to_pixel(frame.y_axis.first_decade - kBreakDepthDecades);
        svg += fmt::format(
            "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">&lt;{}"
            "</text>",
            kLeft - 6, floor_y + 4,
            error_tick_label(static_cast<int>(std::log10(kPlotErrorFloor))));
        for (double x : {kLeft, kRight}) {
            svg += fmt::format(
                "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"12\" height=\"6\" fill=\"#fff\"/>"
                "<path class=\"axis-break\" d=\"M{:.1f},{:.1f}l12,-4M{:.1f},{:.1f}l12,-4\" "
                "stroke=\"#444\"/>",
                x - 6, y - 3, x - 6, y - 1, x - 6, y + 5);
        }
    }
    svg += "</g>\n";
    return svg;
}

// The points on the Pareto front over every drawn point, in increasing time.
std::vector<std::size_t> front_points(const std::vector<PlotPoint>& points) {
    std::vector<double> xs, ys;
    for (const PlotPoint& p : points) {
        xs.push_back(p.time_ns);
        ys.push_back(p.error);
    }
    return pareto_front(xs, ys);
}

// The Pareto front as the boundary of the region it dominates: down from the top at the fastest
// front point, then steps right-and-down, then right to the edge. Anything above and right of
// the line is beaten in both time and error.
std::string pareto_step(const PlotData& data, const PlotFrame& frame,
                        const std::vector<std::size_t>& front) {
    const std::vector<PlotPoint>& points = data.points;
    std::string step = fmt::format("M{:.1f},{:.1f}", frame.px(points[front[0]]), kTop);
    for (std::size_t k = 0; k < front.size(); ++k) {
        if (k > 0) step += fmt::format("H{:.1f}", frame.px(points[front[k]]));
        step += fmt::format("V{:.1f}", frame.py(points[front[k]]));
    }
    step += fmt::format("H{:.1f}", kRight);
    return fmt::format(
        "<path class=\"pareto-front\" d=\"{}\" fill=\"none\" stroke=\"#222\" "
        "stroke-opacity=\"0.55\" stroke-width=\"1.5\" "
        "stroke-dasharray=\"6 3\"/>\n",
        step);
}

// A point's parameter label, placed after every marker is known (label_layout.h).
struct PendingLabel {
    LabelRequest request;
    const char* colour = "";
};

// One method's <g class="series">: its curve, then its points; the points' parameter labels
// are appended to `labels`, placed and drawn later over everything.
std::string series_group(const std::vector<ResultRow>& rows, const PlotData& data,
                         const PlotFrame& frame, std::size_t s, std::vector<PendingLabel>& labels) {
    const std::vector<PlotPoint>& points = data.points;
    const std::string& id = data.series_ids[s];
    const char* colour = kColours[s % kColours.size()];
    const std::vector<std::size_t>& members = data.series_points.at(id);
    std::string svg = fmt::format("<g class=\"series\" data-method=\"{}\">\n", xml_escape(id));
    if (members.size() >= 2) {
        std::string coordinates;
        for (std::size_t p : members) {
            coordinates += fmt::format("{:.1f},{:.1f} ", frame.px(points[p]), frame.py(points[p]));
        }
        coordinates.pop_back();
        svg += fmt::format(
            "<polyline class=\"curve\" points=\"{}\" fill=\"none\" "
            "stroke=\"{}\" stroke-width=\"1.8\"/>\n",
            coordinates, colour);
    }
    for (std::size_t p : members) {
        const ResultRow& row = rows[points[p].row];
        const bool is_default = !row.sweep_point;
        const double x = frame.px(points[p]);
        const double y = frame.py(points[p]);
        svg += fmt::format(
            "<path class=\"point{}\" d=\"{}\" fill=\"{}\" stroke=\"{}\" stroke-width=\"{}\">"
            "<title>{}&#10;box_rmse {:.4g}{}&#10;time {}</title></path>\n",
            is_default ? " default" : "",
            marker_path(static_cast<int>(s), x, y, is_default ? kDefaultRadius : kPointRadius),
            colour, is_default ? "#111" : "none", is_default ? "1.5" : "0", xml_escape(row.method),
            row[metric::kBoxRmse],
            points[p].clamped ? fmt::format(" (drawn at the floor {:g})", kPlotErrorFloor)
                              : std::string(),
            format_time(row[metric::kTimeMedianNs]));
        const std::string label = point_label(row);
        if (!label.empty()) {
            labels.push_back({{{x, y, is_default ? kDefaultRadius : kPointRadius},
                               label,
                               kLabelFontPx,
                               is_default},
                              colour});
        }
    }
    svg += "</g>\n";
    return svg;
}

// Every series, the rings round the front's points, then the point labels where they cover no
// mark and no other label; `labels_left_out` counts those with no free spot.
std::string series_marks(const std::vector<ResultRow>& rows, const PlotData& data,
                         const PlotFrame& frame, const std::vector<std::size_t>& front,
                         std::size_t& labels_left_out) {
    // Curves, then points, so no line crosses over a marker.
    std::string svg;
    std::vector<PendingLabel> pending;
    for (std::size_t s = 0; s < data.series_ids.size(); ++s) {
        svg += series_group(rows, data, frame, s, pending);
    }
    // Every mark a label must keep clear of: each point (as large as a default one), and the
    // ring round each front point.
    std::vector<Marker> markers;
    for (const PlotPoint& p : data.points)
        markers.push_back({frame.px(p), frame.py(p), kDefaultRadius});
    for (std::size_t p : front) {
        svg += fmt::format(
            "<circle class=\"pareto-ring\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{:.1f}\" "
            "fill=\"none\" stroke=\"#111\" stroke-width=\"1.2\"/>\n",
            frame.px(data.points[p]), frame.py(data.points[p]), kRingRadius);
        markers.push_back({frame.px(data.points[p]), frame.py(data.points[p]), kRingRadius});
    }
    // Default points' labels first: they are the ones a reader looks for.
    std::stable_partition(pending.begin(), pending.end(),
                          [](const PendingLabel& l) { return l.request.bold; });
    std::vector<LabelRequest> requests;
    for (const PendingLabel& l : pending) requests.push_back(l.request);
    const std::vector<std::optional<PlacedLabel>> placed =
        place_labels(requests, markers, {kLeft, kTop, kRight, kBottom});
    // Labels last, over everything, with a white halo so they read over lines.
    svg +=
        "<g font-size=\"10\" paint-order=\"stroke\" stroke=\"#fff\" stroke-width=\"3\" "
        "stroke-linejoin=\"round\">\n";
    for (std::size_t k = 0; k < pending.size(); ++k) {
        if (!placed[k]) {
            ++labels_left_out;
            continue;
        }
        if (placed[k]->leader) {  // far from its point: a thin line says whose it is
            const Marker& from = pending[k].request.anchor;
            const auto [to_x, to_y] = nearest_point(placed[k]->box, from.x, from.y);
            svg += fmt::format(
                "<line class=\"leader\" x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" "
                "y2=\"{:.1f}\" stroke=\"{}\" stroke-width=\"0.8\"/>\n",
                from.x, from.y, to_x, to_y, pending[k].colour);
        }
        svg +=
            fmt::format("<text class=\"label\" x=\"{:.1f}\" y=\"{:.1f}\" fill=\"{}\"{}>{}</text>\n",
                        placed[k]->text_x, placed[k]->baseline_y, pending[k].colour,
                        pending[k].request.bold ? " font-weight=\"bold\"" : "",
                        xml_escape(pending[k].request.text));
    }
    svg += "</g>\n";
    return svg;
}

// Legend: one entry per series, then the keys for the marks.
std::string legend(const std::vector<std::string>& series_ids) {
    double y = kTop + 6;
    std::string svg = "<g class=\"legend\">\n";
    for (std::size_t s = 0; s < series_ids.size(); ++s, y += kLegendLineHeight) {
        const char* colour = kColours[s % kColours.size()];
        svg += fmt::format(
            "<line x1=\"{:.1f}\" y1=\"{y:.1f}\" x2=\"{:.1f}\" y2=\"{y:.1f}\" stroke=\"{c}\" "
            "stroke-width=\"1.8\"/><path d=\"{}\" fill=\"{c}\"/><text x=\"{:.1f}\" "
            "y=\"{:.1f}\">{}</text>\n",
            kLegendX, kLegendX + 24, marker_path(static_cast<int>(s), kLegendX + 12, y, 4.5),
            kLegendX + 32, y + 4, xml_escape(series_ids[s]), fmt::arg("y", y),
            fmt::arg("c", colour));
    }
    y += 0.5 * kLegendLineHeight;
    svg += fmt::format(
        "<path d=\"{}\" fill=\"#bbb\" stroke=\"#111\" stroke-width=\"1.5\"/><text x=\"{:.1f}\" "
        "y=\"{:.1f}\">default parameters</text>\n",
        marker_path(0, kLegendX + 12, y, kDefaultRadius), kLegendX + 32, y + 4);
    y += kLegendLineHeight;
    svg += fmt::format(
        "<path d=\"{}\" fill=\"#bbb\"/><text x=\"{:.1f}\" y=\"{:.1f}\">sweep point "
        "(labelled n=, k=)</text>\n",
        marker_path(0, kLegendX + 12, y, kPointRadius), kLegendX + 32, y + 4);
    y += kLegendLineHeight;
    svg += fmt::format(
        "<line x1=\"{:.1f}\" y1=\"{y:.1f}\" x2=\"{:.1f}\" y2=\"{y:.1f}\" stroke=\"#222\" "
        "stroke-opacity=\"0.55\" stroke-width=\"1.5\" stroke-dasharray=\"6 3\"/><text "
        "x=\"{:.1f}\" y=\"{:.1f}\">Pareto front</text>\n",
        kLegendX, kLegendX + 24, kLegendX + 32, y + 4, fmt::arg("y", y));
    y += kLegendLineHeight;
    svg += fmt::format(
        "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"7\" fill=\"none\" stroke=\"#111\" "
        "stroke-width=\"1.2\"/><text x=\"{:.1f}\" y=\"{:.1f}\">on the front: nothing both "
        "faster</text><text x=\"{:.1f}\" y=\"{:.1f}\">and more accurate</text>\n",
        kLegendX + 12, y, kLegendX + 32, y + 4, kLegendX + 32, y + 4 + 14);
    svg += "</g>\n";
    return svg;
}

// Notes under the axis label: what was clamped, what was left out.
std::string notes(const PlotData& data, const PlotFrame& frame, std::size_t labels_left_out) {
    std::string note;
    if (frame.broken) {
        note += fmt::format(
            "box_rmse below {:g} (float32 rounding) or 0 is drawn on the floor "
            "line below the axis break. ",
            kPlotErrorFloor);
    } else if (data.any_clamped) {
        note += fmt::format("box_rmse below {:g} (float32 rounding) or 0 is drawn at {:g}. ",
                            kPlotErrorFloor, kPlotErrorFloor);
    }
    if (data.left_out > 0) {
        note += fmt::format("{} row{} without a finite time and error not drawn.", data.left_out,
                            data.left_out == 1 ? "" : "s");
    }
    if (labels_left_out > 0) {
        note += fmt::format(" {} label{} left out where {} would cover a point (hover for it).",
                            labels_left_out, labels_left_out == 1 ? "" : "s",
                            labels_left_out == 1 ? "it" : "they");
    }
    if (note.empty()) return {};
    return fmt::format(
        "<text class=\"note\" x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" "
        "fill=\"#555\">{}</text>\n",
        kLeft, kBottom + 58, xml_escape(note));
}

}  // namespace

std::string xml_escape(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&#39;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::vector<std::size_t> pareto_front(const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
        if (std::isfinite(x[i]) && std::isfinite(y[i])) order.push_back(i);
    }
    // By x, then y: the first point of each x is the only one of that x that can be on the
    // front (besides its exact duplicates), and it is on it iff its y beats every faster point.
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return x[a] != x[b] ? x[a] < x[b] : y[a] < y[b];
    });
    std::vector<std::size_t> front;
    double best_y = std::numeric_limits<double>::infinity();
    for (std::size_t i : order) {
        const bool duplicate = !front.empty() && x[front.back()] == x[i] && y[front.back()] == y[i];
        if (y[i] < best_y || duplicate) {
            front.push_back(i);
            best_y = y[i];
        }
    }
    return front;
}

std::string accuracy_time_svg(const std::vector<ResultRow>& rows, const std::string& title) {
    const PlotData data = collect_points(rows);
    const double height =
        std::max(kMinHeight, kTop + (data.series_ids.size() + 6) * kLegendLineHeight + 20.0);
    std::string svg = svg_head(title, height);
    if (data.points.empty()) {
        svg += fmt::format(
            "<text x=\"{:.0f}\" y=\"{:.0f}\">no rows with a finite time and "
            "error to plot ({} left out)</text>\n</svg>\n",
            kLeft, 0.5 * (kTop + kBottom), data.left_out);
        return svg;
    }
    const PlotFrame frame = make_frame(data);
    svg += axes(frame);
    if (data.any_clamped) svg += floor_marks(frame);
    const std::vector<std::size_t> front = front_points(data.points);
    svg += pareto_step(data, frame, front);
    std::size_t labels_left_out = 0;
    svg += series_marks(rows, data, frame, front, labels_left_out);
    svg += legend(data.series_ids);
    svg += notes(data, frame, labels_left_out);
    svg += "</svg>\n";
    return svg;
}

}  // namespace aabench
