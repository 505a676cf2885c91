// The Scene data model: what every pattern generator returns, what the scene file holds, and
// what every method and reference consumes. See docs/scene-format.md for the file format.
//
// Conventions (DESIGN.md): geometry is double, in pixel units; pixel (i, j) covers
// [i, i+1] x [j, j+1]; y grows down, row 0 is the top row. A shape is one or more closed
// contours filled by the nonzero winding rule over all of its contours; shapes composite in
// order, a later shape covering an earlier one where they overlap.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace aabench {

// Bad input from a user (scene file, spec string, argument): a one-line message that names
// what is wrong and where. The CLI turns it into exit code 2.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Point {
    double x = 0.0;
    double y = 0.0;
    bool operator==(const Point&) const = default;
};

using Contour = std::vector<Point>;  // closed implicitly: the last point joins the first

struct Shape {
    std::vector<Contour> contours;
    double value = 1.0;
    bool operator==(const Shape&) const = default;
};

// Ordered key/value pairs: the generator's id, its resolved parameters, the size.
using Metadata = std::vector<std::pair<std::string, std::string>>;

struct Scene {
    int width = 0;
    int height = 0;
    double background = 0.0;
    std::vector<Shape> shapes;
    Metadata metadata;

    bool operator==(const Scene&) const = default;

    // Number of contour edges (closing edges included), for edges/s figures.
    std::size_t edge_count() const;
    // Smallest and largest of the background and the shape values: every method's output
    // must lie within them (up to its own rounding).
    std::pair<double, double> value_range() const;
};

// Size limits checked before anything is allocated (docs/scene-format.md).
inline constexpr int kMaxImageSide = 65536;
inline constexpr long long kMaxImagePixels = 1LL << 26;  // 64 Mpixel: 256 MiB as float32

// Throws InputError naming `where` if width x height is outside the limits above.
void check_image_size(long long width, long long height, const std::string& where);

}  // namespace aabench
