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

#include "methods/method.h"
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

// What the estimates need to know of a scene: SceneSize (methods/method_traits.h), so that each
// method's row can make its own.
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

// The time of one render of `method` on a scene of this size, in ms on the cost model's
// machine: the row's estimate (MethodTraits::time_ms, methods/cost_model.h), deterministic,
// never measured here. Finite and positive for any scene.
double estimate_render_ms(const MethodInstance& method, const SceneSize& scene);

// Throws InputError "<what>: needs about 12.3 GiB by estimate (...), more than the memory
// budget of 8 GiB" when `bytes` exceeds `budget`.
void check_job_memory(std::size_t bytes, std::size_t budget, const std::string& what);

// Throws InputError naming `where` when `tasks` exceeds kMaxCompareTasks.
void check_task_count(long long tasks, const std::string& where);

// "12.3 GiB", "840 MiB", "5.0 KiB", "17 bytes".
std::string format_bytes(std::size_t bytes);

}  // namespace aabench
