// How many shadows the shadow stage finds on an object's first face, seen at width x height:
// for tests that must know a face is past the overlay's cut-layer threshold.
#pragma once

#include <cstddef>
#include <vector>

#include "harness/world/stages.h"

namespace aabench::testing {

inline std::size_t shadows_on_first_face(const World& w, int width, int height, int object) {
    const std::vector<WorldFace> faces = collect_faces(w, ViewSetup::from(w.camera, width, height));
    const ShadowsByFace shadows = find_shadows(w, faces);
    for (std::size_t k = 0; k < faces.size(); ++k) {
        if (faces[k].object == object && faces[k].index == 0) return shadows[k].size();
    }
    return 0;
}

}  // namespace aabench::testing
