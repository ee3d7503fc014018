// What every loader is given: the options of a load and the memory budget it charges.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "memory/memory_budget.h"
#include "scene/load_error.h"

namespace radiant {

struct LoadOptions {
  bool allow_external_files = false;  // let URIs and includes leave the scene's folder
  // Charged for everything loading allocates, before it is allocated (the command shares it
  // with the render). Null: the load makes its own budget of `max_memory_bytes`.
  MemoryBudget* budget = nullptr;
  size_t max_memory_bytes = 0;  // the limit of that own budget; 0 = default_memory_limit()
  int gltf_scene = -1;          // glTF scene index; -1 = the file's default scene
  std::string material_variant;  // KHR_materials_variants: the variant to use; "" = the default materials
  // glTF: sample `animation` (a name or index; "" = the first) at this time in seconds; unset =
  // the file's static state (docs/gltf-obj.md, "Animation").
  std::optional<double> animation_time;
  std::string animation;
  // Motion blur (--shutter): the animation also sampled from animation_time + open to
  // animation_time + close seconds, into the scene's motion steps (scene/motion_steps.h).
  struct Shutter {
    double open = 0, close = 0;
  };
  std::optional<Shutter> shutter;
  // Every file the load reads is appended here (load_scene sets it; SceneDesc::input_files).
  std::vector<std::string>* files_read = nullptr;
};

// Charges `bytes` for `what` (a file and a place) to options.budget, which must be set; throws
// LoadError with the budget's one-line refusal.
void charge_load(const LoadOptions& options, uint64_t bytes, const std::string& what);

// `given` with a budget for loaders called directly (tests, fuzzers): its own budget when it has
// one, else a new one of given.max_memory_bytes held here. Not copyable: `options.budget` may
// point into it.
struct BudgetedLoadOptions {
  std::optional<MemoryBudget> own_budget;
  LoadOptions options;
  explicit BudgetedLoadOptions(const LoadOptions& given);
  BudgetedLoadOptions(const BudgetedLoadOptions&) = delete;
  BudgetedLoadOptions& operator=(const BudgetedLoadOptions&) = delete;
};

}  // namespace radiant
