// SPDX-License-Identifier: Apache-2.0
// The sharding rule (host/app/shard.hpp) and where a sharded sequence restarts its state
// (host/app/sequence.hpp, plan_split): docs/slurm.md.
#include <catch2/catch.hpp>
#include <stdexcept>
#include <vector>

#include "host/app/sequence.hpp"
#include "host/app/shard.hpp"

using scw::app::parse_shard;
using scw::app::plan_split;
using scw::app::Shard;
using scw::app::shard_range;

TEST_CASE("parse_shard reads I/N and refuses anything else, naming the form", "[app]") {
  const Shard s = parse_shard("3/4");
  CHECK(s.index == 3);
  CHECK(s.count == 4);
  for (const char* bad : {"4/4", "1/0", "-1/4", "1", "a/4", "1/4/2", "", "/4", "1/"})
    CHECK_THROWS_WITH(parse_shard(bad), Catch::Contains("give I/N with 0 <= I < N"));
}

TEST_CASE("shard_range: contiguous blocks in order, every item in exactly one", "[app]") {
  for (std::size_t total : {0u, 1u, 3u, 7u, 49u, 1000u})
    for (int n = 1; n <= 9; ++n) {
      std::size_t next = 0;
      for (int i = 0; i < n; ++i) {
        const auto r = shard_range({i, n}, total);
        CHECK(r.begin == next);
        CHECK(r.size() + 1 >= total / n);  // sizes differ by at most one
        CHECK(r.size() <= total / n + 1);
        next = r.end;
      }
      CHECK(next == total);
    }
  CHECK(shard_range({2, 3}, 7).begin == 4);  // floor(2 * 7 / 3)
  CHECK(shard_range({2, 3}, 7).end == 7);
}

TEST_CASE("plan_split restarts a shard at its first frame and at the segments inside it", "[app]") {
  const auto one = plan_split({{0, 1}, 3}, 7);  // one process, --segments 3
  CHECK(one.range.begin == 0);
  CHECK(one.range.end == 7);
  CHECK(one.restarts == std::vector<std::size_t>{0, 2, 4});
  const auto shard = plan_split({{1, 3}, 0}, 7);  // --shard 1/3: segments default to 3
  CHECK(shard.restarts == std::vector<std::size_t>{2});
  const auto finer = plan_split({{1, 2}, 4}, 8);  // --shard 1/2 --segments 4
  CHECK(finer.restarts == std::vector<std::size_t>{4, 6});
  CHECK_THROWS_WITH(plan_split({{0, 3}, 4}, 7), Catch::Contains("give a multiple of N"));
}
