// Grid circles and the eight-way plotter (circle_raster.h).
#include "methods/scan/circles/circle_raster.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aabench {
namespace {

// x is an integer plus 1/2 (exactly: both steps are exact in double for |x| < 2^51).
bool half_integer(double x) { return std::abs(x) < 1e15 && x - 0.5 == std::floor(x - 0.5); }

}  // namespace

std::string grid_circles(const Scene& scene, std::vector<GridCircle>* circles) {
    if (circles) circles->clear();
    for (std::size_t k = 0; k < scene.shapes.size(); ++k) {
        const Shape& s = scene.shapes[k];
        if (!s.circle) return fmt::format("shape {} is a polygon; this method draws circles only", k);
        if (s.inv_depth || s.value_plane) return fmt::format("shape {} has a plane", k);
        const Circle& c = *s.circle;
        // A circle that cannot reach the window (2 px margin for the octant walk's pixels)
        // draws nothing: left out before the checks below, so that a band of render_in_bands
        // (the window moved by whole rows) never refuses what the whole image accepts.
        if (c.center.x - c.outer > scene.width + 2.0 || c.center.x + c.outer < -2.0 ||
            c.center.y - c.outer > scene.height + 2.0 || c.center.y + c.outer < -2.0) {
            continue;
        }
        // The pixel indices below are ints: a centre moved far by a window origin is refused
        // rather than overflow them (scene files keep centres within 1e9 px).
        if (!(std::abs(c.center.x) <= kMaxGridCentre && std::abs(c.center.y) <= kMaxGridCentre)) {
            return fmt::format("shape {}: centre ({}, {}) is beyond {} px of the window", k,
                               c.center.x, c.center.y, kMaxGridCentre);
        }
        if (!half_integer(c.center.x) || !half_integer(c.center.y)) {
            return fmt::format("shape {}: centre ({}, {}) is not a pixel centre (integer + 1/2)", k,
                               c.center.x, c.center.y);
        }
        int radius = -1;
        if (c.is_disc()) {
            if (c.outer == 0.5) radius = 0;  // the point: the disc of radius 1/2
        } else {
            const double r = c.outer - 0.5;
            if (c.inner == r - 0.5 && r == std::floor(r) && r >= 1.0 && r <= kMaxGridRadius) {
                radius = static_cast<int>(r);
            }
        }
        if (radius < 0) {
            return fmt::format(
                "shape {} is not a one-pixel-wide ring of integer radius (inner r - 1/2, outer "
                "r + 1/2) nor the point (disc of radius 1/2)",
                k);
        }
        if (circles) {
            circles->push_back({static_cast<int>(std::floor(c.center.x)),
                                static_cast<int>(std::floor(c.center.y)), radius, s.value});
        }
    }
    return {};
}

namespace {
std::vector<float>& thread_alpha() {
    thread_local std::vector<float> alpha;
    return alpha;
}
std::vector<std::size_t>& thread_touched() {
    thread_local std::vector<std::size_t> touched;
    return touched;
}
}  // namespace

CirclePlotter::CirclePlotter(Image& out, int row_lo, int row_hi)
    : out_(out),
      row_lo_(row_lo),
      row_hi_(row_hi),
      alpha_(thread_alpha()),
      touched_(thread_touched()) {
    // alpha_ is all zero between plotters (flush and the destructor clear what they touch).
    if (alpha_.size() < out.data.size()) alpha_.resize(out.data.size(), 0.0f);
}

CirclePlotter::~CirclePlotter() {
    for (std::size_t p : touched_) alpha_[p] = 0.0f;
    touched_.clear();
}

std::string grid_circles_scratch(const Scene& scene, const std::vector<GridCircle>*& circles) {
    thread_local std::vector<GridCircle> scratch;
    circles = &scratch;
    return grid_circles(scene, &scratch);
}

void CirclePlotter::plot(int i, int j, float alpha) {
    if (i < 0 || j < row_lo_ || i >= out_.width || j >= row_hi_ || !(alpha > 0.0f)) return;
    const std::size_t p = static_cast<std::size_t>(j) * out_.width + i;
    if (alpha_[p] == 0.0f) touched_.push_back(p);
    alpha_[p] = std::max(alpha_[p], alpha);
}

void CirclePlotter::plot8(int cx, int cy, int x, int y, float alpha) {
    plot(cx + x, cy + y, alpha);
    plot(cx - x, cy + y, alpha);
    plot(cx + x, cy - y, alpha);
    plot(cx - x, cy - y, alpha);
    plot(cx + y, cy + x, alpha);
    plot(cx - y, cy + x, alpha);
    plot(cx + y, cy - x, alpha);
    plot(cx - y, cy - x, alpha);
}

void CirclePlotter::flush(double value) {
    for (std::size_t p : touched_) {
        const double under = out_.data[p];
        out_.data[p] = static_cast<float>(under + (value - under) * alpha_[p]);
        alpha_[p] = 0.0f;
    }
    touched_.clear();
}

void fill_for_circles(const Scene& scene, const std::string& reason, Image& out, int row_lo,
                      int row_hi) {
    const float fill = reason.empty() ? static_cast<float>(scene.background)
                                      : std::numeric_limits<float>::quiet_NaN();
    std::fill(out.row(row_lo),
              out.row(row_lo) + static_cast<std::size_t>(row_hi - row_lo) * out.width, fill);
}

}  // namespace aabench
