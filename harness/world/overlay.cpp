// The overlay (harness/world/overlay.h): faces whole, patterns laid over them, and a shadow
// layer per face.
#include "harness/world/overlay.h"

#include <cmath>

namespace aabench {
namespace {

// Strictly apart bounds: nothing of `a` lies inside `b`.
bool bounds_apart(const Polygon2& a, const Polygon2& b) {
    glm::dvec2 alo(INFINITY), ahi(-INFINITY), blo(INFINITY), bhi(-INFINITY);
    for (const glm::dvec2& p : a) {
        alo = glm::min(alo, p);
        ahi = glm::max(ahi, p);
    }
    for (const glm::dvec2& p : b) {
        blo = glm::min(blo, p);
        bhi = glm::max(bhi, p);
    }
    return ahi.x < blo.x || bhi.x < alo.x || ahi.y < blo.y || bhi.y < alo.y;
}

// The shadows of one face as disjoint convex cells, each with the lights it hides, all with
// `base`'s reflectance: each shadow marks the layer's cells inside it and adds the parts of
// itself no earlier shadow covered (the shadow minus each earlier cell in turn).
std::vector<Cell> shadow_cells(const Cell& base, const std::vector<FaceShadow>& shadows,
                               double min_area) {
    std::vector<Cell> layer;
    std::vector<Polygon2> rest, remaining, outside;
    for (const FaceShadow& s : shadows) {
        const std::uint64_t bit = std::uint64_t{1} << s.light;
        rest.assign(1, s.polygon);
        for (const Cell& c : layer) {
            remaining.clear();
            for (Polygon2& r : rest) {
                if (bounds_apart(r, c.loop)) {
                    remaining.push_back(std::move(r));
                    continue;
                }
                outside.clear();
                (void)split_by_convex(r, c.loop, min_area, outside);
                for (Polygon2& o : outside) remaining.push_back(std::move(o));
            }
            rest.swap(remaining);
            if (rest.empty()) break;
        }
        split_cells(layer, s.polygon, min_area, [&](Cell& cell) { cell.shadowed |= bit; });
        for (Polygon2& r : rest) {
            Cell cell = base;
            cell.loop = std::move(r);
            cell.shadowed = bit;
            cell.role = ShapeRole::kShadow;
            layer.push_back(std::move(cell));
        }
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
        face.reflectance = f.reflectance;
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
                cell.reflectance = p.reflectance;
                cell.value = p.reflectance;
                cell.role = ShapeRole::kPattern;
                patterns.push_back(std::move(cell));
            }
        }
        st.patterns += patterns.size();
        if (!shadows.empty() && !shadows[k].empty()) {
            std::vector<Cell> layer = shadow_cells(face, shadows[k], min_area);
            // What lies under each shadow cell: the patterns over it, later over earlier.
            for (const Cell& p : patterns) {
                split_cells(layer, p.loop, min_area,
                            [&](Cell& c) { c.reflectance = p.reflectance; });
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
