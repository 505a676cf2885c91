#include "harness/world/pipeline.h"

#include <chrono>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "harness/reference/visibility.h"
#include "harness/world/alloc_count.h"
#include "harness/world/reflections.h"
#include "harness/world/stages.h"

namespace aabench {
namespace {

// Runs fn as stage s: time and allocations added to its cost (a stage may run in two parts,
// as projection does: faces first, the cells' projection last).
template <class Fn>
void run_stage(WorldRender& r, Stage s, Fn&& fn) {
    StageCost& cost = r.costs[static_cast<int>(s)];
    const AllocCounts before = thread_alloc_counts();
    const auto t0 = std::chrono::steady_clock::now();
    fn(cost);
    const auto t1 = std::chrono::steady_clock::now();
    const AllocCounts after = thread_alloc_counts();
    cost.ran = true;
    cost.time_ms += std::chrono::duration<double, std::milli>(t1 - t0).count();
    cost.bytes += after.bytes - before.bytes;
    cost.allocations += after.allocations - before.allocations;
}

// The registry's methods that draw affine values (default parameters), for error messages.
std::vector<std::string> depth_capable_methods() {
    std::vector<std::string> ids;
    for (const MethodInfo& info : method_registry()) {
        if (make_method(info.id).method->affine_values()) ids.push_back(info.id);
    }
    return ids;
}

// `scene` with each shape's value set to its depth z_s = f^2 / z_v (an affine plane, since its
// inv_depth is) and the background to 0 (infinitely far).
Scene depth_valued(const Scene& scene, double focal_px, bool keep_depth_planes) {
    Scene depth = scene;
    depth.background = 0.0;
    const double f2 = focal_px * focal_px;
    for (Shape& s : depth.shapes) {
        const AffinePlane& w = *s.inv_depth;
        s.value_plane = AffinePlane{f2 * w.c, f2 * w.gx, f2 * w.gy};
        if (!keep_depth_planes) s.inv_depth.reset();
    }
    return depth;
}

Scene empty_like(const Scene& scene) {
    Scene s;
    s.width = scene.width;
    s.height = scene.height;
    s.background = scene.background;
    s.metadata = scene.metadata;
    s.thin_objects = scene.thin_objects;
    return s;
}

}  // namespace

WorldRender render_world(const Scene& scene, const Plan& plan) {
    WorldRender r;
    r.plan = plan;
    if (!scene.world) {
        r.screen = scene;
        r.pieces = scene;
        return r;
    }
    const World& world = *scene.world;
    ViewSetup view;
    std::vector<WorldFace> faces;
    run_stage(r, Stage::kProjection, [&](StageCost&) {
        view = ViewSetup::from(world.camera, scene.width, scene.height);
        faces = collect_faces(world, view);
    });
    r.focal_px = view.focal_px;
    if (plan.in(Stage::kCulling)) {
        run_stage(r, Stage::kCulling, [&](StageCost& c) {
            const std::size_t culled = cull_back_faces(faces, view);
            c.detail = fmt::format("culled {} of {} faces", culled, faces.size());
        });
    }
    std::vector<std::vector<Cell>> cells = initial_cells(faces);
    if (plan.in(Stage::kPatterns)) {
        run_stage(r, Stage::kPatterns, [&](StageCost& c) {
            c.detail = fmt::format("{} pattern cells", cut_patterns(world, faces, cells));
        });
    }
    if (plan.in(Stage::kShadows)) {
        run_stage(r, Stage::kShadows, [&](StageCost& c) {
            c.detail = fmt::format("{} shadow polygons fell on faces", cast_shadows(world, faces, cells));
        });
    }
    if (plan.in(Stage::kShading)) {
        run_stage(r, Stage::kShading, [&](StageCost&) { shade(world, faces, cells); });
    } else {
        unshaded(cells);
    }
    r.screen = empty_like(scene);
    run_stage(r, Stage::kProjection, [&](StageCost& c) {
        project_cells(faces, cells, view, r.screen);
        r.shared_edges = shared_edges(world, faces, view);
        c.detail = fmt::format("{} faces, {} shapes on screen", faces.size(), r.screen.shapes.size());
    });
    if (plan.in(Stage::kVisibility)) {
        run_stage(r, Stage::kVisibility, [&](StageCost& c) {
            VisibilityStats st;
            r.pieces = visible_pieces(r.screen, &st);
            c.detail = fmt::format("{} shapes -> {} visible pieces; {} pairs overlap of {} "
                                   "candidates", st.shapes_in, st.pieces_out,
                                   st.overlapping_pairs, st.candidate_pairs);
        });
    } else {
        r.pieces = r.screen;
    }
    if (plan.in(Stage::kDepthImage)) {
        run_stage(r, Stage::kDepthImage, [&](StageCost&) {
            r.depth = depth_valued(r.pieces, view.focal_px, /*keep_depth_planes=*/false);
        });
    }
    if (plan.in(Stage::kReflections)) {
        run_stage(r, Stage::kReflections, [&](StageCost& c) {
            OpticalDepthStats st;
            r.optical_depth = optical_path_depth(scene, &st);
            c.detail = fmt::format("{} rays ({} per pixel side), {} samples met a mirror",
                                   st.rays, kOpticalSamplesPerSide, st.mirror_hits);
        });
    }
    for (Shape& s : r.pieces.shapes) s.inv_depth.reset();
    return r;
}

Image render_depth_image(WorldRender& render, const Method& method,
                         const std::string& method_name) {
    if (!render.depth) {
        throw std::logic_error("render_depth_image: the plan has no depth stage");
    }
    if (!method.affine_values()) {
        throw InputError(fmt::format(
            "{} does not draw affine values, so it cannot draw a depth image (methods that do: "
            "{})",
            method_name, fmt::join(depth_capable_methods(), ", ")));
    }
    Image depth;
    run_stage(render, Stage::kDepthImage, [&](StageCost&) {
        depth = Image(render.depth->width, render.depth->height);
        if (!method.own_visibility()) {
            method.render(*render.depth, depth);
            return;
        }
        // A method with its own visibility resolves depth as it resolves values: the
        // ScreenScene with each cell's value set to its z_s plane, depth planes kept.
        method.render(depth_valued_screen(render), depth);
    });
    return depth;
}

Scene depth_valued_screen(const WorldRender& render) {
    if (!render.depth) throw std::logic_error("depth_valued_screen: the plan has no depth stage");
    return depth_valued(render.screen, render.focal_px, /*keep_depth_planes=*/true);
}

EdgeImages run_edge_stage(WorldRender& render, const EdgesSpec& spec, const Image& depth,
                          const Image& shaded) {
    if (!render.plan.in(Stage::kEdges)) {
        throw std::logic_error("run_edge_stage: the plan has no edge stage");
    }
    EdgeImages edges;
    run_stage(render, Stage::kEdges,
              [&](StageCost&) { edges = enhance_edges(depth, shaded, spec); });
    return edges;
}

Scene drawable_scene(const Scene& scene) {
    if (!scene.world) return scene;
    return render_world(scene, make_plan(scene)).pieces;
}

Scene drawable_scene(const Scene& scene, const Method& method) {
    if (!scene.world) return scene;
    WorldRender r = render_world(scene, make_plan(scene));
    return method.own_visibility() ? std::move(r.screen) : std::move(r.pieces);
}

const Scene& scene_for(const WorldRender& render, const Method& method) {
    return method.own_visibility() ? render.screen : render.pieces;
}

std::string format_stage_costs(const WorldRender& render) {
    std::string out = fmt::format("  {:<12} {:<4} {:>9} {:>12} {:>7}  {}\n", "stage", "plan",
                                  "time_ms", "bytes", "allocs", "detail");
    for (int k = 0; k < kStageCount; ++k) {
        const StageCost& c = render.costs[k];
        const bool in = render.plan.stages[k].in;
        if (c.ran) {
            out += fmt::format("  {:<12} {:<4} {:>9.3f} {:>12} {:>7}  {}\n",
                               stage_name(static_cast<Stage>(k)), in ? "in" : "out", c.time_ms,
                               c.bytes, c.allocations, c.detail);
        } else {
            out += fmt::format("  {:<12} {:<4} {:>9} {:>12} {:>7}  {}\n",
                               stage_name(static_cast<Stage>(k)), in ? "in" : "out", "-", "-", "-",
                               in ? "(runs after the method: render --stats)" : "not called");
        }
    }
    return out;
}

}  // namespace aabench
