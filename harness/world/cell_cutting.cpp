// The cells: each face cut into disjoint convex cells by its patterns and its shadows
// (docs/world.md, "The stages"), what every method but the scanline ones and every reference
// take (the scanline methods take the overlay, harness/world/overlay.h).
#include <algorithm>
#include <cmath>

#include "harness/world/stages.h"

namespace aabench {
namespace {

// Above this many patterns on one face the patterns stage cuts the face tile by tile (a grid
// of about kPatternsPerTile patterns per tile): cutting every cell by every pattern costs
// patterns x cells, quadratic in the patterns, which a checkerboard of thousands of squares
// cannot afford. Below it (every built-in pattern but the checkerboard) the face is cut whole,
// so those cells stay as they always were.
constexpr std::size_t kTiledPatterns = 64;
constexpr double kPatternsPerTile = 4.0;

// The patterns of one face cut tile by tile: the tiles (the face clipped to a grid over its
// bounds) in row-major order, each cut by the patterns whose bounds meet it, in their order.
// The cells are the same regions as cutting the whole face, cut also along the tile lines.
std::vector<Cell> cut_patterns_tiled(const Cell& whole, const std::vector<Polygon2>& cutters,
                                     const std::vector<const FacePattern*>& patterns,
                                     double min_area, std::size_t& made) {
    const Box2 face = bounds(whole.loop);
    const int side = static_cast<int>(
        std::ceil(std::sqrt(static_cast<double>(cutters.size()) / kPatternsPerTile)));
    const glm::dvec2 step = (face.hi - face.lo) / static_cast<double>(side);
    std::vector<std::vector<std::size_t>> in_tile(static_cast<std::size_t>(side) * side);
    auto tile_of = [&](double v, double lo, double d) {
        return std::clamp(static_cast<int>(std::floor((v - lo) / d)), 0, side - 1);
    };
    for (std::size_t p = 0; p < cutters.size(); ++p) {
        if (cutters[p].empty()) continue;
        const Box2 b = bounds(cutters[p]);
        const int i0 = tile_of(b.lo.x, face.lo.x, step.x), i1 = tile_of(b.hi.x, face.lo.x, step.x);
        const int j0 = tile_of(b.lo.y, face.lo.y, step.y), j1 = tile_of(b.hi.y, face.lo.y, step.y);
        for (int j = j0; j <= j1; ++j) {
            for (int i = i0; i <= i1; ++i)
                in_tile[static_cast<std::size_t>(j) * side + i].push_back(p);
        }
    }
    std::vector<Cell> out, tile_cells;
    for (int j = 0; j < side; ++j) {
        for (int i = 0; i < side; ++i) {
            // The last tile of a row or column ends at the face's bound itself (no rounding).
            const double x0 = face.lo.x + i * step.x, y0 = face.lo.y + j * step.y;
            const double x1 = i + 1 == side ? face.hi.x : x0 + step.x;
            const double y1 = j + 1 == side ? face.hi.y : y0 + step.y;
            Cell tile = whole;
            tile.loop = clip_convex(whole.loop, Polygon2{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
            if (std::abs(twice_area(tile.loop)) <= min_area) continue;
            tile_cells.assign(1, std::move(tile));
            for (const std::size_t p : in_tile[static_cast<std::size_t>(j) * side + i]) {
                split_cells(tile_cells, cutters[p], min_area, [&](Cell& c) {
                    c.take_reflectance(*patterns[p]);
                    c.role = ShapeRole::kPattern;
                    ++made;
                });
            }
            for (Cell& c : tile_cells) out.push_back(std::move(c));
        }
    }
    return out;
}

}  // namespace

Box2 bounds(const Polygon2& poly) {
    Box2 b;
    for (const glm::dvec2& p : poly) {
        b.lo = glm::min(b.lo, p);
        b.hi = glm::max(b.hi, p);
    }
    return b;
}

// Strictly apart: some axis-aligned line has one box wholly on each side.
bool apart(const Box2& a, const Box2& b) {
    return a.hi.x < b.lo.x || b.hi.x < a.lo.x || a.hi.y < b.lo.y || b.hi.y < a.lo.y;
}

BoxedCells::BoxedCells(std::vector<Cell> from) {
    for (Cell& c : from) push(std::move(c));
}

void BoxedCells::push(Cell cell) {
    const int n = static_cast<int>(cells.size());
    boxes.push_back(bounds(cell.loop));
    cells.push_back(std::move(cell));
    next.push_back(-1);
    (last < 0 ? head : next[last]) = n;
    last = n;
}

void BoxedCells::split(const Polygon2& cutter, double min_twice_area,
                       const std::function<void(Cell&)>& mark) {
    // Each cell as split_cells() treats it (below): apart from the cutter's bounds, or nothing
    // inside, and it stays; else its parts outside, then the part inside, take its place.
    const Box2 cutter_box = bounds(cutter);
    std::vector<Polygon2> outside;
    for (int n = head; n >= 0;) {
        const int after = next[n];
        if (apart(boxes[n], cutter_box)) {
            n = after;
            continue;
        }
        outside.clear();
        Polygon2 inside = split_by_convex(cells[n].loop, cutter, min_twice_area, outside);
        if (inside.empty()) {
            n = after;
            continue;
        }
        const Cell original = std::move(cells[n]);
        int at = -1;  // the node the next part goes into: n first, then new nodes after it
        auto place = [&](Cell part) {
            if (at < 0) {
                at = n;
                boxes[n] = bounds(part.loop);
                cells[n] = std::move(part);
                return;
            }
            const int m = static_cast<int>(cells.size());
            boxes.push_back(bounds(part.loop));
            cells.push_back(std::move(part));
            next.push_back(next[at]);
            next[at] = m;
            if (last == at) last = m;
            at = m;
        };
        for (Polygon2& o : outside) {
            Cell part = original;
            part.loop = std::move(o);
            place(std::move(part));
        }
        Cell in = original;
        in.loop = std::move(inside);
        mark(in);
        place(std::move(in));
        n = after;
    }
}

std::vector<Cell> BoxedCells::take() {
    std::vector<Cell> out;
    out.reserve(cells.size());
    for (int n = head; n >= 0; n = next[n]) out.push_back(std::move(cells[n]));
    return out;
}

void split_cells(std::vector<Cell>& cells, const Polygon2& cutter, double min_twice_area,
                 const std::function<void(Cell&)>& mark) {
    std::vector<Cell> out;
    out.reserve(cells.size() + cutter.size());
    std::vector<Polygon2> outside;
    const Box2 cutter_box = bounds(cutter);
    for (Cell& c : cells) {
        // A cell strictly apart from the cutter's bounds has nothing inside it: kept as it is,
        // as the split below would keep it, without the clipping (a face with many small
        // patterns is mostly cells far from each one).
        if (apart(bounds(c.loop), cutter_box)) {
            out.push_back(std::move(c));
            continue;
        }
        outside.clear();
        Polygon2 inside = split_by_convex(c.loop, cutter, min_twice_area, outside);
        if (inside.empty()) {  // untouched (or only slivers inside): keep the cell as it was
            out.push_back(std::move(c));
            continue;
        }
        for (Polygon2& o : outside) {
            Cell part = c;
            part.loop = std::move(o);
            out.push_back(std::move(part));
        }
        Cell in = c;
        in.loop = std::move(inside);
        mark(in);
        out.push_back(std::move(in));
    }
    cells = std::move(out);
}

std::size_t cut_patterns(const World& world, const std::vector<WorldFace>& faces,
                         std::vector<std::vector<Cell>>& cells) {
    ++work_counts().cut_patterns;
    std::size_t made = 0;
    for (std::size_t k = 0; k < faces.size(); ++k) {
        const WorldFace& f = faces[k];
        if (!f.visible) continue;
        const Polygon2 face_loop = face_outline(f);
        const double min_area = sliver_twice_area(face_loop);
        const std::vector<FacePattern>& patterns = world.objects[f.object].faces[f.index].patterns;
        if (patterns.size() > kTiledPatterns && cells[k].size() == 1) {
            std::vector<Polygon2> cutters;
            std::vector<const FacePattern*> sources;
            for (const FacePattern& p : patterns) {
                Polygon2 cutter = clip_convex(in_face_frame(f, p.loop), face_loop);
                if (std::abs(twice_area(cutter)) <= min_area) cutter.clear();
                cutters.push_back(std::move(cutter));
                sources.push_back(&p);
            }
            cells[k] = cut_patterns_tiled(cells[k][0], cutters, sources, min_area, made);
            continue;
        }
        for (const FacePattern& p : patterns) {
            const Polygon2 cutter = clip_convex(in_face_frame(f, p.loop), face_loop);
            if (std::abs(twice_area(cutter)) <= min_area) continue;
            split_cells(cells[k], cutter, min_area, [&](Cell& c) {
                c.take_reflectance(p);
                c.role = ShapeRole::kPattern;
                ++made;
            });
        }
    }
    return made;
}

std::vector<Cell> cut_face_by_shadows(std::vector<Cell> cells,
                                      const std::vector<FaceShadow>& shadows, double min_area) {
    BoxedCells face(std::move(cells));
    for (const FaceShadow& s : shadows) {
        const std::uint64_t bit = std::uint64_t{1} << s.light;
        face.split(s.polygon, min_area, [&](Cell& cell) {
            cell.shadowed |= bit;
            cell.role = ShapeRole::kShadow;
        });
    }
    return face.take();
}

void cut_shadows(const std::vector<WorldFace>& faces, const ShadowsByFace& shadows,
                 std::vector<std::vector<Cell>>& cells) {
    for (std::size_t r = 0; r < faces.size(); ++r) {
        if (shadows[r].empty() || cells[r].empty()) continue;
        cells[r] = cut_face_by_shadows(std::move(cells[r]), shadows[r],
                                       sliver_twice_area(face_outline(faces[r])));
    }
}

}  // namespace aabench
