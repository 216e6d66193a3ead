// SPDX-License-Identifier: Apache-2.0
// The sharding rule (host/app/shard.hpp) and where a sharded sequence restarts its state
// (host/app/sequence.hpp, plan_split), and the merge on hand-made shards
// (host/app/shard_merge.hpp): docs/slurm.md.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "host/app/sequence.hpp"
#include "host/app/shard.hpp"
#include "host/app/shard_merge.hpp"

using scw::app::parse_shard;
using scw::app::plan_split;
using scw::app::segments_of;
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

TEST_CASE("segments_of gives each segment of a plan as a block, empty ones left out", "[app]") {
  const auto segs = segments_of(plan_split({{1, 2}, 4}, 8));  // --shard 1/2 --segments 4
  REQUIRE(segs.size() == 2);
  CHECK((segs[0].begin == 4 && segs[0].end == 6));
  CHECK((segs[1].begin == 6 && segs[1].end == 8));
  // More segments than frames: a segment would be empty, so there are only as many as frames.
  const auto few = segments_of(plan_split({{0, 1}, 4}, 2));
  REQUIRE(few.size() == 2);
  CHECK((few[0].begin == 0 && few[0].end == 1 && few[1].begin == 1 && few[1].end == 2));
  CHECK(segments_of(plan_split({{0, 2}, 0}, 1)).empty());  // shard 0 of 2 of one frame: none
}

TEST_CASE("merge_shards joins results in shard order, an empty shard's too", "[app]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "scw_test_merge_shards";
  fs::remove_all(dir);
  // 1 frame in 2 shards: shard 0 has none, shard 1 frame 0.
  for (int i = 0; i < 2; ++i) {
    const fs::path d = dir / std::to_string(i);
    fs::create_directories(d);
    std::ofstream(d / "results.jsonl") << (i == 1 ? "{\"frame\":0}\n" : "");
    if (i == 1) std::ofstream(d / "0000_objects.csv") << "label\n";
    scw::app::write_shard_manifest(
        d, {"run", {i, 2}, shard_range({i, 2}, 1), 1, "frames", "x=1\n", {"results.jsonl"}});
  }
  const auto r = scw::app::merge_shards({dir / "1", dir / "0"}, dir / "merged");
  CHECK(r.shards == 2);
  CHECK(r.files == 2);
  std::ifstream in(dir / "merged" / "results.jsonl");
  const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(all == "{\"frame\":0}\n");
  CHECK(fs::exists(dir / "merged" / "0000_objects.csv"));
  CHECK_FALSE(fs::exists(dir / "merged" / "shard.json"));
  CHECK_THROWS_WITH(scw::app::merge_shards({dir / "1"}, dir / "m2"),
                    Catch::Contains("shard(s) 0 of 2 missing"));
  fs::remove_all(dir);
}
