// SVG path data (the `d` attribute; SVG 1.1, "Path data", and its number grammar) read into
// closed contours of Bezier segments: the `svg_path` of scene file version 4
// (docs/scene-format.md, "Paths").
//
// Commands M m L l H h V v Q q T t C c S s Z z, absolute and relative, with implicit repeats
// (after a moveto, further pairs are linetos). Each subpath is a contour, closed for filling by
// a straight edge from its last point to its first (none when they coincide), whether or not
// it ends with Z. A subpath of a moveto alone, or of straight edges that enclose nothing (fewer
// than 3 distinct points), fills nothing and is dropped, as SVG renderers draw it. Arcs (A a)
// are refused: an elliptical arc is not a polynomial curve, and the exact references integrate
// polynomial segments only (convert arcs to cubics first, with a stated error, if you need
// them).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "patterns/scene/scene.h"

namespace aabench {

// A problem at a character offset (0-based) of the path data: the command or the first number
// of the segment at fault, or the token that is wrong. The scene reader names the JSON path and
// the character (1-based, as the JSON reader's byte positions are).
class SvgPathError : public std::runtime_error {
public:
    SvgPathError(std::size_t offset, const std::string& problem)
        : std::runtime_error(problem), offset_(offset) {}
    std::size_t offset() const { return offset_; }

private:
    std::size_t offset_;
};

// The contours of `d`; every coordinate's magnitude at most max_coordinate (after relative
// offsets are added). Throws SvgPathError.
std::vector<SegmentContour> parse_svg_path(std::string_view d, double max_coordinate);

}  // namespace aabench
