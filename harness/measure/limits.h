// Limits on what one job may ask for, checked before the work allocates anything big, and the
// memory estimate that refuses a job over budget. The limits themselves and how the estimate
// is made are in docs/limits.md; the CLI calls these (only the CLI parses arguments).
//
// Limits enforced elsewhere, listed here for one view:
//   image size      kMaxImageSide, kMaxImagePixels          patterns/scene/scene.h, check_image_size
//   vertex count    kMaxSceneVertices                       patterns/scene/scene.h, the scene reader
//   n, k            box-/gauss-multiscan n 1..256, ssaa k 1..64: the registry's ranges
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "patterns/scene/scene.h"

namespace aabench {

// Memory a job may use by default: 8 GiB, half of a 16 GiB workstation, so that a refused job
// is one that would have pushed an ordinary machine into swap. The estimate below is of the
// peak; the CLI may take another budget.
inline constexpr std::size_t kDefaultMemoryBudgetBytes = std::size_t{8} << 30;
// Tasks (pattern x method spec, sweep points included) in one comparison run. Each task keeps
// a result row and, for the report, may keep an image; 100,000 rows is far beyond any sweep
// the report can show, and a mistyped sweep should stop before it starts.
inline constexpr long long kMaxCompareTasks = 100000;

// What the estimate needs to know of a scene: sizes, not geometry.
struct SceneSize {
    long long width = 0;
    long long height = 0;
    long long vertices = 0;
    long long contours = 0;
    long long shapes = 0;
    // Sum over non-horizontal edges of the image rows each overlaps (clipped to the image):
    // the size of the edge table's row buckets, which an edge 60,000 rows tall in a scene of
    // 10^6 edges would make the largest allocation of all.
    long long edge_rows = 0;
    // Sum over edges of the image columns each spans (clipped): the peers' cell counts.
    long long edge_columns = 0;
    // Affine values (depth images) or discs and rings: `exact` integrates those into a whole
    // double raster (piece_coverage.h, curve_coverage.h); plain polygons it does row by row.
    bool exact_raster = false;
};

// O(vertices), allocating nothing.
SceneSize measure_scene(const Scene& scene);

// An estimate of the peak bytes of one job: the scene itself, plus, for each method spec and
// each reference spec ("box", "gaussian[:...]", "cone[:...]"), its working memory, taken one
// at a time (the largest counts), plus the images kept: one float32 image per method and one
// double raster per reference. `concurrent` > 1 multiplies the working part (parallel tasks).
// Specs are checked (InputError for an unknown one). Documented in docs/limits.md.
std::size_t estimate_job_bytes(const SceneSize& scene, const std::vector<std::string>& method_specs,
                               const std::vector<std::string>& reference_specs,
                               int concurrent = 1);

// Throws InputError "<what>: needs about 12.3 GiB by estimate (...), more than the memory
// budget of 8 GiB" when `bytes` exceeds `budget`.
void check_job_memory(std::size_t bytes, std::size_t budget, const std::string& what);

// Throws InputError naming `where` when `tasks` exceeds kMaxCompareTasks.
void check_task_count(long long tasks, const std::string& where);

// "12.3 GiB", "840 MiB", "5.0 KiB", "17 bytes".
std::string format_bytes(std::size_t bytes);

}  // namespace aabench
