// The plan: which stages a scene calls for, and why (docs/world.md, "The plan: effects on demand").
//
// The plan is derived from the scene, never from flags: a stage is in when the scene contains
// the effect (lights, patterns, shadow casters, overlapping faces, edges, mirrors) and the
// scene's own `effects` switches leave it on. The one thing a caller may add is a depth image
// (`render --depth-out`, `reference --depth`). A stage the plan leaves out is never called:
// it costs no time and allocates nothing (tests/world_pipeline_test.cpp measures that).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "patterns/scene/scene.h"

namespace aabench {

// In pipeline order.
enum class Stage {
    kProjection,   // camera, near-plane clipping, perspective; depth planes
    kCulling,      // back faces of closed objects dropped
    kPatterns,     // patterns clipped to their faces, faces cut into cells
    kShadows,      // exact shadow polygons on receiving faces, one per light and caster
    kShading,      // flat illuminance per face: ambient + lights (with their shadows)
    kVisibility,   // exact hidden-surface removal where projected faces overlap
    kDepthImage,   // the scene with each face's value set to its z_s = f d / z_v plane
    kEdges,        // edge enhancement from the depth image (Saito & Takahashi 1990)
    kReflections,  // optical-path depth through mirrors (Saito & Takahashi 1990, eq. 9)
};
inline constexpr int kStageCount = 9;

const char* stage_name(Stage stage);  // "projection", "culling", ...

struct StageDecision {
    bool in = false;
    std::string reason;
};

struct Plan {
    std::array<StageDecision, kStageCount> stages;
    // What the stages' lines do not say: per mesh object, its file, its triangles, the
    // degenerate ones left out and whether it was found closed (MeshSource, world.h).
    std::vector<std::string> notes;
    bool in(Stage s) const { return stages[static_cast<int>(s)].in; }
    const StageDecision& operator[](Stage s) const { return stages[static_cast<int>(s)]; }
};

// What a caller may ask for beyond what the scene calls for.
struct PlanRequest {
    bool depth_image = false;  // e.g. render --depth-out, reference --depth
};

Plan make_plan(const Scene& scene, const PlanRequest& request = {});

// One line per stage: "  shadows      in   light 0 casts: 'block' -> 'floor'".
std::string format_plan(const Plan& plan);

// "1 light", "2 lights": a count with its noun in the right number (the plan's and the stages'
// lines use it).
std::string count_of(std::size_t n, const char* one, const char* many);

// True when every vertex of `object` lies on or behind every face plane (tolerance relative to
// the object's extent, plan.cpp): a closed convex object, whose front faces never overlap.
bool is_convex_object(const Object& object);

}  // namespace aabench
