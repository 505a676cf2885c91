// The Scene data model: what every pattern generator returns, what the scene file holds, and
// what every method and reference consumes. See docs/scene-format.md for the file format.
//
// Conventions (docs/architecture.md): geometry is double, in pixel units; pixel (i, j) covers
// [i, i+1] x [j, j+1] (shifted by the window origin, Scene::origin_x/y); y grows down, row 0
// is the top row. A shape is one or more closed contours filled by the nonzero winding rule
// over all of its contours; shapes composite in order, a later shape covering an earlier one
// where they overlap.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "patterns/scene/rgb.h"
#include "patterns/scene/scene_sequence.h"
#include "patterns/scene/world.h"

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

// An affine function of the position in the pixel frame: c + gx * x + gy * y.
struct AffinePlane {
    double c = 0.0;
    double gx = 0.0;
    double gy = 0.0;
    double at(double x, double y) const { return c + gx * x + gy * y; }
    bool operator==(const AffinePlane&) const = default;
};

// What a piece of a ScreenScene is on its face (Nishita & Nakamae's tie order on coincident
// crossings, section 3.2, and the reports).
enum class ShapeRole : std::uint8_t { kFace, kPattern, kShadow };

// An exact curve (scene file version 2, `disc` and `ring`): the points whose distance from
// `center` lies in [inner, outer]. A disc has inner == 0. See patterns/scene/curves.h.
struct Circle {
    Point center;
    double inner = 0.0;
    double outer = 0.0;
    bool is_disc() const { return inner == 0.0; }
    bool operator==(const Circle&) const = default;
};

// One boundary segment of a shape drawn with Bezier curves (scene file version 4): degree 1 a
// straight edge p[0] -> p[1], degree 2 a quadratic Bezier (p[0], control p[1], end p[2]), degree 3
// a cubic (p[0], p[1], p[2], p[3]). p[0] is where the previous segment ended; the points past
// p[degree] are zero. See patterns/scene/bezier.h.
struct Segment {
    int degree = 1;
    std::array<Point, 4> p{};
    const Point& start() const { return p[0]; }
    const Point& end() const { return p[static_cast<std::size_t>(degree)]; }
    bool operator==(const Segment&) const = default;
};

// A closed boundary of segments, each starting where the one before it ends and the last
// ending where the first starts (the closing edge is a segment of its own).
using SegmentContour = std::vector<Segment>;

struct Shape {
    std::vector<Contour> contours;
    // The shape's value; in a colour scene (Scene::channels == 3) its luminance, so that code
    // that reads one value per shape draws and measures the luminance image of the scene (every
    // method and reference is linear in the values: docs/colour.md).
    double value = 1.0;
    // In a colour scene, the shape's colour (its value per channel); unset for a grey shape,
    // whose value is then the same in every channel. Unset in every grey scene.
    std::optional<Rgb> rgb;
    // The ScreenScene's additions (docs/world.md, "The ScreenScene"); a 2-D shape has
    // none of them and keeps the 2-D rule (a later shape covers an earlier one).
    // 1/z_v as an affine function of the screen position (exact for a planar face under
    // perspective): where two shapes overlap, the larger inv_depth is nearer and is seen.
    std::optional<AffinePlane> inv_depth;
    // An affine value (depth images: z_s = f d / z_v); when set, `value` is not used.
    std::optional<AffinePlane> value_plane;
    int face = -1;  // the face it lies on (index in the ScreenScene's face list), -1 for 2-D
    ShapeRole role = ShapeRole::kFace;
    // A disc or ring, exact. Its `contours` then hold the polygonisation made by
    // patterns/scene/curves.h (sagitta <= kCurveSagittaPx), which is all that methods and
    // references without curve support see; those with it (the box reference, aa-circle,
    // wu-circle, midpoint-circle) read this instead.
    std::optional<Circle> circle;
    // A shape with Bezier segments (version 4 curve items and `svg_path`): its exact boundary,
    // every contour of the shape as segments. Its `contours` then hold the flattening made by
    // patterns/scene/bezier.h (deviation <= kBezierViewFlatnessPx), which is what methods and
    // references without Bezier support see; those with it read this instead. Empty for
    // every other shape.
    std::vector<SegmentContour> outline;
    bool operator==(const Shape&) const = default;
};

// An object whose survival is measured (captured mass, popping: harness/measure/symptoms.h): a shape
// measured on its own, rendered alone on the scene's background. It is a copy of (or a piece
// of) what the scene's shapes draw, not drawn itself. Built-in patterns fill these (each strip,
// each spoke tip); scene files carry none (docs/scene-format.md).
struct ThinObject {
    std::string label;  // names the object in reports, e.g. "strip w=0.05 a=1°", "tip 3"
    Shape shape;
    bool operator==(const ThinObject&) const = default;
};

// Ordered key/value pairs: the generator's id, its resolved parameters, the size.
using Metadata = std::vector<std::pair<std::string, std::string>>;

struct Scene {
    int width = 0;
    int height = 0;
    // Where the image window lies in scene coordinates: pixel (i, j) covers
    // [origin_x + i, origin_x + i + 1] x [origin_y + j, origin_y + j + 1]. Zero for every
    // built-in pattern; a scene file may set it ("origin", docs/scene-format.md) to place the
    // window far from 0 (the hard cases put it at 2^20 and 2^30 px). Methods, references and
    // metrics never see it: harness/world's prepared frame takes it out first (see
    // in_window_frame() below).
    double origin_x = 0.0;
    double origin_y = 0.0;
    double background = 0.0;  // in a colour scene, its luminance (as Shape::value)
    // 1 for a grey scene, 3 for a colour scene (linear R, G, B): a scene file with any colour
    // array, or a colour pattern. The images of a colour scene have three planes.
    int channels = 1;
    std::optional<Rgb> background_rgb;  // a colour scene's background, unset when grey
    std::vector<Shape> shapes;
    Metadata metadata;
    std::vector<ThinObject> thin_objects;  // measured, not drawn (see ThinObject)
    // A 3-D scene (file version 2 with "objects", or a 3-D pattern): shapes stay empty until
    // harness/world/ projects the world into a ScreenScene. Methods never see a world.
    std::optional<World> world;
    // A scene file's motion over frames (version 3, "sequence"): the scene is frame 0 of it.
    // Only a sequence run (`compare --sequences --scenes`, harness/world/sequence.h) moves it;
    // everything else reads the scene as it is. Built-in patterns have none.
    std::optional<SceneSequence> sequence;
    // What a producer knows of the shapes beyond this (exact visibility's disjoint pieces)
    // travels beside the scene, in a SceneInput (patterns/scene/scene_input.h).

    bool operator==(const Scene&) const = default;

    // Number of contour edges (closing edges included), for edges/s figures.
    std::size_t edge_count() const;
    // Smallest and largest of the background and the shape values: every method's output
    // must lie within them (up to its own rounding).
    std::pair<double, double> value_range() const;
};

// True when the window origin is (0, 0), so that pixel (i, j) covers [i, i+1] x [j, j+1]: the
// precondition of every method, reference and metric (methods/method.h), which
// in_window_frame() below establishes.
inline bool is_window_frame(const Scene& scene) {
    return scene.origin_x == 0.0 && scene.origin_y == 0.0;
}

// Throws std::logic_error naming `who` unless is_window_frame(scene): the entry check of
// methods, references and metrics, one comparison per call. A caller that skipped the prepared
// frame would otherwise draw or measure the wrong part of the plane, silently.
void require_window_frame(const Scene& scene, const char* who);

// The value of `shape` in channel `c` of a colour scene (its rgb, or its grey value), and the
// background's.
inline double channel_value(const Shape& shape, int c) {
    return shape.rgb ? (*shape.rgb)[static_cast<std::size_t>(c)] : shape.value;
}
inline double channel_background(const Scene& scene, int c) {
    return scene.background_rgb ? (*scene.background_rgb)[static_cast<std::size_t>(c)]
                                : scene.background;
}

// Channel `c` (0 R, 1 G, 2 B) of a colour scene as a grey scene: every value replaced by its
// value in that channel, colours dropped. Every method and reference is linear in the values,
// so the channel's image is the grey image of this scene. A grey scene is returned as it is.
// A colour world's scene gives its channel world (channel_world, patterns/scene/world.h).
Scene channel_scene(const Scene& scene, int c);

// True when some shape carries a depth plane (a ScreenScene of a 3-D world).
bool has_depth_planes(const Scene& scene);

// Copies of everything but the bulk: the scene without its shapes, the shape without its
// contours (for code that builds new shapes from old ones: exact visibility writes a quarter
// of a million pieces of a 200,000-shape scene, and copying the shapes to drop them was a
// tenth of its time). Each names every other field of its struct: keep them in step with
// Shape and Scene (tests/scene_copy_test.cpp sets every field).
Scene without_shapes(const Scene& scene);
Shape without_contours(const Shape& shape);

// The scene in window coordinates: the origin subtracted from every vertex (shapes and thin
// objects) and set to zero, so that pixel (i, j) covers [i, i+1] x [j, j+1] again. The
// prepared frame calls it once per scene (harness/world/frame.h; docs/world.md, "The prepared
// frame"), and hands methods, references and metrics only its result, so no other code
// handles an origin. Why one subtraction per coordinate is as good as exact: see
// patterns/scene/scene.cpp.
Scene in_window_frame(const Scene& scene);

// Twice the signed (shoelace) area of a closed contour, summed about its first vertex (smaller
// terms than about the origin, so little cancellation for coordinates far from it). Positive
// for clockwise contours in the y-down frame.
double twice_signed_area(const Contour& contour);

// Size limits checked before anything is allocated (docs/scene-format.md).
inline constexpr int kMaxImageSide = 65536;
inline constexpr long long kMaxImagePixels = 1LL << 26;  // 64 Mpixel: 256 MiB as float32
// Vertices in one scene (all contours of all shapes). The scene reader counts them while it
// parses and stops at the first one past the limit, before the tree holding them grows further:
// a scene at the limit takes about 1.5 GB to parse and 256 MiB as a Scene (docs/limits.md).
inline constexpr long long kMaxSceneVertices = 1LL << 24;  // 16,777,216
// Coordinates (and the window origin) within +-1e300 px: the difference of two coordinates
// must stay finite, which near DBL_MAX (1.8e308) it does not. The reader refuses larger ones.
inline constexpr double kMaxCoordinate = 1e300;
// Values (a background, a shape's value, a world's shaded values) within +-1e30: every image is
// float32 (largest 3.4e38), and a value past it becomes inf in the image; methods sum weighted
// samples and post-process passes sum neighbourhoods in float, so eight decades stay spare. The
// reader refuses larger ones, and the world stages refuse a shaded value past it.
inline constexpr double kMaxValue = 1e30;

// Throws InputError naming `where` if width x height is outside the limits above.
void check_image_size(long long width, long long height, const std::string& where);

}  // namespace aabench
