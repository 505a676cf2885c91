// The built-in test patterns: properties every generator must have (pure, recorded, well
// formed, checked parameters, bounded vertex counts). Each pattern against its analytic
// description is in patterns_geometry_test.cpp.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "pattern_checks.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

using testing::kSizes;
using testing::signed_area;
using testing::Size;

const std::string* find_metadata(const Scene& scene, const std::string& key) {
    for (const auto& [k, v] : scene.metadata) {
        if (k == key) return &v;
    }
    return nullptr;
}

bool inside_image(const Scene& scene) {
    for (const Shape& shape : scene.shapes) {
        for (const Contour& contour : shape.contours) {
            for (const Point& p : contour) {
                if (!(p.x >= 0.0 && p.x <= scene.width && p.y >= 0.0 && p.y <= scene.height)) {
                    return false;
                }
            }
        }
    }
    return true;
}

// ---- Properties of every registered pattern ----

TEST(Patterns, RegistryHasTheTwentyEightDocumentedPatterns) {
    std::vector<std::string> ids;
    for (const PatternInfo& info : pattern_registry()) ids.push_back(info.id);
    // The five 2-D patterns first (their order is the reports' order), then the 3-D ones
    // (tests/patterns3d_test.cpp checks those).
    // circles and circle-radii (exact rings) follow the five polygon patterns, then curves and
    // crescents (Bezier curves), then isoluminant (colour: tests/colour_test.cpp), then text,
    // text-cff and text-page (glyph outlines); colour-room (a colour world:
    // tests/colour_world_test.cpp) beside room. The mesh
    // models of Debian's packages come last (tests/mesh_patterns_test.cpp).
    EXPECT_EQ(ids, (std::vector<std::string>{"star", "strips", "grating", "rings", "zoneplate",
                                             "circles", "circle-radii", "curves", "crescents",
                                             "isoluminant", "text", "text-cff", "text-page", "room",
                                             "colour-room", "blocks",
                                             "interpenetrate", "mesh", "terrain", "torus",
                                             "checkerboard", "terrain-edges", "mirror",
                                             "foliage", "bunny", "horse", "engine", "truck"}));
    for (const PatternInfo& info : pattern_registry()) {
        EXPECT_FALSE(info.summary.empty()) << info.id;
        for (const ParamSpec& p : info.params) {
            EXPECT_FALSE(p.doc.empty()) << info.id << "." << p.name;
            EXPECT_TRUE(p.default_value >= p.min_value && p.default_value <= p.max_value)
                << info.id << "." << p.name;
        }
    }
}

TEST(Patterns, GenerationIsDeterministicRecordedAndWellFormed) {
    for (const PatternInfo& info : pattern_registry()) {
        if (info.model_file) continue;  // tests/mesh_patterns_test.cpp
        if (make_pattern(info.id, 8, 8).world) continue;  // 3-D: tests/patterns3d_test.cpp
        for (const Size size : kSizes) {
            SCOPED_TRACE(fmt::format("{} at {}x{}", info.id, size.width, size.height));
            const Scene scene = make_pattern(info.id, size.width, size.height);
            EXPECT_TRUE(scene == make_pattern(info.id, size.width, size.height));

            EXPECT_EQ(scene.width, size.width);
            EXPECT_EQ(scene.height, size.height);
            // A grey pattern draws value 1 on 0; a colour one its colours (their luminances as
            // values: the colour pattern's own test checks them).
            const bool colour = scene.channels == 3;
            if (!colour) EXPECT_EQ(scene.background, 0.0);
            ASSERT_FALSE(scene.metadata.empty());
            EXPECT_EQ(scene.metadata.front(), std::make_pair(std::string("pattern"), info.id));
            for (const ParamSpec& p : info.params) {
                const std::string* value = find_metadata(scene, p.name);
                ASSERT_NE(value, nullptr) << p.name;
                EXPECT_EQ(*value, p.default_string()) << p.name;
            }
            const std::string* recorded_size = find_metadata(scene, "size");
            ASSERT_NE(recorded_size, nullptr);
            EXPECT_EQ(*recorded_size, fmt::format("{}x{}", size.width, size.height));

            ASSERT_FALSE(scene.shapes.empty());
            for (const Shape& shape : scene.shapes) {
                if (colour) {
                    ASSERT_TRUE(shape.rgb.has_value());
                    EXPECT_EQ(shape.value, luminance(*shape.rgb));
                } else {
                    EXPECT_EQ(shape.value, 1.0);
                }
                ASSERT_FALSE(shape.contours.empty());
                for (const Contour& contour : shape.contours) {
                    ASSERT_GE(contour.size(), 3u);
                    for (const Point& p : contour) {
                        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
                    }
                    EXPECT_NE(signed_area(contour), 0.0);
                }
            }
        }
    }
}

TEST(Patterns, GivenParametersAreRecorded) {
    const Scene scene = make_pattern("star:spokes=12,start_angle=0.25", 64, 48);
    ASSERT_NE(find_metadata(scene, "spokes"), nullptr);
    EXPECT_EQ(*find_metadata(scene, "spokes"), "12");
    EXPECT_EQ(*find_metadata(scene, "start_angle"), "0.25");
    EXPECT_EQ(*find_metadata(scene, "radius"), "0.92");
    EXPECT_EQ(scene.shapes.size(), 12u);
}

TEST(Patterns, UnknownIdIsAnInputErrorListingTheValidIds) {
    try {
        make_pattern("chessboard", 64, 64);
        FAIL() << "no InputError";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("chessboard"), std::string::npos) << message;
        for (const PatternInfo& info : pattern_registry()) {
            EXPECT_NE(message.find(info.id), std::string::npos) << message;
        }
    }
}

TEST(Patterns, OutOfRangeParameterIsAnInputErrorNamingTheRange) {
    for (const PatternInfo& info : pattern_registry()) {
        for (const ParamSpec& p : info.params) {
            // max + 1 is out of range and, for an int parameter, still an integer.
            const std::string spec =
                fmt::format("{}:{}={}", info.id, p.name, format_real(p.max_value + 1.0));
            try {
                make_pattern(spec, 64, 64);
                ADD_FAILURE() << spec << ": no InputError";
            } catch (const InputError& e) {
                const std::string message = e.what();
                EXPECT_NE(message.find(p.name), std::string::npos) << message;
                EXPECT_NE(message.find(p.range_string()), std::string::npos) << message;
            }
        }
    }
}

TEST(Patterns, DefaultsKeepShapesInsideTheImage) {
    // The grating reaches past the edges by design; the others must fit at every size.
    for (const char* id : {"star", "rings", "zoneplate"}) {
        for (const Size size : kSizes) {
            EXPECT_TRUE(inside_image(make_pattern(id, size.width, size.height)))
                << id << " at " << size.width << "x" << size.height;
        }
    }
    // Strips: at 16x16 the cells are 2 px wide, smaller than the off-grid offset plus the
    // margin, so only the sizes with real cells are checked.
    EXPECT_TRUE(inside_image(make_pattern("strips", 256, 256)));
    EXPECT_TRUE(inside_image(make_pattern("strips", 300, 200)));
}

TEST(Patterns, TextPageFillsTheImageWithLinesAndDrawsNothingBeyondIt) {
    for (const double size : {6.0, 12.0}) {
        SCOPED_TRACE(fmt::format("size_px={}", size));
        const int width = 200, height = 120;
        const Scene scene = make_pattern(fmt::format("text-page:size_px={}", size), width, height);
        // Baselines 4 + s, then 1.25 s apart, while a line's top (baseline - s) is in the image.
        int lines = 0;
        for (double b = 4.0 + size; b - size < height; b += 1.25 * size) ++lines;
        ASSERT_EQ(static_cast<int>(scene.shapes.size()), lines);
        ASSERT_EQ(scene.thin_objects.size(), scene.shapes.size());
        EXPECT_EQ(scene.thin_objects.front().label, "line 1");
        for (const Shape& shape : scene.shapes) {
            double x_max = -1.0;
            for (const SegmentContour& contour : shape.outline) {
                double x_min = contour.front().p[0].x;
                for (const Segment& seg : contour) {
                    for (int q = 0; q <= seg.degree; ++q) {
                        x_min = std::min(x_min, seg.p[q].x);
                        x_max = std::max(x_max, seg.p[q].x);
                    }
                }
                EXPECT_LT(x_min, width) << "a contour that starts right of the image is left out";
            }
            // Each line runs across the whole width: its last glyph reaches the right edge
            // (within a glyph and a space, 1.5 em).
            EXPECT_GT(x_max, width - 1.5 * size);
        }
    }
}

// ---- vertex limit ----

TEST(Patterns, AbsurdVertexCountsAreInputErrorsNamingTheParameters) {
    struct Case {
        std::string spec;
        int width, height;
        std::string parameter;
    };
    // Each would need well over the generators' limit of 4 million vertices.
    const Case cases[] = {
        {"grating:period=0.05", 65536, 1024, "period"},
        {"rings:period=0.05,max_radius=10", 4096, 4096, "period"},
        {"zoneplate:nyquist_radius=0.5,max_radius=10", 4096, 4096, "nyquist_radius"},
        {"text-page:size_px=4", 4096, 4096, "size_px"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.spec);
        try {
            make_pattern(c.spec, c.width, c.height);
            ADD_FAILURE() << c.spec << ": no InputError";
        } catch (const InputError& e) {
            const std::string message = e.what();
            const std::string id = c.spec.substr(0, c.spec.find(':'));
            EXPECT_NE(message.find(id), std::string::npos) << message;
            EXPECT_NE(message.find(c.parameter), std::string::npos) << message;
            EXPECT_NE(message.find("vertices"), std::string::npos) << message;
        }
    }
}

}  // namespace
}  // namespace aabench
