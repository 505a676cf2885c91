// Exact radial-filter references: for every pixel, the integral of a radial filter centred on
// the pixel centre (i + 0.5, j + 0.5) times the scene's visible value, the filter normalised
// to unit volume over its support. Exact to <= 1e-10 per pixel (in practice ~1e-14); see the
// essay at the top of filter_reference.cpp and docs/references.md. The scene is in its window
// frame, as for the box reference (harness/reference/box_reference.h).
//
// The filters and their parameters: methods/scan/kernel/filter.h.
#pragma once

#include <string>
#include <vector>

#include "methods/scan/kernel/filter.h"
#include "methods/scan/kernel/image.h"
#include "patterns/scene/params.h"
#include "patterns/scene/scene.h"
#include "patterns/scene/scene_input.h"

namespace aabench {

// The value at every pixel centre of a radial `filter` (std::invalid_argument for the box:
// exact_reference() takes any). Cost O(jump-set length x R^2 + pixels); see the .cpp.
Coverage filtered_reference(const Scene& scene, const Filter& filter);

// Any reference by spec: "box" (the exact box reference, harness/reference/box_reference.h) or a
// radial filter spec, as Filter::parse() reads it (InputError listing the valid filters).
Coverage exact_reference(const SceneInput& in, const std::string& filter_spec);
Coverage exact_reference(const SceneInput& in, const Filter& filter);
// Every plane of the reference: a colour scene's three channels (each the reference of its grey
// channel scene, in.channel(c) or channel_scene: every reference is linear in the values), a
// grey scene's one.
CoveragePlanes exact_reference_planes(const SceneInput& in, const Filter& filter);

// The canonical form of a reference spec (Filter::text()), so equal filters written
// differently share one reference computation.
std::string canonical_reference_spec(const std::string& filter_spec);

}  // namespace aabench
