// The overlay (harness/world/overlay.h): faces whole, patterns laid over them, and a shadow
// layer per face.
#include "harness/world/overlay.h"

#include <cmath>

namespace aabench {
namespace {

// The shadows of one face as disjoint convex cells, each with the lights it hides, all with
// `base`'s reflectance: each shadow marks the layer's cells inside it and adds the parts of
// itself no earlier shadow covered (the shadow minus each earlier cell in turn). The cells'
// bounds and the remaining parts' are kept beside them (BoxedCells, stages.h): a cell apart
// from the bounds of all the parts left is apart from each, so it is passed over at once, as
// testing part by part would pass it: the same cells in the same order.
std::vector<Cell> shadow_cells(const Cell& base, const std::vector<FaceShadow>& shadows,
                               double min_area) {
    BoxedCells layer({});
    std::vector<Polygon2> rest, remaining, outside;
    std::vector<Box2> rest_boxes, remaining_boxes;
    for (const FaceShadow& s : shadows) {
        const std::uint64_t bit = std::uint64_t{1} << s.light;
        rest.assign(1, s.polygon);
        rest_boxes.assign(1, bounds(s.polygon));
        Box2 rest_box = rest_boxes[0];
        for (int c = layer.head; c >= 0; c = layer.next[c]) {
            if (apart(layer.boxes[c], rest_box)) continue;
            remaining.clear();
            remaining_boxes.clear();
            for (std::size_t r = 0; r < rest.size(); ++r) {
                if (apart(rest_boxes[r], layer.boxes[c])) {
                    remaining.push_back(std::move(rest[r]));
                    remaining_boxes.push_back(rest_boxes[r]);
                    continue;
                }
                outside.clear();
                (void)split_by_convex(rest[r], layer.cells[c].loop, min_area, outside);
                for (Polygon2& o : outside) {
                    remaining_boxes.push_back(bounds(o));
                    remaining.push_back(std::move(o));
                }
            }
            rest.swap(remaining);
            rest_boxes.swap(remaining_boxes);
            if (rest.empty()) break;
            rest_box = Box2{};
            for (const Box2& b : rest_boxes) {
                rest_box.lo = glm::min(rest_box.lo, b.lo);
                rest_box.hi = glm::max(rest_box.hi, b.hi);
            }
        }
        layer.split(s.polygon, min_area, [&](Cell& cell) { cell.shadowed |= bit; });
        for (Polygon2& r : rest) {
            Cell cell = base;
            cell.loop = std::move(r);
            cell.shadowed = bit;
            cell.role = ShapeRole::kShadow;
            layer.push(std::move(cell));
        }
    }
    return layer.take();
}

// Why a face with more than kCutLayerShadows (overlay.h) shadows takes its layer from the
// cut (cut_by_shadows below) rather than shadow by shadow (shadow_cells): subtracting each
// shadow from every earlier cell leaves the rest of the shadow in fragments that the next
// shadows fragment again, so the layer grows far faster than the shadows (the bunny's ground
// under its 64,000 shadow triangles at 64 x 64: 1,830,293 layer cells and 100 s, against
// 217,738 shadowed cells and 1.6-2.5 s from the cut; docs/world.md, "The overlay", has the
// command). At or below it (every built-in scene but the
// mesh models with shadows on) the layer is built as it always was, so those images stay.

// The shadow layer as the shadowed cells of the face cut by its patterns, then by its shadows
// (as cut_patterns does, then cut_face_by_shadows, cell_cutting.cpp): the same region (where some shadow falls),
// cut into disjoint convex cells, each with the lights it hides and the reflectance of the
// topmost pattern under it, else the face's: what shadow_cells() and the patterns' split give,
// cut along other lines.
std::vector<Cell> cut_by_shadows(const Cell& face, const std::vector<Cell>& patterns,
                                 const std::vector<FaceShadow>& shadows, double min_area) {
    std::vector<Cell> cut(1, face);
    for (const Cell& p : patterns) {
        split_cells(cut, p.loop, min_area, [&](Cell& c) { c.take_reflectance(p); });
    }
    std::vector<Cell> layer;
    for (Cell& c : cut_face_by_shadows(std::move(cut), shadows, min_area)) {
        if (c.shadowed != 0) layer.push_back(std::move(c));  // in the shadow role already
    }
    return layer;
}

}  // namespace

std::vector<std::vector<Cell>> overlay_cells(const World& world,
                                             const std::vector<WorldFace>& faces,
                                             const ShadowsByFace& shadows, bool patterns_on,
                                             OverlayStats* stats) {
    ++work_counts().build_overlay;
    OverlayStats st;
    std::vector<std::vector<Cell>> out(faces.size());
    for (std::size_t k = 0; k < faces.size(); ++k) {
        const WorldFace& f = faces[k];
        if (!f.visible) continue;
        const Polygon2 outline = face_outline(f);
        const double min_area = sliver_twice_area(outline);
        Cell face;
        face.loop = outline;
        face.take_reflectance(f);
        face.value = f.reflectance;
        out[k].push_back(face);
        ++st.faces;
        // The patterns exactly as the patterns stage clips them (stages.cpp, cut_patterns).
        std::vector<Cell> patterns;
        if (patterns_on) {
            for (const FacePattern& p : world.objects[f.object].faces[f.index].patterns) {
                Cell cell;
                cell.loop = clip_convex(in_face_frame(f, p.loop), outline);
                if (std::abs(twice_area(cell.loop)) <= min_area) continue;
                cell.take_reflectance(p);
                cell.value = p.reflectance;
                cell.role = ShapeRole::kPattern;
                patterns.push_back(std::move(cell));
            }
        }
        st.patterns += patterns.size();
        if (!shadows.empty() && shadows[k].size() > kCutLayerShadows) {
            std::vector<Cell> layer = cut_by_shadows(face, patterns, shadows[k], min_area);
            st.shadow_cells += layer.size();
            for (Cell& c : patterns) out[k].push_back(std::move(c));
            for (Cell& c : layer) out[k].push_back(std::move(c));
        } else if (!shadows.empty() && !shadows[k].empty()) {
            std::vector<Cell> layer = shadow_cells(face, shadows[k], min_area);
            // What lies under each shadow cell: the patterns over it, later over earlier.
            for (const Cell& p : patterns) {
                split_cells(layer, p.loop, min_area, [&](Cell& c) { c.take_reflectance(p); });
            }
            st.shadow_cells += layer.size();
            for (Cell& c : patterns) out[k].push_back(std::move(c));
            for (Cell& c : layer) out[k].push_back(std::move(c));
        } else {
            for (Cell& c : patterns) out[k].push_back(std::move(c));
        }
    }
    if (stats) *stats = st;
    return out;
}

}  // namespace aabench
