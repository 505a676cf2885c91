// The HTML report (harness/report/html_report.h; what the page shows and why: docs/report.md).
//
// Choices a reader of the page depends on:
// - Display transform. Images are linear coverage; shown raw, a 50% edge pixel would look too
//   dark on a screen, and every antialiased edge would look wrong in the same way. So views are
//   the sRGB encoding (IEC 61966-2-1 transfer function) of the values clamped to [0, 1],
//   rounded to 8 bits, computed here exactly (thresholds, no lookup-table rounding) rather than
//   by OpenImageIO's colorconvert, whose result depends on whatever $OCIO config is set.
// - Error maps. error = method - box reference, coloured by a diverging map (ColorBrewer RdBu:
//   blue too dark, white right, red too bright) on a signed log scale over kErrorDecades
//   decades below the pattern's scale S: |error| >= S is full colour, |error| <= S/10^3 is
//   white. S is the largest |error| of any method of the pattern rounded up to 1, 2 or 5 x 10^k,
//   the same for every method of the pattern, so maps compare side by side. A linear scale
//   would be set by the worst method (`none`: errors near 1) and leave the good ones (errors
//   of 1e-2 and below) white; a log scale shows both. The colour bar beside the maps states S.
// - Magnified crops. The scene's "focus" region (or a centred square), cut and magnified by an
//   integer factor with nearest-neighbour sampling (OpenImageIO resample without
//   interpolation), so every pixel is a visible block. The crops are of the 8-bit views, so
//   they show exactly the pixels the full views show.
#include "harness/report/html_report.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "harness/report/image_io.h"
#include "harness/report/report.h"
#include "harness/report/svg_plot.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// Images narrower than this are shown at the largest integer zoom that fits it (pixelated);
// wider ones at their own size, never scaled down (a browser's downscaling would alias).
constexpr int kThumbnailPx = 256;
// Side of the centred square magnified when the scene names no focus region.
constexpr int kDefaultFocusPx = 32;
// The magnified crops are zoomed to about kThumbnailPx, by at most this factor.
constexpr int kMaxZoom = 16;
// The error maps' log scale: from the scale S down to S / 10^kErrorDecades (white). Three
// decades reach from `none`'s errors near 1 to 8-bit quantisation (1/510).
constexpr double kErrorDecades = 3.0;
// When every method is exact up to float32 rounding, the maps still need a scale.
constexpr double kMinErrorScale = 1e-6;

// ColorBrewer RdBu, 11 classes, ordered from the most negative error to the most positive.
constexpr std::array<std::uint32_t, 11> kDivergingKnots = {0x053061, 0x2166ac, 0x4393c3, 0x92c5de,
                                                           0xd1e5f0, 0xf7f7f7, 0xfddbc7, 0xf4a582,
                                                           0xd6604d, 0xb2182b, 0x67001f};

// ---- Text ----

// Shortest text that reads back as the same double: how the table stores its sort keys, so a
// number on the page can be traced to the row bit for bit.
std::string exact_number(double value) {
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "Infinity" : "-Infinity";  // as JavaScript reads
    return fmt::format("{}", value);
}

std::string shown_number(double value, const char* format) {
    // NaN in a row means "not measured here" (symptoms of sweep points, popping without thin
    // objects): a dash reads as that, "NaN" reads as a failure.
    if (std::isnan(value)) return "&ndash;";
    if (std::isinf(value)) return value > 0 ? "&infin;" : "&minus;&infin;";
    return fmt::format(fmt::runtime(format), value);
}

// A file name from a spec: letters, digits and ".-=_" kept, everything else (':', ',', '/')
// becomes '_'. Collisions are resolved by the caller.
std::string slug(const std::string& text) {
    std::string out;
    for (char c : text) {
        const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' ||
                          c == '=' || c == '_';
        out += keep ? c : '_';
    }
    if (out.empty() || out[0] == '.') out = "_" + out;  // never a hidden file
    return out;
}

// `wanted`, or wanted-2, wanted-3, ... if already taken; the result is then taken.
std::string unique_name(const std::string& wanted, std::set<std::string>& taken) {
    std::string name = wanted;
    for (int k = 2; taken.count(name); ++k) name = fmt::format("{}-{}", wanted, k);
    taken.insert(name);
    return name;
}

// ---- Pixels ----

struct Rect {
    int x = 0;
    int y = 0;
    int w = 0;
    int h = 0;
};

// The magnified region: the scene's "focus" metadata ("x,y,w,h" in px, rounded outwards to
// whole pixels and clipped to the image), or a centred square. `note` says which.
Rect focus_region(const Scene& scene, std::string& note) {
    const int side = std::min({kDefaultFocusPx, scene.width, scene.height});
    const Rect centred{(scene.width - side) / 2, (scene.height - side) / 2, side, side};
    const auto item = std::find_if(scene.metadata.begin(), scene.metadata.end(),
                                   [](const auto& kv) { return kv.first == "focus"; });
    if (item == scene.metadata.end()) {
        note = "centred square (the pattern names no focus region)";
        return centred;
    }
    std::array<double, 4> v{};
    char comma = 0;
    std::istringstream in(item->second);
    bool ok = static_cast<bool>(in >> v[0]);
    for (int k = 1; k < 4 && ok; ++k) ok = static_cast<bool>(in >> comma >> v[k]) && comma == ',';
    ok = ok && (in >> std::ws).eof();
    for (double x : v) ok = ok && std::isfinite(x);
    if (ok) {
        // Clipped in double, before the conversion: a huge coordinate must not overflow an int.
        auto clip = [](double value, int limit) {
            return static_cast<int>(std::clamp(value, 0.0, static_cast<double>(limit)));
        };
        const int x0 = clip(std::floor(v[0]), scene.width);
        const int y0 = clip(std::floor(v[1]), scene.height);
        const int x1 = clip(std::ceil(v[0] + v[2]), scene.width);
        const int y1 = clip(std::ceil(v[1] + v[3]), scene.height);
        if (x1 > x0 && y1 > y0) {
            note = fmt::format("the pattern's focus region ({})", item->second);
            return {x0, y0, x1 - x0, y1 - y0};
        }
    }
    note =
        fmt::format("centred square (focus \"{}\" is not x,y,w,h inside the image)", item->second);
    return centred;
}

int zoom_factor(const Rect& region) {
    return std::clamp(kThumbnailPx / std::max(region.w, region.h), 1, kMaxZoom);
}

// Linear values where the 8-bit sRGB code steps up: code c is shown for values in
// [threshold[c-1], threshold[c]). Decoding the half-codes (c + 0.5) / 255 gives rounding to
// nearest of the encoded value exactly, with no table resolution to worry about.
const std::array<double, 255>& srgb_thresholds() {
    static const std::array<double, 255> thresholds = [] {
        std::array<double, 255> t{};
        for (int c = 0; c < 255; ++c) {
            const double encoded = (c + 0.5) / 255.0;
            t[c] = encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
        }
        return t;
    }();
    return thresholds;
}

// 8-bit sRGB view of linear values; NaN shows as 0 (it is counted in the table's nonfinite).
template <class T>
OIIO::ImageBuf srgb_view(const Raster<T>& image) {
    const auto& thresholds = srgb_thresholds();
    std::vector<std::uint8_t> codes(image.pixel_count());
    for (std::size_t p = 0; p < codes.size(); ++p) {
        const double v = image.data[p];
        codes[p] = std::isnan(v) ? 0
                                 : static_cast<std::uint8_t>(
                                       std::upper_bound(thresholds.begin(), thresholds.end(), v) -
                                       thresholds.begin());
    }
    OIIO::ImageBuf view(OIIO::ImageSpec(image.width, image.height, 1, OIIO::TypeDesc::UINT8));
    view.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, codes.data());
    return view;
}

// Largest |error| over every method of the pattern, rounded up to 1, 2 or 5 x 10^k.
double error_scale(const PatternFigures& figures) {
    double largest = 0.0;
    for (const Image& image : figures.images) {
        if (image.data.size() != figures.reference.data.size()) continue;
        for (std::size_t p = 0; p < image.data.size(); ++p) {
            const double e = std::abs(image.data[p] - figures.reference.data[p]);
            if (std::isfinite(e)) largest = std::max(largest, e);
        }
    }
    largest = std::max(largest, kMinErrorScale);
    const double decade = std::pow(10.0, std::floor(std::log10(largest)));
    for (double step : {1.0, 2.0, 5.0, 10.0}) {
        // The small tolerance keeps 0.2000000001 (a float32 error of 0.2) from becoming 0.5.
        if (largest <= step * decade * (1.0 + 1e-6)) return step * decade;
    }
    return 10.0 * decade;
}

// Position of an error on the colour map, in [0, 1] (0.5 white); NaN stays NaN.
float error_position(double error, double scale) {
    if (!std::isfinite(error)) return std::numeric_limits<float>::quiet_NaN();
    const double magnitude = std::abs(error) / scale;
    const double white_below = std::pow(10.0, -kErrorDecades);
    const double level = magnitude <= white_below
                             ? 0.0
                             : std::min(1.0, std::log10(magnitude / white_below) / kErrorDecades);
    return static_cast<float>(0.5 + 0.5 * std::copysign(level, error));
}

// The signed error map as an 8-bit RGB view (OpenImageIO color_map over kDivergingKnots);
// non-finite errors are black, which no colour of the map is.
OIIO::ImageBuf error_view(const Image& error, double scale) {
    OIIO::ImageBuf positions(OIIO::ImageSpec(error.width, error.height, 1, OIIO::TypeDesc::FLOAT));
    std::vector<float> values(error.pixel_count());
    for (std::size_t p = 0; p < values.size(); ++p) {
        const float position = error_position(error.data[p], scale);
        values[p] = std::isnan(position) ? 0.5f : position;
    }
    positions.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, values.data());
    std::vector<float> knots;
    for (std::uint32_t rgb : kDivergingKnots) {
        for (int shift : {16, 8, 0}) knots.push_back(((rgb >> shift) & 0xff) / 255.0f);
    }
    const OIIO::ImageBuf colours = OIIO::ImageBufAlgo::color_map(
        positions, 0, static_cast<int>(kDivergingKnots.size()), 3, knots);
    if (colours.has_error()) throw InputError("error map colouring failed: " + colours.geterror());
    std::vector<std::uint8_t> rgb(error.pixel_count() * 3);
    colours.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, rgb.data());
    for (std::size_t p = 0; p < values.size(); ++p) {
        if (std::isnan(error_position(error.data[p], scale))) {
            rgb[3 * p] = rgb[3 * p + 1] = rgb[3 * p + 2] = 0;
        }
    }
    OIIO::ImageBuf view(OIIO::ImageSpec(error.width, error.height, 3, OIIO::TypeDesc::UINT8));
    view.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, rgb.data());
    return view;
}

// `region` of `view`, each pixel a factor x factor block.
OIIO::ImageBuf magnify(const OIIO::ImageBuf& view, const Rect& region, int factor) {
    const OIIO::ImageBuf crop = OIIO::ImageBufAlgo::cut(
        view, OIIO::ROI(region.x, region.x + region.w, region.y, region.y + region.h));
    const OIIO::ROI zoomed(0, region.w * factor, 0, region.h * factor, 0, 1, 0, view.nchannels());
    OIIO::ImageBuf out = OIIO::ImageBufAlgo::resample(crop, /*interpolate=*/false, zoomed);
    if (out.has_error()) throw InputError("magnifying failed: " + out.geterror());
    return out;
}

void write_view(const fs::path& path, const OIIO::ImageBuf& view) {
    const OIIO::ImageSpec& spec = view.spec();
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(spec.width) * spec.height *
                                     spec.nchannels);
    view.get_pixels(view.roi(), OIIO::TypeDesc::UINT8, pixels.data());
    write_display_png(path.string(), spec.width, spec.height, spec.nchannels, pixels.data());
}

Image to_float(const Coverage& coverage) {
    Image out(coverage.width, coverage.height);
    for (std::size_t p = 0; p < out.data.size(); ++p)
        out.data[p] = static_cast<float>(coverage.data[p]);
    return out;
}

// ---- The page ----

constexpr const char* kStyle = R"css(
body{font-family:"DejaVu Sans",Verdana,sans-serif;margin:20px 28px;color:#222;font-size:14px}
h1{font-size:22px;margin:0 0 6px}
h2{font-size:19px;border-bottom:2px solid #ccc;padding-bottom:3px;margin-top:36px}
h3{font-size:15px;margin:18px 0 6px}
code,pre,.m{font-family:"DejaVu Sans Mono",Menlo,monospace;font-size:12.5px}
pre{background:#f5f5f5;border:1px solid #e2e2e2;padding:8px 10px;white-space:pre-wrap;
    word-break:break-all}
nav a{margin-right:14px}
.note{color:#555;max-width:1100px}
table.results{border-collapse:collapse;font-size:13px}
table.results th{background:#eef0f3;cursor:pointer;user-select:none;white-space:nowrap;
    position:sticky;top:0}
table.results th,table.results td{padding:3px 9px;border-bottom:1px solid #e4e4e4;
    text-align:right}
table.results th.m,table.results td.m{text-align:left}
table.results th[data-dir=asc]::after{content:" \25B2"}
table.results th[data-dir=desc]::after{content:" \25BC"}
table.results tr.default td.m{font-weight:bold}
table.results tr.sweep td{color:#666}
body.hide-sweep tr.sweep{display:none}
table.context td{padding:2px 10px 2px 0;vertical-align:top}
table.context td:first-child{color:#555;white-space:nowrap}
.plot svg{max-width:100%;height:auto;border:1px solid #e2e2e2}
table.figures{border-collapse:collapse}
table.figures th{font-weight:normal;color:#555;text-align:left;padding:4px 8px 2px 0}
table.figures td{padding:0 8px 10px 0;vertical-align:top}
table.figures td.caption{padding:8px 0 3px;border-top:1px solid #e4e4e4}
table.figures img{display:block;image-rendering:pixelated;border:1px solid #ccc}
.small{font-size:12px;color:#555}
.focusbox{position:relative;display:inline-block}
.focusbox span{position:absolute;border:2px solid #f28e2b;box-sizing:border-box}
)css";

// Sorts a results table by the clicked column: numbers by their data-v (NaN last either way),
// text alphabetically with digits as numbers (n=2 before n=12); a second click reverses.
constexpr const char* kScript = R"js(
document.querySelectorAll('table.results').forEach(function(t){
  var hs=t.tHead.rows[0].cells;
  Array.prototype.forEach.call(hs,function(h,i){h.addEventListener('click',function(){
    var asc=h.dataset.dir!=='asc';
    Array.prototype.forEach.call(hs,function(o){delete o.dataset.dir;});
    h.dataset.dir=asc?'asc':'desc';
    var b=t.tBodies[0],rows=Array.prototype.slice.call(b.rows);
    function key(r){var c=r.cells[i];return c.dataset.v===undefined?c.textContent:+c.dataset.v;}
    rows.sort(function(a,c){var x=key(a),y=key(c);
      if(typeof x==='string'){var o=x.localeCompare(y,undefined,{numeric:true});return asc?o:-o;}
      if(isNaN(x)||isNaN(y))return isNaN(x)-isNaN(y);return asc?x-y:y-x;});
    rows.forEach(function(r){b.appendChild(r);});
  });});
});
var sweep=document.getElementById('show-sweep');
if(sweep)sweep.addEventListener('change',function(){
  document.body.classList.toggle('hide-sweep',!sweep.checked);});
)js";

// How a core column is shown; the sort key is always the exact value.
enum class Shown { kGeneral, kSigned, kPercent, kMsFromNs };

struct CoreColumn {
    const char* key;  // in compare_json()'s rows
    const char* header;
    Shown shown;
};

// The summary columns, in this order; every other numeric column of the rows that is not
// listed in kHiddenColumns follows (symptom figures as they are added), named by its key.
constexpr std::array<CoreColumn, 7> kCoreColumns = {{
    {"box_rmse", "box_rmse", Shown::kGeneral},
    {"own_rmse", "own_rmse", Shown::kGeneral},
    {"box_max_abs", "max_abs", Shown::kGeneral},
    {"box_bias", "bias", Shown::kSigned},
    {"dropout", "dropout", Shown::kPercent},
    {"time_median_ns", "time (ms)", Shown::kMsFromNs},
    {"mpixel_per_s", "Mpixel/s", Shown::kGeneral},
}};
// Numeric columns left to results.csv: identifiers, sizes, parts of a shown figure.
const std::set<std::string> kHiddenColumns = {
    "task",        "cost_value",     "width",
    "height",      "edges",          "box_max_x",
    "box_max_y",   "dropout_pixels", "dropout_candidates",
    "own_max_abs", "own_bias",       "time_min_ns",
    "time_max_ns", "time_runs",      "medges_per_s",
};

std::string shown(double value, Shown how) {
    switch (how) {
        case Shown::kSigned:
            return shown_number(value, "{:+.3g}");
        case Shown::kPercent:
            return std::isnan(value) ? "NaN" : fmt::format("{:.2f}%", 100 * value);
        case Shown::kMsFromNs:
            return shown_number(value * 1e-6, "{:.4g}");
        case Shown::kGeneral:
            break;
    }
    return shown_number(value, "{:.4g}");
}

double json_number(const Json& value) {
    return value.is_number() ? value.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

struct Section {
    std::string spec;
    std::string id;
    std::string name;  // file and anchor name
    std::vector<std::size_t> rows;
    const PatternFigures* figures = nullptr;
};

std::string results_table(const ReportData& data, const Json& json_rows, const Json& definitions,
                          const std::vector<std::size_t>& members) {
    // Extra columns: numeric in some row of this pattern, neither core nor hidden.
    std::vector<std::string> extra;
    std::set<std::string> core_keys;
    for (const CoreColumn& c : kCoreColumns) core_keys.insert(c.key);
    for (std::size_t r : members) {
        for (const auto& [key, value] : json_rows[r].items()) {
            if (core_keys.count(key) || kHiddenColumns.count(key) || value.is_boolean()) continue;
            if (value.is_number() || value.is_null()) {
                // null is a NaN number in a numeric column; a string column is never null.
                if (std::find(extra.begin(), extra.end(), key) == extra.end()) {
                    extra.push_back(key);
                }
            }
        }
    }
    // "nonfinite" is noise while it is 0 everywhere, and an alarm when it is not.
    std::erase_if(extra, [&](const std::string& key) {
        if (key != "nonfinite") return false;
        return std::all_of(members.begin(), members.end(),
                           [&](std::size_t r) { return json_number(json_rows[r][key]) == 0.0; });
    });

    auto definition = [&](const std::string& key) {
        return definitions.contains(key) && definitions[key].is_string()
                   ? xml_escape(definitions[key].get<std::string>())
                   : std::string();
    };
    std::string html = "<table class=\"results\"><thead><tr><th class=\"m\">method</th>";
    for (const CoreColumn& c : kCoreColumns) {
        html += fmt::format("<th title=\"{}\">{}</th>", definition(c.key), c.header);
    }
    for (const std::string& key : extra) {
        html += fmt::format("<th title=\"{}\">{}</th>", definition(key), xml_escape(key));
    }
    html += "</tr></thead>\n<tbody>\n";

    // Ordered by box_rmse, NaN last; ties keep run order.
    std::vector<std::size_t> order = members;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const double x = data.rows[a].box.rmse, y = data.rows[b].box.rmse;
        if (std::isnan(x) || std::isnan(y)) return !std::isnan(x) && std::isnan(y);
        return x < y;
    });
    for (std::size_t r : order) {
        const ResultRow& row = data.rows[r];
        html += fmt::format("<tr class=\"{}\"><td class=\"m\" title=\"own reference: {}\">{}</td>",
                            row.sweep_point ? "sweep" : "default", xml_escape(row.reference_filter),
                            xml_escape(row.method));
        for (const CoreColumn& c : kCoreColumns) {
            const double value = json_number(json_rows[r][c.key]);
            std::string title;
            if (std::string(c.key) == "box_max_abs") {
                title = fmt::format(" title=\"at ({}, {})\"", row.box.max_x, row.box.max_y);
            } else if (std::string(c.key) == "time_median_ns") {
                title = fmt::format(" title=\"min {:.4g} ms, max {:.4g} ms, {} runs, {}\"",
                                    row.time.min_ns * 1e-6, row.time.max_ns * 1e-6, row.time.runs,
                                    xml_escape(row.time_source));
            } else if (std::string(c.key) == "dropout") {
                title = fmt::format(" title=\"{} of {} pixels\"", row.box.dropout_pixels,
                                    row.box.dropout_candidates);
            }
            html += fmt::format("<td data-v=\"{}\"{}>{}</td>", exact_number(value), title,
                                shown(value, c.shown));
        }
        for (const std::string& key : extra) {
            const double value = json_rows[r].contains(key)
                                     ? json_number(json_rows[r][key])
                                     : std::numeric_limits<double>::quiet_NaN();
            html += fmt::format("<td data-v=\"{}\">{}</td>", exact_number(value),
                                shown(value, Shown::kGeneral));
        }
        html += "</tr>\n";
    }
    html += "</tbody></table>\n";
    return html;
}

// The colour bar of the error maps: the same knots as the maps, ticks at each decade. `name`
// (the pattern's) makes the gradient's id unique in the page.
std::string colour_bar(double scale, const std::string& name) {
    constexpr double kBarWidth = 240.0;
    constexpr double kX0 = 12.0;
    std::string stops;
    for (std::size_t k = 0; k < kDivergingKnots.size(); ++k) {
        stops +=
            fmt::format(R"~(<stop offset="{:.3f}" stop-color="#{:06x}"/>)~",
                        static_cast<double>(k) / (kDivergingKnots.size() - 1), kDivergingKnots[k]);
    }
    const std::string id = xml_escape("errbar-" + name);
    std::string svg = fmt::format(
        R"~(<svg xmlns="http://www.w3.org/2000/svg" width="264" height="52" font-size="10" )~"
        R"~(font-family="DejaVu Sans, Verdana, sans-serif"><defs><linearGradient id="{id}">{})~"
        R"~(</linearGradient></defs><rect x="{x:.0f}" y="4" width="{w:.0f}" height="14" )~"
        R"~(fill="url(#{id})" stroke="#999"/>)~",
        stops, fmt::arg("id", id), fmt::arg("x", kX0), fmt::arg("w", kBarWidth));
    for (int d = 0; d <= static_cast<int>(kErrorDecades); ++d) {
        const double value = scale * std::pow(10.0, -d);
        for (int sign : {-1, 1}) {
            if (d == static_cast<int>(kErrorDecades) && sign < 0) continue;
            const double x = kX0 + kBarWidth * error_position(sign * value, scale);
            const std::string label = d == static_cast<int>(kErrorDecades)
                                          ? std::string("0")
                                          : fmt::format("{:+g}", sign * value);
            svg +=
                fmt::format(R"~(<line x1="{x:.1f}" y1="18" x2="{x:.1f}" y2="22" stroke="#555"/>)~"
                            R"~(<text x="{x:.1f}" y="33" text-anchor="middle">{}</text>)~",
                            label, fmt::arg("x", x));
        }
    }
    svg += fmt::format(R"~(<text x="{:.0f}" y="47" fill="#555">log scale; |error| &lt; {:g} )~"
                       R"~(white, black NaN</text></svg>)~",
                       kX0, scale * std::pow(10.0, -kErrorDecades));
    return svg;
}

std::string img(const std::string& src, int width, int height, const std::string& alt) {
    return fmt::format(R"~(<img src="{}" width="{}" height="{}" alt="{}">)~", xml_escape(src),
                       width, height, xml_escape(alt));
}

// Writes the pattern's images and returns its figure grid.
std::string figure_grid(const fs::path& dir, const Section& section, const ReportData& data) {
    const PatternFigures& fig = *section.figures;
    const int width = fig.reference.width;
    const int height = fig.reference.height;
    const std::string rel = "images/" + section.name + "/";
    const fs::path image_dir = dir / "images" / section.name;
    std::error_code ec;
    fs::create_directories(image_dir, ec);
    if (ec) {
        throw InputError(
            fmt::format("{}: cannot create directory ({})", image_dir.string(), ec.message()));
    }

    // The scene names the focus; a scene of another size (not filled in) cannot.
    Scene sized;
    sized.width = width;
    sized.height = height;
    const bool scene_fits = fig.scene.width == width && fig.scene.height == height;
    std::string focus_note;
    const Rect focus = focus_region(scene_fits ? fig.scene : sized, focus_note);
    const int zoom = zoom_factor(focus);
    const int shown_scale = std::max(1, kThumbnailPx / width);
    const int view_w = width * shown_scale;
    const int view_h = height * shown_scale;
    const int zoom_w = focus.w * zoom;
    const int zoom_h = focus.h * zoom;
    const double scale = error_scale(fig);

    std::string html = fmt::format(
        "<p class=\"note\">Views: the linear values clamped to [0, 1] and sRGB-encoded (IEC "
        "61966-2-1 transfer function, 8 bits){}. Error = method &minus; exact box reference, "
        "colour-mapped (not transformed): blue too dark, red too bright, on one signed log "
        "scale for every method of this pattern (colour bar). Magnified: {}, x {}..{}, y "
        "{}..{} ({}&times;{} px), nearest-neighbour &times;{}, outlined in orange on the "
        "reference. EXR links: float32 linear data (the error is the method's EXR minus the "
        "reference's).</p>\n",
        shown_scale > 1 ? fmt::format(", shown at {}&times; (nearest neighbour)", shown_scale)
                        : std::string(),
        xml_escape(focus_note), focus.x, focus.x + focus.w, focus.y, focus.y + focus.h, focus.w,
        focus.h, zoom);
    html +=
        "<table class=\"figures\"><tr><th>image</th><th>error vs box reference</th><th>"
        "magnified</th><th>error, magnified</th></tr>\n";

    // Reference row: the image with the focus outlined, the colour bar, the magnified crop.
    const OIIO::ImageBuf reference_view = srgb_view(fig.reference);
    write_view(image_dir / "reference.png", reference_view);
    write_image((image_dir / "reference.exr").string(), to_float(fig.reference));
    write_view(image_dir / "reference.zoom.png", magnify(reference_view, focus, zoom));
    html += fmt::format(
        "<tr><td colspan=\"4\" class=\"caption\"><b>reference</b>: exact box coverage "
        "(computed in double) <a href=\"{r}reference.exr\">EXR</a></td></tr>\n<tr><td><span "
        "class=\"focusbox\">{}<span style=\"left:{:.3f}%;top:{:.3f}%;width:{:.3f}%;height:"
        "{:.3f}%\"></span></span></td><td>{}</td><td>{}</td><td></td></tr>\n",
        img(rel + "reference.png", view_w, view_h, "reference"), 100.0 * focus.x / width,
        100.0 * focus.y / height, 100.0 * focus.w / width, 100.0 * focus.h / height,
        colour_bar(scale, section.name),
        img(rel + "reference.zoom.png", zoom_w, zoom_h, "reference, magnified"),
        fmt::arg("r", rel));

    std::set<std::string> taken = {"reference"};
    for (std::size_t k = 0; k < fig.methods.size() && k < fig.images.size(); ++k) {
        const Image& image = fig.images[k];
        if (image.width != width || image.height != height) {
            throw InputError(fmt::format("report: {} on {} is {}x{}, the reference {}x{}",
                                         fig.methods[k], section.spec, image.width, image.height,
                                         width, height));
        }
        const std::string name = unique_name(slug(fig.methods[k]), taken);
        Image error(width, height);
        for (std::size_t p = 0; p < error.data.size(); ++p) {
            error.data[p] = static_cast<float>(image.data[p] - fig.reference.data[p]);
        }
        const OIIO::ImageBuf view = srgb_view(image);
        const OIIO::ImageBuf error_map = error_view(error, scale);
        write_view(image_dir / (name + ".png"), view);
        write_image((image_dir / (name + ".exr")).string(), image);
        write_view(image_dir / (name + ".error.png"), error_map);
        write_view(image_dir / (name + ".zoom.png"), magnify(view, focus, zoom));
        write_view(image_dir / (name + ".error.zoom.png"), magnify(error_map, focus, zoom));

        // The row's figures, when the run has it (it should: figures are of default rows).
        std::string figures_text;
        for (std::size_t r : section.rows) {
            const ResultRow& row = data.rows[r];
            if (row.method == fig.methods[k] && !row.sweep_point) {
                figures_text = fmt::format(
                    " &nbsp; box_rmse {:.4g}, max_abs {:.4g} at ({}, {}), "
                    "bias {:+.3g}, time {:.4g} ms",
                    row.box.rmse, row.box.max_abs, row.box.max_x, row.box.max_y, row.box.bias,
                    row.time.median_ns * 1e-6);
                break;
            }
        }
        const std::string spec = xml_escape(fig.methods[k]);
        html += fmt::format(
            "<tr><td colspan=\"4\" class=\"caption\"><b class=\"m\">{spec}</b>{} &nbsp; <a "
            "href=\"{r}{n}.exr\">EXR</a></td></tr>\n"
            "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
            figures_text, img(rel + name + ".png", view_w, view_h, fig.methods[k]),
            img(rel + name + ".error.png", view_w, view_h, fig.methods[k] + ", error"),
            img(rel + name + ".zoom.png", zoom_w, zoom_h, fig.methods[k] + ", magnified"),
            img(rel + name + ".error.zoom.png", zoom_w, zoom_h,
                fig.methods[k] + ", error magnified"),
            fmt::arg("spec", spec), fmt::arg("r", rel), fmt::arg("n", xml_escape(name)));
    }
    html += "</table>\n";
    return html;
}

std::string context_table(const RunContext& c) {
    std::string html = "<table class=\"context\">\n";
    const std::vector<std::pair<const char*, std::string>> items = {
        {"tool", c.tool},
        {"git revision", c.git_revision},
        {"build type", c.build_type},
        {"compiler", c.compiler},
        {"flags", c.flags},
        {"cpu", c.cpu},
        {"hardware threads", std::to_string(c.hardware_threads)},
        {"date (UTC)", c.date_utc},
    };
    for (const auto& [key, value] : items) {
        html +=
            fmt::format("<tr><td>{}</td><td class=\"m\">{}</td></tr>\n", key, xml_escape(value));
    }
    return html + "</table>\n";
}

}  // namespace

void write_html_report(const std::string& dir, const ReportData& data) {
    const fs::path base(dir);
    std::error_code ec;
    fs::create_directories(base / "plots", ec);
    if (ec) throw InputError(fmt::format("{}: cannot create directory ({})", dir, ec.message()));

    // One JSON rendering of the rows gives every column by name, including the ones added to
    // the result table after this file was written (report.cpp's result_columns()).
    const Json doc = Json::parse(compare_json(data.rows, data.context));
    const Json& json_rows = doc["rows"];
    const Json& definitions = doc["definitions"];

    // Sections: patterns in order of their first row, then figures of patterns without rows.
    std::vector<Section> sections;
    std::set<std::string> taken_names;
    auto section_for = [&](const std::string& spec, const std::string& id) -> Section& {
        for (Section& s : sections) {
            if (s.spec == spec) return s;
        }
        sections.push_back(
            {spec, id, unique_name(slug(id.empty() ? spec : id), taken_names), {}, nullptr});
        return sections.back();
    };
    for (std::size_t r = 0; r < data.rows.size(); ++r) {
        section_for(data.rows[r].pattern, data.rows[r].pattern_id).rows.push_back(r);
    }
    for (const PatternFigures& fig : data.figures) {
        Section& s = section_for(fig.pattern_spec, fig.pattern_id);
        if (!s.figures) s.figures = &fig;
    }

    const RunContext& c = data.context;
    std::string html = fmt::format(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<meta "
        "name=\"viewport\" content=\"width=device-width\">\n<title>aabench report{}</title>\n"
        "<style>{}</style>\n</head>\n<body>\n<h1>aabench: antialiasing accuracy against time</h1>\n"
        "<p class=\"small\">{} &middot; revision <code>{}</code> &middot; {} &middot; {}</p>\n"
        "<p>Reproduce this run:</p>\n<pre>{}</pre>\n",
        c.date_utc.empty() ? "" : " " + xml_escape(c.date_utc), kStyle, xml_escape(c.date_utc),
        xml_escape(c.git_revision), xml_escape(c.cpu), xml_escape(c.compiler),
        xml_escape(c.command));
    html += "<nav>";
    for (const Section& s : sections) {
        html += fmt::format("<a href=\"#{}\">{}</a>", xml_escape(s.name), xml_escape(s.name));
    }
    if (!data.hard_case_table.empty()) html += "<a href=\"#hard-cases\">hard cases</a>";
    html += "<a href=\"#context\">context</a></nav>\n";
    html +=
        "<p class=\"note\">Every number on this page was measured in this run (results.csv "
        "and results.json beside it hold them all, with their definitions). Tables are "
        "ordered by box_rmse; click a header to sort by it, hover over it for its "
        "definition. Times are single-threaded medians: compare them as ratios within "
        "this run.";
    const bool any_sweep = std::any_of(data.rows.begin(), data.rows.end(),
                                       [](const ResultRow& r) { return r.sweep_point; });
    if (any_sweep) {
        html +=
            " <label><input type=\"checkbox\" id=\"show-sweep\" checked> show sweep points "
            "(grey) in the tables</label>";
    }
    html += "</p>\n";

    for (const Section& s : sections) {
        html += fmt::format("<section id=\"{}\">\n<h2>{}</h2>\n<p class=\"small m\">{}",
                            xml_escape(s.name), xml_escape(s.id.empty() ? s.name : s.id),
                            xml_escape(s.spec));
        if (!s.rows.empty()) {
            const ResultRow& first = data.rows[s.rows.front()];
            html += fmt::format(" &middot; {}&times;{} px &middot; {} edges", first.width,
                                first.height, first.edges);
        }
        html += "</p>\n";
        if (!s.rows.empty()) {
            html += "<h3>Results</h3>\n" + results_table(data, json_rows, definitions, s.rows);
            std::vector<ResultRow> pattern_rows;
            for (std::size_t r : s.rows) pattern_rows.push_back(data.rows[r]);
            const std::string svg = accuracy_time_svg(
                pattern_rows,
                fmt::format("{}: accuracy against time", s.id.empty() ? s.name : s.id));
            const std::string plot_file = "plots/" + s.name + ".svg";
            write_text_file((base / plot_file).string(),
                            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + svg);
            html += fmt::format(
                "<h3>Accuracy against time <a class=\"small\" href=\"{}\">"
                "(SVG)</a></h3>\n<div class=\"plot\">{}</div>\n",
                xml_escape(plot_file), svg);
        }
        if (s.figures) html += "<h3>Images</h3>\n" + figure_grid(base, s, data);
        html += "</section>\n";
    }
    if (!data.hard_case_table.empty()) {
        html += fmt::format(
            "<section id=\"hard-cases\">\n<h2>Hard cases</h2>\n<pre>{}</pre>\n"
            "</section>\n",
            xml_escape(data.hard_case_table));
    }
    html += fmt::format(
        "<section id=\"context\">\n<h2>Context</h2>\n{}<p>Command:</p>\n"
        "<pre>{}</pre>\n</section>\n",
        context_table(c), xml_escape(c.command));
    html += fmt::format("<script>{}</script>\n</body>\n</html>\n", kScript);
    write_text_file((base / "index.html").string(), html);
}

}  // namespace aabench
