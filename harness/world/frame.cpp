// The prepared frame (harness/world/frame.h): the plan, then the world stages it keeps, each
// run once, timed and its heap allocation counted.
#include "harness/world/frame.h"

#include <chrono>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "harness/reference/visibility.h"
#include "harness/world/alloc_count.h"
#include "harness/world/finite_checks.h"
#include "harness/world/overlay.h"
#include "harness/world/reflections.h"
#include "harness/world/stages.h"

namespace aabench {
namespace {

// Runs fn as stage `cost`: time and allocations added to it (a stage may run in two parts, as
// projection does: faces first, the cells' projection last).
template <class Fn>
void run_stage(StageCost& cost, Fn&& fn) {
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
        if (info.traits->affine_values) ids.push_back(info.id);
    }
    return ids;
}

// `scene` with each shape's value set to its depth z_s = f d / z_v (an affine plane, since its
// inv_depth is; depth_scale = f d, ViewSetup::depth_scale) and the background to 0 (infinitely
// far). A depth image is grey in a colour world too: its colours are dropped.
Scene depth_valued(const Scene& scene, double depth_scale, bool keep_depth_planes) {
    Scene depth = scene;
    depth.background = 0.0;
    depth.channels = 1;
    depth.background_rgb.reset();
    for (Shape& s : depth.shapes) {
        s.rgb.reset();
        const AffinePlane& w = *s.inv_depth;
        s.value_plane = AffinePlane{depth_scale * w.c, depth_scale * w.gx, depth_scale * w.gy};
        if (!keep_depth_planes) s.inv_depth.reset();
    }
    return depth;
}

Scene empty_like(const Scene& scene) {
    Scene s;
    s.width = scene.width;
    s.height = scene.height;
    s.background = scene.background;
    s.channels = scene.channels;
    s.background_rgb = scene.background_rgb;
    s.metadata = scene.metadata;
    s.thin_objects = scene.thin_objects;
    s.origin_x = scene.origin_x;
    s.origin_y = scene.origin_y;
    return s;
}

}  // namespace

struct PreparedFrame::State {
    FrameRequest request;
    Plan plan;
    Scene given;
    // 2-D with a window origin: `given` in its window frame, what every input below is (empty
    // otherwise: `given` is already in it).
    std::optional<Scene> window;
    Scene screen;  // 3-D: the ScreenScene; 2-D: empty (the window scene is the input)
    double focal_px = 0.0;
    double depth_scale = 0.0;  // f d: z_s = depth_scale / z_v
    // The seams symptom's edges, built on first use (harness work no method relies on).
    mutable std::once_flag shared_edges_once;
    mutable std::vector<std::array<Point, 2>> shared_edges;
    std::optional<Scene> depth_screen;
    std::optional<Image> optical_depth;
    // Kept for the overlay, built on first use.
    ViewSetup view;
    std::vector<WorldFace> faces;
    ShadowsByFace shadows;
    double collect_ms = 0.0;      // projection's first half: the faces
    double shadow_cast_ms = 0.0;  // the shadows stage's casting (without its cuts)
    double cell_cutting_ms = 0.0;
    mutable std::once_flag overlay_once;
    mutable Scene overlay;
    mutable StageCost overlay_cost;
    mutable double overlay_layering_ms = 0.0;

    // The visible pieces (and the depth pieces made from them), built on first use.
    mutable std::once_flag pieces_once;
    mutable Scene pieces;
    mutable std::optional<Scene> depth_pieces;
    // True when exact visibility made them (disjoint convex pieces, and so the depth pieces);
    // false when the cells themselves are the pieces (no two faces overlap).
    mutable bool pieces_disjoint = false;

    mutable std::mutex cost_mutex;
    mutable StageCosts costs;

    bool world() const { return given.world.has_value(); }
    // `built` (the pieces or the depth pieces, once built) as what it is known to be.
    SceneInput pieces_input(const Scene& built) const {
        return pieces_disjoint ? SceneInput::disjoint_pieces(built) : SceneInput(built);
    }
    // A 2-D scene's one input (screen, pieces and overlay alike), in its window frame.
    const Scene& flat() const { return window ? *window : given; }
    // A 2-D colour scene's channels as grey scenes (channel_scene of flat()), made once so
    // that a method drawing channel by channel allocates nothing per render; empty otherwise.
    std::array<Scene, 3> channels;
    // A colour world's inputs' channels likewise, each made with its input.
    std::array<Scene, 3> screen_channels;
    mutable std::array<Scene, 3> pieces_channels;
    mutable std::array<Scene, 3> overlay_channels;
    static void make_channels(const Scene& scene, std::array<Scene, 3>& out) {
        if (scene.channels != 3) return;
        for (int c = 0; c < 3; ++c) out[c] = channel_scene(scene, c);
    }
    // `in` with its channels when it is a colour scene.
    static SceneInput coloured(const SceneInput& in, const std::array<Scene, 3>& made) {
        return in.scene().channels == 3 ? in.with_channels(made) : in;
    }
    // flat() with its channels when it is a colour scene.
    SceneInput flat_input() const { return coloured(SceneInput(flat()), channels); }

    // Runs `fn` as stage s and adds what it cost (thread-safe: the lazy visibility stage may
    // run while another thread reads the costs).
    template <class Fn>
    void stage(Stage s, Fn&& fn) const {
        StageCost local;
        run_stage(local, fn);
        std::lock_guard<std::mutex> lock(cost_mutex);
        costs[static_cast<int>(s)].add(local);
    }

    void build_pieces() const {
        std::call_once(pieces_once, [this] {
            if (plan.in(Stage::kVisibility)) {
                stage(Stage::kVisibility, [&](StageCost& c) {
                    VisibilityStats st;
                    pieces = visible_pieces(screen, &st);
                    pieces_disjoint = true;
                    check_finite_shapes("visibility", faces, pieces);
                    c.detail = fmt::format(
                        "{} -> {}; {} wholly hidden by {} tiles, no pair tested; {} of {} "
                        "candidates",
                        count_of(st.shapes_in, "shape", "shapes"),
                        count_of(st.pieces_out, "visible piece", "visible pieces"),
                        st.hidden_by_tiles, st.tiles,
                        count_of(st.overlapping_pairs, "pair overlaps", "pairs overlap"),
                        st.candidate_pairs);
                });
            } else {
                pieces = screen;  // no two faces overlap: the cells are the visible pieces
            }
            if (plan.in(Stage::kDepthImage)) {
                stage(Stage::kDepthImage, [&](StageCost&) {
                    depth_pieces = depth_valued(pieces, depth_scale, /*keep_depth_planes=*/false);
                    check_finite_shapes("depth", faces, *depth_pieces);
                });
            }
            for (Shape& s : pieces.shapes) s.inv_depth.reset();
            make_channels(pieces, pieces_channels);
        });
    }

    bool has_layers() const {
        return plan.in(Stage::kPatterns) || plan.in(Stage::kShadows);
    }

    void build_overlay() const {
        std::call_once(overlay_once, [this] {
            StageCost local;
            run_stage(local, [&](StageCost& c) {
                const World& world = *given.world;
                OverlayStats os;
                const auto t0 = std::chrono::steady_clock::now();
                std::vector<std::vector<Cell>> cells =
                    overlay_cells(world, faces, shadows, plan.in(Stage::kPatterns), &os);
                overlay_layering_ms = std::chrono::duration<double, std::milli>(
                                          std::chrono::steady_clock::now() - t0)
                                          .count();
                if (plan.in(Stage::kShading)) {
                    shade_values(world, faces, cells);
                } else {
                    unshaded(cells);
                }
                check_finite_cells("overlay", faces, cells);
                overlay = empty_like(given);
                append_projected(faces, cells, view, overlay);
                check_finite_shapes("overlay", faces, overlay);
                make_channels(overlay, overlay_channels);
                c.detail = fmt::format("{} faces + {} patterns + {} shadow cells laid over them",
                                       os.faces, os.patterns, os.shadow_cells);
            });
            std::lock_guard<std::mutex> lock(cost_mutex);
            overlay_cost = local;
        });
    }
};

PreparedFrame::PreparedFrame(std::unique_ptr<State> state) : state_(std::move(state)) {}
PreparedFrame::PreparedFrame(PreparedFrame&&) noexcept = default;
PreparedFrame& PreparedFrame::operator=(PreparedFrame&&) noexcept = default;
PreparedFrame::~PreparedFrame() = default;

PreparedFrame PreparedFrame::prepare(const Scene& scene, const FrameRequest& request) {
    auto st = std::make_unique<State>();
    st->request = request;
    st->plan = make_plan(scene, {.depth_image = request.depth_image});
    st->given = scene;
    if (!scene.world) {
        // The one place a window origin is taken out (a 3-D scene has none: the camera places
        // its window, docs/scene-format.md).
        if (!is_window_frame(scene)) st->window = in_window_frame(scene);
        State::make_channels(st->flat(), st->channels);
        return PreparedFrame(std::move(st));
    }
    const Plan& plan = st->plan;
    const World& world = *scene.world;
    ViewSetup& view = st->view;
    std::vector<WorldFace>& faces = st->faces;
    st->stage(Stage::kProjection, [&](StageCost&) {
        view = ViewSetup::from(world.camera, scene.width, scene.height);
        faces = collect_faces(world, view);
        check_finite_faces("projection", faces);
    });
    st->collect_ms = st->costs[static_cast<int>(Stage::kProjection)].time_ms;
    st->focal_px = view.focal_px;
    st->depth_scale = view.depth_scale();
    if (plan.in(Stage::kCulling)) {
        st->stage(Stage::kCulling, [&](StageCost& c) {
            const std::size_t culled = cull_back_faces(faces, view);
            c.detail = fmt::format("culled {} of {}", culled,
                                   count_of(faces.size(), "face", "faces"));
        });
    }
    std::vector<std::vector<Cell>> cells = initial_cells(faces);
    if (plan.in(Stage::kPatterns)) {
        st->stage(Stage::kPatterns, [&](StageCost& c) {
            c.detail = fmt::format("{} pattern cells", cut_patterns(world, faces, cells));
            check_finite_cells("patterns", faces, cells);
        });
        st->cell_cutting_ms = st->costs[static_cast<int>(Stage::kPatterns)].time_ms;
    }
    if (plan.in(Stage::kShadows)) {
        st->stage(Stage::kShadows, [&](StageCost& c) {
            // Casting is what the cells and the overlay both need; the cuts only the cells.
            const auto t0 = std::chrono::steady_clock::now();
            st->shadows = find_shadows(world, faces);
            const auto t1 = std::chrono::steady_clock::now();
            cut_shadows(faces, st->shadows, cells);
            check_finite_cells("shadows", faces, cells);
            const auto t2 = std::chrono::steady_clock::now();
            st->shadow_cast_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
            st->cell_cutting_ms += std::chrono::duration<double, std::milli>(t2 - t1).count();
            c.detail = fmt::format("{} shadow polygons fell on faces", shadow_count(st->shadows));
        });
    }
    if (plan.in(Stage::kShading)) {
        st->stage(Stage::kShading, [&](StageCost&) {
            shade(world, faces, cells);
            check_finite_cells("shading", faces, cells);
        });
    } else {
        unshaded(cells);
    }
    st->screen = empty_like(scene);
    st->stage(Stage::kProjection, [&](StageCost& c) {
        project_cells(faces, cells, view, st->screen);
        check_finite_shapes("projection", faces, st->screen);
        State::make_channels(st->screen, st->screen_channels);
        c.detail =
            fmt::format("{}, {} on screen", count_of(faces.size(), "face", "faces"),
                        count_of(st->screen.shapes.size(), "shape", "shapes"));
    });
    if (plan.in(Stage::kDepthImage)) {
        st->stage(Stage::kDepthImage, [&](StageCost&) {
            st->depth_screen =
                depth_valued(st->screen, view.depth_scale(), /*keep_depth_planes=*/true);
            check_finite_shapes("depth", faces, *st->depth_screen);
        });
    }
    if (plan.in(Stage::kReflections)) {
        st->stage(Stage::kReflections, [&](StageCost& c) {
            OpticalDepthStats os;
            st->optical_depth = optical_path_depth(scene, &os);
            check_finite_image("reflections", *st->optical_depth);
            c.detail = fmt::format("{} rays ({} per pixel side), {} samples met a mirror",
                                   os.rays, kOpticalSamplesPerSide, os.mirror_hits);
        });
    }
    return PreparedFrame(std::move(st));
}

const FrameRequest& PreparedFrame::request() const { return state_->request; }
const Plan& PreparedFrame::plan() const { return state_->plan; }
bool PreparedFrame::is_world() const { return state_->world(); }
const Scene& PreparedFrame::given() const { return state_->given; }

const Scene& PreparedFrame::screen() const {
    return state_->world() ? state_->screen : state_->flat();
}

SceneInput PreparedFrame::pieces() const {
    if (!state_->world()) return state_->flat_input();
    state_->build_pieces();
    return State::coloured(state_->pieces_input(state_->pieces), state_->pieces_channels);
}

Scene window_scene(Scene scene) {
    if (is_window_frame(scene)) return scene;
    return in_window_frame(scene);
}

bool draws_visible_pieces(const Scene& scene, const MethodTraits& traits) {
    return scene.world.has_value() && !traits.own_visibility;
}

bool PreparedFrame::needs_pieces(const MethodTraits& traits) const {
    return draws_visible_pieces(state_->given, traits);
}

const Scene& PreparedFrame::overlay() const {
    if (!state_->world()) return state_->flat();
    state_->build_overlay();
    return state_->overlay;
}

bool PreparedFrame::draws_overlay(const MethodTraits& traits) const {
    // Without patterns or shadows the overlay is the cells (every face whole): not built.
    return state_->world() && traits.own_visibility && traits.coplanar_overlays &&
           state_->has_layers();
}

SceneInput PreparedFrame::input_for(const Method& method) const {
    if (!state_->world()) return state_->flat_input();
    if (needs_pieces(method)) return pieces();
    if (draws_overlay(method.traits())) {
        return State::coloured(SceneInput(overlay()), state_->overlay_channels);
    }
    return State::coloured(SceneInput(screen()), state_->screen_channels);
}

double PreparedFrame::focal_px() const { return state_->focal_px; }

const std::vector<std::array<Point, 2>>& PreparedFrame::shared_edges() const {
    const State& st = *state_;
    if (st.world()) {
        std::call_once(st.shared_edges_once, [&] {
            st.shared_edges = aabench::shared_edges(*st.given.world, st.faces, st.view);
        });
    }
    return st.shared_edges;
}

bool PreparedFrame::has_depth_stage() const { return state_->depth_screen.has_value(); }

SceneInput PreparedFrame::depth_pieces() const {
    if (!has_depth_stage()) throw std::logic_error("depth_pieces: the plan has no depth stage");
    state_->build_pieces();
    return state_->pieces_input(*state_->depth_pieces);
}

const Scene& PreparedFrame::depth_screen() const {
    if (!has_depth_stage()) throw std::logic_error("depth_screen: the plan has no depth stage");
    return *state_->depth_screen;
}

const std::optional<Image>& PreparedFrame::optical_depth() const { return state_->optical_depth; }

AfterMethod PreparedFrame::after_method(const Method& method, const std::string& method_name,
                                        const Image& shaded, bool want_depth) const {
    AfterMethod after;
    const bool edges = state_->plan.in(Stage::kEdges);
    // With mirrors the edge stage reads the optical-path depth of eq. 9 (the reflections
    // stage) instead of the method's z_s, which is then drawn only when asked for.
    const bool draw_depth = want_depth || (edges && !state_->optical_depth);
    if (draw_depth) {
        if (!has_depth_stage()) {
            throw std::logic_error("after_method: a depth image asked of a frame without the "
                                   "depth stage (FrameRequest::depth_image)");
        }
        if (!method.affine_values()) {
            throw InputError(fmt::format(
                "{} does not draw affine values, so it cannot draw a depth image (methods that "
                "do: {})",
                method_name, fmt::join(depth_capable_methods(), ", ")));
        }
        // The method draws depth as it draws values: the depth pieces, or for a method with
        // its own visibility the depth-valued ScreenScene (depth planes kept).
        const SceneInput input = needs_pieces(method) ? depth_pieces() : depth_screen();
        run_stage(after.depth_cost, [&](StageCost&) {
            after.depth = Image(input.scene().width, input.scene().height);
            method.render(input, *after.depth);
        });
        check_finite_image("depth", *after.depth);
    }
    if (edges) {
        const Image& depth = state_->optical_depth ? *state_->optical_depth : *after.depth;
        run_stage(after.edge_cost, [&](StageCost&) {
            after.edges = enhance_edges(depth, shaded, *state_->given.world->edges);
        });
        check_finite_image("edges", after.edges->composite);
    }
    return after;
}

void PreparedFrame::edge_stage(const Image& depth, const Image& shaded, EdgeImages& out,
                               const EdgesSpec* spec) const {
    if (!state_->plan.in(Stage::kEdges)) {
        throw std::logic_error("edge_stage: the plan has no edge stage");
    }
    enhance_edges(depth, shaded, spec ? *spec : *state_->given.world->edges, out);
}

StageCosts PreparedFrame::costs() const {
    std::lock_guard<std::mutex> lock(state_->cost_mutex);
    return state_->costs;
}

PreparedFrame::LayerCosts PreparedFrame::layer_costs() const {
    LayerCosts out;
    out.cell_cutting_ms = state_->cell_cutting_ms;
    out.cell_shapes = state_->screen.shapes.size();
    std::lock_guard<std::mutex> lock(state_->cost_mutex);
    out.overlay = state_->overlay_cost;
    out.overlay_built = out.overlay.ran;
    if (out.overlay_built) {
        out.overlay_layering_ms = state_->overlay_layering_ms;
        out.overlay_shapes = state_->overlay.shapes.size();
    }
    return out;
}

double PreparedFrame::relied_stage_ms(const Method& method) const {
    if (!state_->world()) return 0.0;
    if (draws_overlay(method.traits())) {
        state_->build_overlay();
        const StageCosts c = costs();
        std::lock_guard<std::mutex> lock(state_->cost_mutex);
        return state_->collect_ms + c[static_cast<int>(Stage::kCulling)].time_ms +
               state_->shadow_cast_ms + state_->overlay_cost.time_ms;
    }
    const StageCosts c = costs();
    double ms = 0.0;
    for (const Stage s : {Stage::kProjection, Stage::kCulling, Stage::kPatterns, Stage::kShadows,
                          Stage::kShading}) {
        ms += c[static_cast<int>(s)].time_ms;
    }
    if (needs_pieces(method)) ms += c[static_cast<int>(Stage::kVisibility)].time_ms;
    return ms;
}

std::string format_stage_costs(const Plan& plan, const StageCosts& costs) {
    std::string out = fmt::format("  {:<12} {:<4} {:>9} {:>12} {:>7}  {}\n", "stage", "plan",
                                  "time_ms", "bytes", "allocs", "detail");
    for (int k = 0; k < kStageCount; ++k) {
        const StageCost& c = costs[k];
        const bool in = plan.stages[k].in;
        if (c.ran) {
            out += fmt::format("  {:<12} {:<4} {:>9.3f} {:>12} {:>7}  {}\n",
                               stage_name(static_cast<Stage>(k)), in ? "in" : "out", c.time_ms,
                               c.bytes, c.allocations, c.detail);
        } else {
            out += fmt::format("  {:<12} {:<4} {:>9} {:>12} {:>7}  {}\n",
                               stage_name(static_cast<Stage>(k)), in ? "in" : "out", "-", "-", "-",
                               in ? "(not needed by this request)" : "not called");
        }
    }
    return out;
}

}  // namespace aabench
