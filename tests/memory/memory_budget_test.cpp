// MemoryBudget: one cap per command, charged before allocating, refused in one line.
#include <doctest/doctest.h>

#include <limits>

#include "memory/memory_budget.h"

using namespace radiant;

static std::string refusal_of(MemoryBudget& budget, uint64_t bytes, const std::string& what) {
  try {
    budget.charge(bytes, what);
  } catch (const MemoryLimitError& error) {
    return error.what();
  }
  return "charged";
}

TEST_CASE("memory budget: a charge over the limit is refused with what needed how much against which limit") {
  MemoryBudget budget(100 << 20);
  CHECK(refusal_of(budget, uint64_t(1900) << 20, "model.gltf: meshes[0].primitives[0].attributes.POSITION") ==
        "model.gltf: meshes[0].primitives[0].attributes.POSITION: 1.86 GiB needed, over the memory limit of "
        "100 MiB (--max-memory)");
  CHECK(budget.used() == 0);  // a refused charge charges nothing
  CHECK(refusal_of(budget, 60 << 20, "a") == "charged");
  CHECK(refusal_of(budget, 50 << 20, "b.obj") ==
        "b.obj: 50.0 MiB needed (with 60.0 MiB already in use), over the memory limit of 100 MiB (--max-memory)");
  CHECK(refusal_of(budget, 40 << 20, "c") == "charged");
  CHECK(budget.used() == 100 << 20);  // exactly the limit is allowed
  budget.release(70 << 20);
  CHECK(budget.used() == 30 << 20);
  budget.release(uint64_t(1) << 40);  // never below zero
  CHECK(budget.used() == 0);
}

TEST_CASE("memory budget: the limit names where it comes from") {
  MemoryBudget budget(1 << 30, default_memory_limit_source);
  CHECK(refusal_of(budget, uint64_t(3) << 30, "f") ==
        "f: 3.00 GiB needed, over the memory limit of 1.00 GiB (a quarter of RAM; raise it with --max-memory)");
}

TEST_CASE("memory budget: no charge can wrap around the limit") {
  MemoryBudget budget(1000);
  CHECK(budget.try_charge(600));
  CHECK_FALSE(budget.try_charge(std::numeric_limits<uint64_t>::max()));
  CHECK_FALSE(budget.try_charge(std::numeric_limits<uint64_t>::max() - 300));
  CHECK(budget.used() == 600);
  CHECK(saturating_multiply(uint64_t(1) << 40, uint64_t(1) << 40) == std::numeric_limits<uint64_t>::max());
  CHECK(saturating_multiply(3, 5) == 15);
  MemoryBudget uncapped(std::numeric_limits<uint64_t>::max());
  CHECK(uncapped.try_charge(uint64_t(1) << 62));
}

TEST_CASE("memory budget: a MemoryCharge gives its bytes back when it dies or is replaced") {
  MemoryBudget budget(1000);
  {
    MemoryCharge film(&budget, 400, "film");
    CHECK(budget.used() == 400);
    MemoryCharge moved = std::move(film);
    CHECK(budget.used() == 400);
    moved = MemoryCharge(&budget, 100, "smaller");
    CHECK(budget.used() == 100);
    CHECK_THROWS_AS(MemoryCharge(&budget, 901, "too much"), MemoryLimitError);
    CHECK(budget.used() == 100);
  }
  CHECK(budget.used() == 0);
  MemoryCharge nothing(nullptr, uint64_t(1) << 60, "no budget, no cap");
  CHECK(nothing.bytes() == 0);
}

TEST_CASE("memory budget: an adopted charge gives back what a loader charged raw, once") {
  MemoryBudget budget(1000);
  budget.charge(300, "a frame's scene");
  {
    MemoryCharge scene = MemoryCharge::adopt(&budget, 300);
    CHECK(budget.used() == 300);  // adopting charges nothing more
    CHECK(scene.bytes() == 300);
    scene = MemoryCharge::adopt(&budget, 0);  // replaced: the old bytes go back
    CHECK(budget.used() == 0);
  }
  CHECK(budget.used() == 0);
  CHECK(MemoryCharge::adopt(nullptr, 300).bytes() == 0);
}

TEST_CASE("memory budget: sizes read like people write them") {
  CHECK(format_bytes(0) == "0 bytes");
  CHECK(format_bytes(1) == "1 byte");
  CHECK(format_bytes(1023) == "1023 bytes");
  CHECK(format_bytes(1536) == "1.50 KiB");
  CHECK(format_bytes(uint64_t(100) << 20) == "100 MiB");
  CHECK(format_bytes(uint64_t(1) << 40) == "1.00 TiB");
}
