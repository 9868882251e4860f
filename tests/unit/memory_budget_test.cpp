// The memory budget: reservations are released on every path, refusals say whether a retry can help,
// cache entries are evicted least recently used first, and concurrent reservations never overshoot.
#include "engine/core/memory_budget.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "engine/envmap/envmap.hpp"
#include "engine/envmap/envmap_sampler.hpp"
#include "engine/envmap/sample_set.hpp"
#include "engine/mediancut/median_cut.hpp"

namespace lp {
namespace {

TEST(MemoryBudget, ReservationsAreCountedAndReleasedWhenDestroyed) {
  MemoryBudget budget(1000);
  {
    const auto a = budget.reserve(300, MemoryUse::Held, "a");
    const auto b = budget.reserve(200, MemoryUse::Transient, "b");
    EXPECT_EQ(budget.used(), 500);
    EXPECT_EQ(budget.used(MemoryUse::Held), 300);
    EXPECT_EQ(budget.used(MemoryUse::Transient), 200);
  }
  EXPECT_EQ(budget.used(), 0);
}

TEST(MemoryBudget, NothingLeaksWhenTheWorkThrows) {
  MemoryBudget budget(1000);
  auto work = [&] {
    const auto pixels = budget.reserve(600, MemoryUse::Transient, "decoding");
    throw std::runtime_error("corrupt");
  };
  EXPECT_THROW(work(), std::runtime_error);
  EXPECT_EQ(budget.used(), 0);
  EXPECT_NO_THROW(budget.reserve(1000, MemoryUse::Transient, "all of it"));
}

TEST(MemoryBudget, MovedReservationsAreReleasedOnce) {
  MemoryBudget budget(1000);
  MemoryReservation outer;
  {
    auto inner = budget.reserve(400, MemoryUse::Transient, "x");
    outer = std::move(inner);
  }
  EXPECT_EQ(budget.used(), 400);
  EXPECT_EQ(outer.bytes(), 400);
  outer = budget.reserve(100, MemoryUse::Transient, "y");  // the 400 go back first
  EXPECT_EQ(budget.used(), 100);
  outer.release();
  outer.release();
  EXPECT_EQ(budget.used(), 0);
}

TEST(MemoryBudget, RefusalsTellWhetherARetryCanSucceed) {
  MemoryBudget budget(1000);
  const auto held = budget.reserve(600, MemoryUse::Held, "a map");
  auto in_flight = budget.reserve(300, MemoryUse::Transient, "an encoding");
  try {
    budget.reserve(200, MemoryUse::Transient, "a picture");
    FAIL() << "over budget";
  } catch (const MemoryBudgetError& e) {
    EXPECT_TRUE(e.transient()) << e.what();  // fits once the encoding ends
    EXPECT_NE(std::string(e.what()).find("a picture"), std::string::npos) << e.what();
  }
  try {
    budget.reserve(500, MemoryUse::Transient, "a big picture");
    FAIL() << "over budget";
  } catch (const MemoryBudgetError& e) {
    EXPECT_FALSE(e.transient()) << e.what();  // cannot fit while the map is held
  }
  EXPECT_THROW(budget.reserve(1001, MemoryUse::Transient, "more than everything"), MemoryBudgetError);
  EXPECT_EQ(budget.used(), 900);
  in_flight.release();
  EXPECT_NO_THROW(budget.reserve(400, MemoryUse::Transient, "a picture"));
}

TEST(MemoryBudget, ResizeGrowsWithinTheBudgetAndKeepsTheOldSizeWhenRefused) {
  MemoryBudget budget(1000);
  auto r = budget.reserve(100, MemoryUse::Transient, "x");
  r.resize(700);
  EXPECT_EQ(budget.used(), 700);
  EXPECT_THROW(r.resize(1200), MemoryBudgetError);
  EXPECT_EQ(r.bytes(), 700);
  EXPECT_EQ(budget.used(), 700);
  r.resize(50);
  EXPECT_EQ(budget.used(), 50);
  r.set_use(MemoryUse::Held);
  EXPECT_EQ(budget.used(MemoryUse::Held), 50);
  EXPECT_EQ(budget.used(MemoryUse::Transient), 0);
}

TEST(MemoryBudget, CacheEntriesAreEvictedLeastRecentlyUsedFirst) {
  MemoryBudget budget(1000);
  std::vector<std::string> evicted;
  MemoryReservation a, b, c;
  a = budget.reserve_cache(300, "a", [&] { evicted.push_back("a"), a.release(); });
  b = budget.reserve_cache(300, "b", [&] { evicted.push_back("b"), b.release(); });
  c = budget.reserve_cache(300, "c", [&] { evicted.push_back("c"), c.release(); });
  a.touch();  // b is now the least recently used, then c
  const auto big = budget.reserve(600, MemoryUse::Transient, "big");
  EXPECT_EQ(evicted, (std::vector<std::string>{"b", "c"}));
  EXPECT_EQ(budget.used(), 900);
}

TEST(MemoryBudget, AnEvictedEntryStillInUseIsNotCountedAsFree) {
  MemoryBudget budget(1000);
  int evictions = 0;
  auto in_use = budget.reserve_cache(800, "table", [&] { ++evictions; });  // its user keeps it
  try {
    budget.reserve(400, MemoryUse::Transient, "x");
    FAIL() << "the table is still in use";
  } catch (const MemoryBudgetError& e) {
    EXPECT_TRUE(e.transient());
  }
  EXPECT_EQ(evictions, 1);
  EXPECT_THROW(budget.reserve(400, MemoryUse::Transient, "x"), MemoryBudgetError);
  EXPECT_EQ(evictions, 1);  // evicted once only
  in_use.release();
  EXPECT_NO_THROW(budget.reserve(400, MemoryUse::Transient, "x"));
}

TEST(MemoryBudget, ConcurrentReservationsNeverOvershoot) {
  constexpr int64_t kCapacity = 10'000;
  MemoryBudget budget(kCapacity);
  std::atomic<int64_t> granted{0}, peak{0};
  std::atomic<int> refusals{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < 2000; ++i) {
        const int64_t bytes = 500 + 97 * ((t + i) % 23);
        try {
          const auto r = budget.reserve(bytes, MemoryUse::Transient, "work");
          const int64_t now = granted.fetch_add(bytes) + bytes;
          int64_t seen = peak.load();
          while (now > seen && !peak.compare_exchange_weak(seen, now)) {
          }
          granted.fetch_sub(bytes);
        } catch (const MemoryBudgetError&) {
          ++refusals;
        }
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_LE(peak.load(), kCapacity);
  EXPECT_EQ(budget.used(), 0);
}

Image flat_image(int width, int height) {
  Image image(width, height);
  for (float& v : image.data()) v = 1.0f;
  return image;
}

TEST(EnvMapMemory, DerivedDataIsReservedEvictedAndBuiltAgain) {
  const MemoryBudget budget(int64_t{1} << 20);
  auto map = std::make_shared<EnvMap>(flat_image(64, 32));
  map->account_memory(budget, budget.reserve(EnvMap::image_bytes(64, 32), MemoryUse::Held, "map"));
  int builds = 0;
  auto build = [&] {
    ++builds;
    return std::make_shared<const int>(7);
  };
  EXPECT_EQ(*map->derived<int>("table", 100'000, build), 7);
  EXPECT_EQ(map->memory_bytes(), EnvMap::image_bytes(64, 32) + 100'000);
  EXPECT_EQ(budget.used(MemoryUse::Cache), 100'000);
  map->derived<int>("table", 100'000, build);
  EXPECT_EQ(builds, 1);

  // Room for something that needs the table's bytes: the table goes, and comes back on its next use.
  auto other = budget.reserve(budget.capacity() - budget.used() + 50'000, MemoryUse::Transient, "other");
  EXPECT_EQ(map->memory_bytes(), EnvMap::image_bytes(64, 32));
  EXPECT_EQ(budget.used(MemoryUse::Cache), 0);
  EXPECT_THROW(map->derived<int>("table", 100'000, build), MemoryBudgetError);
  other.release();
  EXPECT_EQ(*map->derived<int>("table", 100'000, build), 7);
  EXPECT_EQ(builds, 2);
  map.reset();
  EXPECT_EQ(budget.used(), 0);
}

TEST(EnvMapMemory, MedianCutResultsAreCachedInTheBudgetAndEvictedFirst) {
  const MemoryBudget budget(int64_t{8} << 20);
  auto map = std::make_shared<EnvMap>(flat_image(64, 32));
  map->account_memory(budget, budget.reserve(EnvMap::image_bytes(64, 32), MemoryUse::Held, "map"));
  MedianCutParams params;
  params.count = 256;
  bool hit = true;
  median_cut_cached(*map, params, &hit);
  EXPECT_FALSE(hit);
  // The result and the summed-area table it was cut from are both cache entries of the map.
  EXPECT_GE(budget.used(MemoryUse::Cache),
            MedianCutResult::memory_bytes(256) + SummedAreaTable::memory_bytes(64, 32));
  median_cut_cached(*map, params, &hit);
  EXPECT_TRUE(hit);

  auto other = budget.reserve(budget.capacity() - EnvMap::image_bytes(64, 32), MemoryUse::Transient, "other");
  EXPECT_EQ(budget.used(MemoryUse::Cache), 0);
  other.release();
  median_cut_cached(*map, params, &hit);
  EXPECT_FALSE(hit);
}

TEST(EnvMapMemory, TheSamplerHoldsItsCdfsAndTheAliasTableIsReservedWhenIndependentSamplesAreDrawn) {
  const MemoryBudget budget(int64_t{8} << 20);
  auto map = std::make_shared<EnvMap>(flat_image(64, 32));
  map->account_memory(budget, budget.reserve(EnvMap::image_bytes(64, 32), MemoryUse::Held, "map"));
  const auto sampler = map->sampler(LuminanceMode::Average);
  EXPECT_EQ(budget.used(MemoryUse::Cache), EnvMapSampler::memory_bytes(64, 32));
  std::vector<EnvSample> out(16);
  generate_samples(*sampler, {SampleStrategy::Sobol, 16, 1}, 0, out);
  EXPECT_EQ(budget.used(MemoryUse::Cache), EnvMapSampler::memory_bytes(64, 32));
  generate_samples(*sampler, {SampleStrategy::Independent, 16, 1}, 0, out);
  EXPECT_EQ(map->memory_bytes(), EnvMap::image_bytes(64, 32) + EnvMapSampler::memory_bytes(64, 32) +
                                     AliasTable2D::memory_bytes(64, 32));
  // 8 bytes a cell (a threshold and an alias): the densities are the distribution's.
  EXPECT_EQ(AliasTable2D::memory_bytes(64, 32), 8 * (64 * 32 + 32));
}

}  // namespace
}  // namespace lp
