// without_shapes() and without_contours() (patterns/scene/scene.h): every other field copied.
// Each test sets every field of the struct away from its default, so a field the copy forgets
// shows as a difference.
#include <gtest/gtest.h>

#include "patterns/scene/scene.h"

namespace aabench {
namespace {

Shape every_field_set() {
    Shape s;
    s.contours = {{{0, 0}, {4, 0}, {0, 3}}, {{1, 1}, {2, 1}, {1, 2}}};
    s.value = 0.375;
    s.rgb = Rgb{0.5, 0.25, 0.125};
    s.inv_depth = AffinePlane{0.5, 0.25, -0.125};
    s.value_plane = AffinePlane{1.0, -2.0, 3.0};
    s.face = 7;
    s.role = ShapeRole::kShadow;
    s.circle = Circle{{2.5, 3.5}, 1.0, 2.0};
    return s;
}

TEST(SceneCopy, WithoutContoursKeepsEveryOtherField) {
    const Shape s = every_field_set();
    Shape expected = s;
    expected.contours.clear();
    EXPECT_EQ(without_contours(s), expected);
}

TEST(SceneCopy, WithoutShapesKeepsEveryOtherField) {
    Scene s;
    s.width = 33;
    s.height = 17;
    s.origin_x = 1024.0;
    s.origin_y = -2048.0;
    s.background = 0.125;
    s.channels = 3;
    s.background_rgb = Rgb{0.25, 0.0625, 1.5};
    s.shapes = {every_field_set(), every_field_set()};
    s.metadata = {{"generator", "test"}, {"size", "33x17"}};
    s.thin_objects = {ThinObject{"strip", every_field_set()}};
    World world;
    world.ambient = 0.2;
    world.objects.emplace_back();
    world.objects.back().name = "box";
    s.world = world;
    SceneSequence sequence;
    sequence.frames = 12;
    s.sequence = sequence;
    Scene expected = s;
    expected.shapes.clear();
    EXPECT_EQ(without_shapes(s), expected);
}

}  // namespace
}  // namespace aabench
