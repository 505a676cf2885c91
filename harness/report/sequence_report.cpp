// The files of a sequence run (harness/report/sequence_report.h).
#include "harness/report/sequence_report.h"

#include <OpenImageIO/imagebufalgo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "harness/measure/sequence_metrics.h"
#include "harness/report/html_parts.h"
#include "harness/report/image_io.h"
#include "harness/report/report.h"
#include "harness/report/svg_plot.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// The filmstrip's crop: a centred square of this side (or the image, when smaller), each pixel
// drawn as a kZoom x kZoom block, so single pixels and their flicker are visible.
constexpr int kCropPx = 24;
constexpr int kZoom = 4;
// Distinct colours for the plots' lines (Okabe & Ito's colour-blind-safe set, then greys).
constexpr const char* kColours[] = {"#000000", "#e69f00", "#56b4e9", "#009e73", "#f0e442",
                                    "#0072b2", "#d55e00", "#cc79a7", "#777777", "#bbbbbb"};

std::vector<MetricId> table_metrics() {
    std::vector<MetricId> ids;
    for (MetricId id = 0; id < metric_registry().size(); ++id) {
        if (metric_registry()[id].applies == kAppliesSequences) ids.push_back(id);
    }
    return ids;
}

std::string cell(const MetricDef& def, double v, int width) {
    if (std::isnan(v)) return fmt::format("{:>{}}", "-", width);
    if (std::isinf(v)) return fmt::format("{:>{}}", v > 0 ? "inf" : "-inf", width);
    if (def.shown == Shown::kSigned) return fmt::format("{:>+{}.{}f}", v, width, def.text_decimals);
    return fmt::format("{:>{}.{}f}", v, width, def.text_decimals);
}

Image to_image(const Coverage& c) {
    Image out(c.width, c.height);
    for (std::size_t k = 0; k < c.data.size(); ++k) out.data[k] = static_cast<float>(c.data[k]);
    return out;
}

OIIO::ImageBuf magnified_crop(const Image& image) {
    const int side_w = std::min(kCropPx, image.width), side_h = std::min(kCropPx, image.height);
    const int x = (image.width - side_w) / 2, y = (image.height - side_h) / 2;
    const OIIO::ImageBuf view = html_parts::display_view(image);
    const OIIO::ImageBuf crop =
        OIIO::ImageBufAlgo::cut(view, OIIO::ROI(x, x + side_w, y, y + side_h));
    const OIIO::ROI zoomed(0, side_w * kZoom, 0, side_h * kZoom, 0, 1, 0, view.nchannels());
    OIIO::ImageBuf out = OIIO::ImageBufAlgo::resample(crop, /*interpolate=*/false, zoomed);
    if (out.has_error()) throw InputError("magnifying failed: " + out.geterror());
    return out;
}

// Largest |error| of the last frames, rounded up to 1, 2 or 5 x 10^k (as the still report's
// maps), at least 1e-3 so that exact methods' maps stay white.
double last_error_scale(const SequenceFigures& fig) {
    double largest = 1e-3;
    for (const SequenceMethodRun& run : fig.runs) {
        for (float e : run.last_error.data) {
            if (std::isfinite(e)) largest = std::max(largest, double(std::abs(e)));
        }
    }
    const double decade = std::pow(10.0, std::floor(std::log10(largest)));
    for (double step : {1.0, 2.0, 5.0, 10.0}) {
        if (largest <= step * decade * (1.0 + 1e-6)) return step * decade;
    }
    return 10.0 * decade;
}

std::string html_table(const SequenceRunResult& result, const std::string& sequence) {
    std::string out = "<table><tr><th>method</th>";
    const std::vector<MetricId> ids = table_metrics();
    for (MetricId id : ids) {
        const MetricDef& d = metric_registry()[id];
        out +=
            fmt::format("<th title=\"{}\">{}</th>", xml_escape(d.definition), xml_escape(d.header));
    }
    out += "</tr>\n";
    for (const ResultRow& r : result.rows) {
        if (r.pattern != sequence) continue;
        out += "<tr><td>" + xml_escape(r.method) + "</td>";
        if (!r.not_applicable.empty()) {
            out += fmt::format("<td colspan=\"{}\">n/a: {}</td></tr>\n", ids.size(),
                               xml_escape(r.not_applicable));
            continue;
        }
        for (MetricId id : ids) {
            out += "<td>" + cell(metric_registry()[id], r[id], 0) + "</td>";
        }
        out += "</tr>\n";
    }
    return out + "</table>\n";
}

std::string sequence_section(const fs::path& dir, const SequenceRunResult& result,
                             const SequenceFigures& fig) {
    const std::string name = html_parts::slug(fig.sequence);
    const fs::path image_dir = dir / "images" / name;
    fs::create_directories(image_dir);
    std::string out = fmt::format("<section id=\"{0}\"><h2>{1}</h2><p>{2}; {3} frames.</p>\n", name,
                                  xml_escape(fig.sequence), xml_escape(fig.summary), fig.frames);
    out += html_table(result, fig.sequence);
    out += "<h3>Error per frame</h3>\n" + frame_error_svg(fig, false);
    if (fig.still) {
        out +=
            "<h3>Convergence</h3><p>|e<sub>t</sub> &minus; steady| / steady per frame; the "
            "dashed line is the 10 % band of seq_convergence.</p>\n" +
            frame_error_svg(fig, true);
    }
    // Filmstrip: the reference's crops, then each method's, one row each.
    std::string frames_text;
    for (int t : fig.kept_frames) frames_text += fmt::format(" {}", t);
    out += fmt::format(
        "<h3>Filmstrip</h3><p>The centre {0}&times;{0} px magnified {1}&times; at "
        "frames{2}, the exact box reference first.</p>\n<table>\n",
        kCropPx, kZoom, frames_text);
    const auto strip_row = [&](const std::string& label, const std::string& file,
                               const std::vector<OIIO::ImageBuf>& crops) {
        html_parts::write_strip(image_dir / file, crops);
        out += fmt::format("<tr><td>{}</td><td><img src=\"images/{}/{}\" alt=\"{}\"></td></tr>\n",
                           xml_escape(label), name, file, xml_escape(label));
    };
    std::vector<OIIO::ImageBuf> crops;
    for (const Coverage& c : fig.kept_reference) crops.push_back(magnified_crop(to_image(c)));
    strip_row("reference", "reference.film.png", crops);
    for (const SequenceMethodRun& run : fig.runs) {
        crops.clear();
        for (const Image& image : run.kept) crops.push_back(magnified_crop(image));
        strip_row(run.method, html_parts::slug(run.method) + ".film.png", crops);
    }
    out += "</table>\n";
    // The last frame's error maps.
    const double scale = last_error_scale(fig);
    out += "<h3>Last frame: error against the exact box reference</h3>\n" +
           html_parts::signed_colour_bar(scale, name + "-bar") + "<div class=\"maps\">\n";
    for (const SequenceMethodRun& run : fig.runs) {
        const std::string file = html_parts::slug(run.method) + ".last-error.png";
        html_parts::write_png_view(image_dir / file,
                                   html_parts::signed_view(run.last_error, scale));
        out += "<figure>" +
               html_parts::img_tag("images/" + name + "/" + file, run.last_error.width,
                                   run.last_error.height, run.method + ", last frame's error") +
               "<figcaption>" + xml_escape(run.method) + "</figcaption></figure>\n";
    }
    return out + "</div></section>\n";
}

}  // namespace

std::string format_sequence_tables(const std::vector<ResultRow>& rows) {
    const std::vector<MetricId> ids = table_metrics();
    std::size_t name_width = 6;
    for (const ResultRow& r : rows) name_width = std::max(name_width, r.method.size());
    std::string out;
    std::string current;
    for (const ResultRow& r : rows) {
        if (r.pattern != current) {
            current = r.pattern;
            out += fmt::format("{}{}  ({}x{})\n  {:<{}}", out.empty() ? "" : "\n", current, r.width,
                               r.height, "method", name_width);
            for (MetricId id : ids) {
                const MetricDef& d = metric_registry()[id];
                out += fmt::format(" {:>{}}", d.header, d.text_width);
            }
            out += '\n';
        }
        out += fmt::format("  {:<{}}", r.method, name_width);
        if (!r.not_applicable.empty()) {
            out += " n/a: " + r.not_applicable + "\n";
            continue;
        }
        for (MetricId id : ids) {
            const MetricDef& d = metric_registry()[id];
            out += " " + cell(d, r[id], d.text_width);
        }
        out += '\n';
    }
    return out;
}

std::string sequence_frames_csv(const SequenceRunResult& result) {
    std::string out = "sequence,method,frame,box_rmse,frame_ms,disoccluded_share\n";
    for (const SequenceFigures& fig : result.figures) {
        for (const SequenceMethodRun& run : fig.runs) {
            for (std::size_t t = 0; t < run.frame_rmse.size(); ++t) {
                out += fmt::format("{},\"{}\",{},{:.9g},{:.6g},{:.6g}\n", fig.sequence, run.method,
                                   t, run.frame_rmse[t], run.frame_ms[t], fig.disoccluded_share[t]);
            }
        }
    }
    return out;
}

std::string sequence_frames_json(const SequenceRunResult& result, const RunContext& context) {
    Json doc;
    doc["context"] = {{"git_revision", context.git_revision},
                      {"cpu", context.cpu},
                      {"date_utc", context.date_utc},
                      {"command", context.command}};
    Json& sequences = doc["sequences"] = Json::array();
    for (const SequenceFigures& fig : result.figures) {
        Json s = {{"sequence", fig.sequence},
                  {"frames", fig.frames},
                  {"disoccluded_share", fig.disoccluded_share}};
        Json& methods = s["methods"] = Json::array();
        for (const SequenceMethodRun& run : fig.runs) {
            methods.push_back(
                {{"method", run.method}, {"box_rmse", run.frame_rmse}, {"frame_ms", run.frame_ms}});
        }
        sequences.push_back(std::move(s));
    }
    return doc.dump(1) + "\n";
}

std::string frame_error_svg(const SequenceFigures& fig, bool relative_to_steady) {
    constexpr double kW = 640, kH = 300, kLeft = 60, kRight = 190, kTop = 12, kBottom = 36;
    // Errors below the floor (exact methods: float32 rounding) are drawn at it.
    constexpr double kFloor = 1e-7;
    std::vector<std::vector<double>> series;
    for (const SequenceMethodRun& run : fig.runs) {
        std::vector<double> y = run.frame_rmse;
        if (relative_to_steady) {
            const std::size_t half = y.size() / 2;
            double steady = 0.0;
            for (std::size_t t = half; t < y.size(); ++t) steady += y[t];
            steady /= std::max<std::size_t>(1, y.size() - half);
            for (double& v : y) v = steady > 0 ? std::abs(v - steady) / steady : kFloor;
        }
        for (double& v : y) v = std::isfinite(v) ? std::max(v, kFloor) : kFloor;
        series.push_back(std::move(y));
    }
    double lo = relative_to_steady ? 0.01 : 1.0, hi = relative_to_steady ? 1.0 : 1e-3;
    for (const auto& y : series) {
        for (double v : y) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    const double d_lo = std::floor(std::log10(lo)), d_hi = std::ceil(std::log10(hi));
    const double span = std::max(1.0, d_hi - d_lo);
    const int frames = std::max(2, fig.frames);
    const auto px = [&](double t) { return kLeft + (kW - kLeft - kRight) * t / (frames - 1); };
    const auto py = [&](double v) {
        return kTop + (kH - kTop - kBottom) * (d_hi - std::log10(v)) / span;
    };
    std::string out = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" "
        "font-family=\"sans-serif\" font-size=\"11\">\n",
        kW, kH);
    for (double d = d_lo; d <= d_hi; d += 1.0) {
        const double y = py(std::pow(10.0, d));
        out += fmt::format(
            "<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>"
            "<text x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\">1e{}</text>\n",
            kLeft, y, kW - kRight, y, kLeft - 4, y + 4, d);
    }
    out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">frame (0..{})</text>\n",
                       (kLeft + kW - kRight) / 2, kH - 6, frames - 1);
    if (relative_to_steady) {
        out += fmt::format(
            "<line class=\"band\" x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" "
            "stroke=\"#900\" stroke-dasharray=\"4 3\"/>\n",
            kLeft, py(kConvergenceBand), kW - kRight, py(kConvergenceBand));
    }
    for (std::size_t k = 0; k < series.size(); ++k) {
        const char* colour = kColours[k % std::size(kColours)];
        std::string points;
        for (std::size_t t = 0; t < series[k].size(); ++t) {
            points += fmt::format("{:.1f},{:.1f} ", px(double(t)), py(series[k][t]));
        }
        out += fmt::format(
            "<polyline class=\"series\" fill=\"none\" stroke=\"{}\" "
            "stroke-width=\"1.5\" points=\"{}\"/>\n",
            colour, points);
        out += fmt::format("<text x=\"{}\" y=\"{}\" fill=\"{}\">{}</text>\n", kW - kRight + 8,
                           kTop + 12 + 13 * k, colour, xml_escape(fig.runs[k].method));
    }
    return out + "</svg>\n";
}

void write_sequence_results(const std::string& dir, const SequenceRunResult& result,
                            const RunContext& context) {
    const fs::path base(dir);
    std::error_code ec;
    fs::create_directories(base, ec);
    if (ec) throw InputError("--out: cannot create " + dir + ": " + ec.message());
    write_text_file((base / "table.txt").string(),
                    "command: " + context.command + "\n" + format_sequence_tables(result.rows));
    write_text_file((base / "results.csv").string(), compare_rows_csv(result.rows));
    write_text_file((base / "results.json").string(), compare_json(result.rows, context));
    write_text_file((base / "frames.csv").string(), sequence_frames_csv(result));
    write_text_file((base / "frames.json").string(), sequence_frames_json(result, context));
    std::string page =
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>aabench sequences</title>\n"
        "<style>body{font-family:sans-serif;margin:1em 2em}table{border-collapse:collapse}"
        "td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}td:first-child{"
        "text-align:left}.maps figure{display:inline-block;margin:4px}img{image-rendering:"
        "pixelated}</style></head><body>\n<h1>Sequences</h1>\n";
    page +=
        "<p>Every method on every sequence, each frame against its exact reference "
        "(docs/metrics.md, \"Sequences\"; docs/report.md). Command: <code>" +
        xml_escape(context.command) + "</code>; revision " + xml_escape(context.git_revision) +
        ", " + xml_escape(context.date_utc) + ".</p>\n";
    for (const SequenceFigures& fig : result.figures) page += sequence_section(base, result, fig);
    write_text_file((base / "index.html").string(), page + "</body></html>\n");
}

}  // namespace aabench
