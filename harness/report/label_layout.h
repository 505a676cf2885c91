// Placing point labels on a plot so that none covers a marker or another label (the
// accuracy-time plot's "n=6" labels, harness/report/svg_plot.h). Pure geometry: boxes in, boxes
// out; text widths are estimated from the character count (the page's fonts are not known here).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace aabench {

struct LabelBox {
    double x0 = 0.0;
    double y0 = 0.0;
    double x1 = 0.0;
    double y1 = 0.0;
    bool overlaps(const LabelBox& o) const {
        return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }
};

// A marker the labels must keep clear of: a square round its centre.
struct Marker {
    double x = 0.0;
    double y = 0.0;
    double radius = 0.0;
    LabelBox box() const { return {x - radius, y - radius, x + radius, y + radius}; }
};

struct LabelRequest {
    Marker anchor;     // the labelled point
    std::string text;  // plain text (not escaped)
    double font_px = 10.0;
    bool bold = false;
};

// Where a label goes: its box, and where its text starts (SVG x, baseline y, text-anchor start);
// `leader` when it sits far enough from its point to need a line to it.
struct PlacedLabel {
    LabelBox box;
    double text_x = 0.0;
    double baseline_y = 0.0;
    bool leader = false;
};
// The point of `box` nearest (x, y): where a leader line from (x, y) meets the label.
std::pair<double, double> nearest_point(const LabelBox& box, double x, double y);

// The estimated box of `text` (width per character from DejaVu Sans's average advance, with
// room to spare) at font_px.
double label_width(const std::string& text, double font_px, bool bold);

// Places each request, in order, at the first of its candidate spots (right, left, above,
// below, then the diagonals, then the same further out, twice) that lies inside `frame` and covers
// no marker and no label placed before it; nullopt when none is free (the caller leaves that label
// out and says so).
std::vector<std::optional<PlacedLabel>> place_labels(const std::vector<LabelRequest>& requests,
                                                     const std::vector<Marker>& markers,
                                                     const LabelBox& frame);

}  // namespace aabench
