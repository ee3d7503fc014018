#include "load_options.h"

namespace radiant {

void charge_load(const LoadOptions& options, uint64_t bytes, const std::string& what) {
  if (!options.budget->try_charge(bytes)) throw LoadError(options.budget->refusal(bytes, what));
}

BudgetedLoadOptions::BudgetedLoadOptions(const LoadOptions& given) : options(given) {
  if (options.budget) return;
  if (given.max_memory_bytes > 0) own_budget.emplace(given.max_memory_bytes, "--max-memory");
  else own_budget.emplace(default_memory_limit(), default_memory_limit_source);
  options.budget = &*own_budget;
}

}  // namespace radiant
