// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Loops over independent items: run by TBB's threads when CGAL is linked with TBB
// (CGAL::Parallel_if_available_tag), one after the other otherwise. Each item writes only its own
// outputs and draws its own random numbers, so results do not depend on the number of threads.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_PARALLEL_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_PARALLEL_H

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// function(i) for i in [0, n), by tasks of at least `grain` indices (items that are blocks of
// work already take a grain of 1: a range no larger than its grain is never split).
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename Function>
void for_each_index(std::size_t n, const Function& function, std::size_t grain = 256)
{
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for(std::size_t i = range.begin(); i != range.end(); ++i)
                          function(i);
                      });
    return;
  }
#endif
  for(std::size_t i = 0; i < n; ++i)
    function(i);
}

// function(i, list) for i in [0, n), by blocks in parallel, each block into its own list; then
// the lists appended to `out` in the order of the blocks: the same `out` whatever the threads.
template <typename T, typename Function>
void collect_by_blocks(std::size_t n, std::vector<T>& out, const Function& function)
{
  const std::size_t block = 1024, number_of_blocks = (n + block - 1) / block;
  std::vector<std::vector<T> > found(number_of_blocks);
  for_each_index(
    number_of_blocks,
    [&](std::size_t bi) {
      for(std::size_t i = bi * block; i < (std::min)(n, (bi + 1) * block); ++i)
        function(i, found[bi]);
    },
    1);
  for(const std::vector<T>& items : found)
    out.insert(out.end(), items.begin(), items.end());
}

// A seed for the random numbers of one item in one round, from the user's seed: the same
// whatever thread draws them (splitmix64's finaliser).
inline unsigned int item_seed(unsigned int seed, std::size_t round, std::size_t item)
{
  auto mix = [](std::uint64_t h) {
    h += 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
    return h ^ (h >> 31);
  };
  return static_cast<unsigned int>(mix(mix(mix(seed) + round) + item));
}

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_PARALLEL_H
