// SPDX-License-Identifier: Apache-2.0
// scw_ram_sdp, whole and split (top bits and a tail of words in distributed RAM), against a
// plain array: a registered, read-first read and a write every clock, the same with every split.
#include <catch2/catch.hpp>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "Vram_split.h"
#include "Vram_split_scw_ram_sdp.h"
#include "Vram_whole.h"
#include "Vram_whole_scw_ram_sdp.h"
#include "sim/rtl/verilated_harness.hpp"

namespace {

// The split RAM keeps its words 64 .. 79 in LUT RAM, and every word's top 4 bits.
static_assert(Vram_split_scw_ram_sdp::BlockDepth < Vram_split_scw_ram_sdp::Depth &&
              Vram_split_scw_ram_sdp::LutBits > 0);
static_assert(Vram_whole_scw_ram_sdp::BlockDepth == Vram_whole_scw_ram_sdp::Depth &&
              Vram_whole_scw_ram_sdp::LutBits == 0);

/// Random reads and writes, many of them to one address in one clock and around the block /
/// tail boundary; every clock the read register must hold what the array held before the write.
template <typename VM, typename P>
void check_ram(std::uint32_t seed) {
  constexpr int kDepth = static_cast<int>(P::Depth);
  constexpr int kWidth = static_cast<int>(P::Width);
  const std::uint64_t mask = (kWidth >= 64) ? ~0ull : ((1ull << kWidth) - 1);
  const auto ctx = scw::sim::single_model_context();
  auto ram = std::make_unique<VM>(ctx.get(), "ram");
  std::vector<std::uint64_t> model(kDepth, 0);
  std::uint64_t expect = 0;
  bool known = false;
  std::mt19937_64 rng(seed);
  const int edge = static_cast<int>(P::BlockDepth);
  auto addr = [&] {
    const int pick = static_cast<int>(rng() % 4);
    if (pick == 0) return static_cast<int>(edge - 2 + rng() % 4) % kDepth;  // the boundary
    return static_cast<int>(rng() % kDepth);
  };
  ram->clk_i = 0;
  ram->eval();
  // Fill every word first, so every later read is of a written word.
  for (int a = 0; a < kDepth + 4000; ++a) {
    const bool fill = a < kDepth;
    ram->wr_en_i = fill || (rng() % 3 != 0);
    ram->wr_addr_i = fill ? a : addr();
    ram->wr_data_i = rng() & mask;
    ram->rd_en_i = !fill && (rng() % 4 != 0);
    ram->rd_addr_i = (rng() % 3 == 0) ? ram->wr_addr_i : addr();
    if (ram->rd_en_i) {
      expect = model[ram->rd_addr_i];  // read-first: the word before this clock's write
      known = true;
    }
    if (ram->wr_en_i) model[ram->wr_addr_i] = ram->wr_data_i;
    ram->clk_i = 1;
    ram->eval();
    ram->clk_i = 0;
    ram->eval();
    if (known) REQUIRE(static_cast<std::uint64_t>(ram->rd_data_o) == expect);
  }
  ram->final();
}

TEST_CASE("scw_ram_sdp reads the word before the clock's write, whole or split", "[rtl][ram]") {
  SECTION("whole") { check_ram<Vram_whole, Vram_whole_scw_ram_sdp>(3); }
  SECTION("top bits and a tail in LUT RAM") { check_ram<Vram_split, Vram_split_scw_ram_sdp>(5); }
}

}  // namespace
