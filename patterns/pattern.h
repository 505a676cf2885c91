// The built-in test patterns. A generator is a pure function of (parameters, size): the same
// inputs give the same Scene, bit for bit, and the Scene's metadata records the generator's id,
// every resolved parameter and the size. All patterns are polygons except circles and
// circle-radii, whose rings are exact curves (with their polygonisation: patterns/scene/curves.h),
// and curves and crescents, whose shapes have Bezier segments (with their flattening:
// patterns/scene/bezier.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "patterns/scene/params.h"
#include "patterns/scene/scene.h"

namespace aabench {

struct PatternInfo {
    std::string id;
    std::string summary;
    std::vector<ParamSpec> params;
    std::function<Scene(const ParamValues&, int width, int height)> generate;
    // In the default run (`compare` without --patterns) and the benchmark's pattern set. The
    // edge patterns for Saito & Takahashi 1990's §4 and Fig. 6 (`mirror`, `terrain-edges`) are not,
    // so the default run and its baseline stay as they were; name them with --patterns.
    bool in_default_run = true;
    // Its shapes have Bezier segments (scene file version 4): the sweeps of the methods'
    // curve tolerances run on it (MethodInfo::sweep_on_curves_only).
    bool bezier = false;
    // It reads a model file of a Debian package (the mesh patterns: `bunny`, `horse`, `engine`,
    // `truck`): tens of thousands of triangles, and refused where the package is missing. The
    // test suites that loop over every pattern at their small sizes leave these out (each has
    // its own test, tests/mesh_patterns_test.cpp); they are never in the default run.
    bool model_file = false;
};

// The one table of patterns, in the order the comparison reports them.
const std::vector<PatternInfo>& pattern_registry();

// A row added at the end of the pattern registry for this object's lifetime, for tests that
// prove a new pattern needs nothing but its row (tests/pattern_registry_test.cpp), as
// ScopedMethodRow is for methods (methods/method.h). Not thread-safe: made and destroyed while
// nothing else reads the registry (a PatternInstance resolved before it may point into the
// table it replaced). Throws InputError when the id is taken, std::logic_error when the row
// has no generator.
class ScopedPatternRow {
public:
    explicit ScopedPatternRow(PatternInfo row);
    ~ScopedPatternRow();
    ScopedPatternRow(const ScopedPatternRow&) = delete;
    ScopedPatternRow& operator=(const ScopedPatternRow&) = delete;

private:
    std::string id_;
};

// A pattern spec looked up and checked: the registry row, the resolved parameters, and the
// canonical spec ("id:k=v,..." with every parameter). Throws InputError listing the valid ids
// for an unknown one, or naming the parameter and its range.
struct PatternInstance {
    const PatternInfo* info = nullptr;
    ParamValues params;
    std::string spec;
};
PatternInstance resolve_pattern(const std::string& spec);

// Resolves `ID[:k=v,...]`, checks the size, and generates the scene.
Scene make_pattern(const std::string& spec, int width, int height);

// Each generator file defines one of these; the registry lists them.
PatternInfo star_pattern();
PatternInfo strips_pattern();
PatternInfo grating_pattern();
PatternInfo rings_pattern();
PatternInfo zoneplate_pattern();
// Exact curves (scene.h: Shape::circle): the circle methods' patterns.
PatternInfo circles_pattern();
PatternInfo circle_radii_pattern();
// Bezier curves (scene.h: Shape::outline): curved petals and thin curved strips.
PatternInfo curves_pattern();
PatternInfo crescents_pattern();
// Colour (Scene::channels == 3): two Siemens stars, one of equal luma and one its control.
PatternInfo isoluminant_pattern();
// 3-D patterns (scene.world set; harness/world/ turns them into what methods draw).
PatternInfo room_pattern();
// A colour world (Scene::channels == 3): the room in colour, a warm and a cool light.
PatternInfo colour_room_pattern();
PatternInfo blocks_pattern();
PatternInfo interpenetrate_pattern();
PatternInfo mesh_pattern();
PatternInfo terrain_pattern();
PatternInfo torus_pattern();
PatternInfo checkerboard_pattern();
PatternInfo terrain_edges_pattern();
PatternInfo mirror_pattern();
PatternInfo foliage_pattern();
PatternInfo text_pattern();
PatternInfo text_cff_pattern();
PatternInfo text_page_pattern();
// 3-D models of Debian's model packages (glmark2-data, assimp-testmodels) through the mesh
// loader (patterns/scene/mesh_file.h): refused in one line naming the package when it is
// missing.
PatternInfo bunny_pattern();
PatternInfo horse_pattern();
PatternInfo engine_pattern();
PatternInfo truck_pattern();

// Shared by the generators: starts a Scene of the given size with the pattern's metadata
// (pattern id, resolved parameters, size) filled in.
Scene begin_pattern_scene(const std::string& id, const ParamValues& values, int width,
                          int height);

// Records the region a report should magnify (the pattern's hardest part) as metadata
// "focus" = "x,y,w,h" in whole pixels: a square of `side_px` centred near (cx, cy), moved
// inside the image and shrunk to fit it.
void set_focus(Scene& scene, double cx, double cy, int side_px);
inline constexpr int kFocusSidePx = 32;

// A Siemens star's wedge (patterns/star.cpp): the centre (cx, cy), then the arc of radius
// `radius_px` from angle `start` through `span` radians (y down, increasing angle), in chords
// within kMaxSagittaPx of the circle.
Contour star_wedge(double cx, double cy, double radius_px, double start, double span);

// Shared by the generators. The largest distance between a circle's polygon and the true
// circle (circle_contour's tolerance): far below what any method resolves.
inline constexpr double kMaxSagittaPx = 0.01;
// A scene with more vertices than this is refused: it would be hundreds of MB by the time
// methods build their edge lists, and is never a useful test.
inline constexpr std::size_t kMaxPatternVertices = 4'000'000;  // magnified 8x in a 256 px figure

// One shape of concentric annuli about (cx, cy): zone k is [inner, outer] = zone(k), k = 0, 1,
// ..., until a zone is narrower than min_zone_px. Outer circles run counter-clockwise, inner ones
// clockwise (holes under the nonzero rule); zone 0 is a disc. Vertices are counted as they are
// generated and the scene refused with InputError("<pattern>: more than N vertices; <advice>")
// past kMaxPatternVertices, so a refused scene costs bounded time and memory.
Shape concentric_annuli(double cx, double cy,
                        const std::function<std::pair<double, double>(long long)>& zone,
                        double min_zone_px, const std::string& pattern, const std::string& advice);

// A closed polygon approximating a circle (centre cx, cy; radius r), with enough vertices
// that the polygon stays within `max_sagitta_px` of the true circle. Counter-clockwise in
// the y-down frame when `clockwise` is false.
Contour circle_contour(double cx, double cy, double radius_px, double max_sagitta_px,
                       bool clockwise);

}  // namespace aabench
