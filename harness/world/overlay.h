// The overlay: patterns and shadows drawn as the scanline method of Nishita & Nakamae 1984
// (§3.2) takes them, coplanar polygons laid over their face, instead of cutting the face into
// disjoint cells (docs/world.md, "The overlay").
//
// Per visible face, in this order (the shape order breaks ties within one role):
//   the face itself, whole (role face, the face's reflectance);
//   each pattern clipped to the face, in the scene's order (role pattern, its reflectance;
//   a later pattern lies over an earlier one, as in the cells);
//   the shadow layer (role shadow): the area some shadow covers, cut into disjoint convex
//   cells, each carrying the lights it hides and the reflectance of what lies under it (the
//   topmost pattern there, else the face).
// The scanline's tie order (shadow, pattern, face in front on one face) then shows at each
// point what the cells show there: the shadow layer where a shadow falls, else the topmost
// pattern, else the face. Why the shadow layer and not a bare shadow polygon: a pattern in
// shadow keeps its reflectance and loses the light, so where a shadow overlaps a pattern the
// polygon seen must carry the pattern's reflectance (and where two lights' shadows overlap,
// both lights' loss). Only the shadows are cut (by each other and by the patterns under
// them): the face and its patterns are not.
#pragma once

#include <cstddef>
#include <vector>

#include "harness/world/stages.h"

namespace aabench {

// Above this many shadows on one face, its shadow layer is the shadowed part of the face cut
// as the cells stage cuts it (the same region, cut along other lines; overlay.cpp says why).
inline constexpr std::size_t kCutLayerShadows = 64;

struct OverlayStats {
    std::size_t faces = 0;         // face polygons
    std::size_t patterns = 0;      // pattern polygons
    std::size_t shadow_cells = 0;  // cells of the shadow layers
};

// The overlay's cells per face (index as `faces`), unshaded (value = reflectance), in the order
// above. `shadows` is the shadow stage's (find_shadows); empty when the plan has no shadows.
std::vector<std::vector<Cell>> overlay_cells(const World& world,
                                             const std::vector<WorldFace>& faces,
                                             const ShadowsByFace& shadows, bool patterns_on,
                                             OverlayStats* stats = nullptr);

}  // namespace aabench
