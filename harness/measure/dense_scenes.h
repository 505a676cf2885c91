// The benchmark's dense scenes: what users draw beyond the built-in patterns' defaults, for
// aabench_bench's grid and its cost model (docs/benchmarks.md, "Dense scenes").
//   dense-rings      rings of 0.85 px at 1.7 px pitch (`rings:period=1.7`), circles within
//                    0.01 px sagitta: about 190,000 edges at 1024^2
//   dense-zoneplate  a zone plate reaching Nyquist at 0.3 of the half side
//                    (`zoneplate:nyquist_radius=0.3`): narrowest zones 0.31 px
//   soup             overlapping random polygons (3 to 12 vertices, either orientation,
//                    some self-intersecting) of four values on a grey background
//   glyphs           many small glyph-like outlines (about 9 x 12 px: rings with holes, bars,
//                    chevrons, crossed strokes in one shape) in lines of text, one shape each
// Deterministic: the random scenes come from a fixed seed and a generator whose output the C++
// standard fixes (std::mt19937), mapped to doubles here rather than by a library distribution.
#pragma once

#include <string>
#include <vector>

#include "patterns/scene/scene.h"

namespace aabench {

// The names above, in that order.
const std::vector<std::string>& dense_scene_names();

// The scene `name` at side x side pixels; throws std::invalid_argument for another name.
Scene make_dense_scene(const std::string& name, int side);

}  // namespace aabench
