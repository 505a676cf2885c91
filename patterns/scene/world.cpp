#include "patterns/scene/world.h"

#include <cmath>

#include "patterns/scene/stable_length.h"

namespace aabench {

std::size_t World::face_count() const {
    std::size_t n = 0;
    for (const Object& o : objects) n += o.faces.size();
    return n;
}

glm::dvec3 face_normal(const Object& object, const Face& face) {
    // Newell's method: the sum over the loop's edges of the cross products about the first
    // vertex is twice the vector area; exact for planar loops and robust for near-collinear
    // neighbours, where a single cross product would not be.
    glm::dvec3 n(0.0);
    const std::size_t k = face.loop.size();
    if (k < 3) return n;
    const glm::dvec3 o = object.vertices[face.loop[0]];
    for (std::size_t i = 1; i + 1 < k; ++i) {
        n += glm::cross(object.vertices[face.loop[i]] - o, object.vertices[face.loop[i + 1]] - o);
    }
    const double len = stable_length(n);
    return len > 0.0 ? n / len : glm::dvec3(0.0);
}

}  // namespace aabench
