// The conflation figure (docs/metrics.md, `conflation`): for a method with a `paths` choice
// (the peers cairo and agg: methods/scan/kernel/peer_coverage.h), the rmse between its image and
// the image of the same method at the other choice — one fill per run of shapes of one value
// against one fill per shape, the coverage compositing where shapes meet adds or removes.
#pragma once

#include <optional>
#include <string>

#include "methods/method.h"

namespace aabench {

// The full spec of `method` with its `paths` choice swapped (merged <-> per-shape), every
// other parameter kept; nullopt for a method without that parameter.
std::optional<std::string> conflation_twin_spec(const MethodInstance& method);

// rmse between `out` (the method's image of `scene`) and the twin's image of `scene`;
// nullopt for a method without a twin.
std::optional<double> conflation_rmse(const MethodInstance& method, const SceneInput& scene,
                                      const Image& out);

}  // namespace aabench
