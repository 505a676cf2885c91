// The parts of the HTML report (harness/report/html_report.h) that its three files share: the
// page (html_report.cpp), the summary tables (html_table.cpp), the figure grid (html_figures.cpp).
// Internal to harness/report: nothing outside the report stage includes this.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <cstddef>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "harness/report/html_report.h"

namespace aabench::html_parts {

// One pattern's part of the page: its rows (indices into ReportData::rows) and its figures.
struct Section {
    std::string spec;
    std::string id;
    std::string name;  // file and anchor name
    std::vector<std::size_t> rows;
    const PatternFigures* figures = nullptr;
};

// A file name from a spec: letters, digits and ".-=_" kept, everything else (':', ',', '/')
// becomes '_'. Collisions are resolved by the caller.
std::string slug(const std::string& text);

// `wanted`, or wanted-2, wanted-3, ... if already taken; the result is then taken.
std::string unique_name(const std::string& wanted, std::set<std::string>& taken);

// The results table of one pattern's rows (`members`, indices into data.rows; rows of methods
// that cannot draw the pattern are left out), inside its own scrolling box: the metric
// registry's columns for the HTML table that some row has a value in, the definitions as the
// headers' hover text.
std::string results_table(const ReportData& data, const std::vector<std::size_t>& members);

// The report's summary (html_summary.cpp): the method-family x pattern matrix of the default
// parameters over `sections` (box error, own-filter error, time; coloured per pattern, the best
// marked, sweep points folded under their family), the families that cannot draw some pattern
// in one line, and the generated "which method for what" paragraph. Empty without rows.
std::string summary_section(const ReportData& data, const std::vector<Section>& sections);

// The rows of `members` whose method can draw the pattern (the others have no figures), and
// one line naming the others with their reasons (empty when there are none).
std::vector<std::size_t> drawn_rows(const ReportData& data, const std::vector<std::size_t>& members);
std::string cannot_draw_line(const ReportData& data, const std::vector<std::size_t>& members);

// The cost of each world stage of a 3-D pattern (any of its rows), or empty for a 2-D one.
std::string stage_table(const ResultRow& row);

// Writes the section's images under dir/images/<name>/ and returns its figure grid.
std::string figure_grid(const std::filesystem::path& dir, const Section& section,
                        const ReportData& data);

// Shared by the figure grids (html_figures.cpp, html_edges.cpp): the 8-bit sRGB view of linear
// values clamped to [0, 1]; a signed map on the error maps' diverging colours and log scale
// (|v| >= scale full colour), with its colour bar; a PNG of a view; an <img> tag.
OIIO::ImageBuf display_view(const Image& image);
OIIO::ImageBuf signed_view(const Image& values, double scale);
std::string signed_colour_bar(double scale, const std::string& name);
void write_png_view(const std::filesystem::path& path, const OIIO::ImageBuf& view);
// The views' first channel side by side, left to right, 4 white pixels apart, top-aligned,
// as one PNG (the comparison strips, the sequences' filmstrips); nothing when all are empty.
void write_strip(const std::filesystem::path& path, const std::vector<OIIO::ImageBuf>& views);
std::string img_tag(const std::string& src, int width, int height, const std::string& alt);

// The edge figures of a scene with `edges` (Saito & Takahashi 1990; docs/edges.md): the exact
// depth image, p, e, both composites, the line image and the ground truth. Empty when the section
// has none.
std::string edge_figure_grid(const std::filesystem::path& dir, const Section& section);

}  // namespace aabench::html_parts
