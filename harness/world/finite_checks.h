// No silent non-finite value: every world stage's output is checked before the next stage (or a
// method) reads it, and a non-finite number stops the job with a one-line InputError naming
// the stage and the face (docs/world.md, "No silent non-finite value"). The scene reader
// refuses what it can name by JSON path (a point light at a face's centroid, coordinates past
// 1e100); these checks catch what only a stage's arithmetic shows (a World built in code, an
// overflow in a product the reader does not form).
#pragma once

#include <string_view>
#include <vector>

#include "harness/world/stages.h"
#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// The faces' frames and loops after projection's first half (and culling).
void check_finite_faces(std::string_view stage, const std::vector<WorldFace>& faces);
// The cells of every face after patterns, shadows or shading.
void check_finite_cells(std::string_view stage, const std::vector<WorldFace>& faces,
                        const std::vector<std::vector<Cell>>& cells);
// A ScreenScene, the visible pieces, the overlay or a depth scene: every vertex, value, value
// plane and depth plane. Shape::face indexes `faces` (every shape of a world has one).
void check_finite_shapes(std::string_view stage, const std::vector<WorldFace>& faces,
                         const Scene& scene);
// An image a stage made (the optical-path depth): names the first non-finite pixel.
void check_finite_image(std::string_view stage, const Image& image);

}  // namespace aabench
