#include "patterns/scene/world.h"

#include <cmath>

#include "patterns/scene/stable_length.h"

namespace aabench {

std::size_t World::face_count() const {
    std::size_t n = 0;
    for (const Object& o : objects) n += o.faces.size();
    return n;
}

bool World::is_colour() const {
    if (ambient_rgb) return true;
    for (const Light& l : lights) {
        if (l.intensity_rgb) return true;
    }
    for (const Object& o : objects) {
        for (const Face& f : o.faces) {
            if (f.reflectance_rgb) return true;
            for (const FacePattern& p : f.patterns) {
                if (p.reflectance_rgb) return true;
            }
        }
    }
    return false;
}

World channel_world(const World& world, int c) {
    if (!world.is_colour()) return world;
    World out = world;
    const auto take = [c](double& grey, std::optional<Rgb>& rgb) {
        grey = channel_of(grey, rgb, c);
        rgb.reset();
    };
    take(out.ambient, out.ambient_rgb);
    for (Light& l : out.lights) take(l.intensity, l.intensity_rgb);
    for (Object& o : out.objects) {
        for (Face& f : o.faces) {
            take(f.reflectance, f.reflectance_rgb);
            for (FacePattern& p : f.patterns) take(p.reflectance, p.reflectance_rgb);
        }
    }
    return out;
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
