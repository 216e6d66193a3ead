// SPDX-License-Identifier: Apache-2.0
// The one Verilator harness: owns the context and the model; reset, tick, optional FST trace.
#pragma once

#include <verilated.h>
#include <verilated_fst_c.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "sim/rtl/quiet_cycles.hpp"

namespace scw::sim {

namespace detail {
/// Models Verilated without --trace (scw_verilate NO_TRACE) have no trace().
template <typename VM, typename = void>
struct has_trace : std::false_type {};
template <typename VM>
struct has_trace<VM, std::void_t<decltype(std::declval<VM&>().trace(
                         static_cast<VerilatedFstC*>(nullptr), 0))>> : std::true_type {};
}  // namespace detail

/// With SCW_VERILATOR_SEED=N (N >= 1) in the environment, every register and memory a model
/// does not reset starts at a random value drawn from seed N, and every explicit X the RTL assigns
/// is a random constant (the models are Verilated with --x-initial unique --x-assign unique;
/// Verilator 5.006's +verilator+rand+reset+2 and +verilator+seed+N). Verilator is a 2-state
/// simulator: without this those values read 0, and a design that depends on one passes here and
/// misbehaves on the board. Unset or 0, they are 0 as before. Set before the model is built:
/// its constructor draws the initial values.
inline void randomise_unreset_state(VerilatedContext& ctx) {
  const char* seed = std::getenv("SCW_VERILATOR_SEED");
  if (seed == nullptr || *seed == '\0') return;
  char* end = nullptr;
  const long n = std::strtol(seed, &end, 10);
  if (*end != '\0' || n < 0 || n > 0x7fffffff)
    throw std::invalid_argument(std::string("SCW_VERILATOR_SEED='") + seed +
                                "' is not a seed: give a whole number from 1 (0 or unset: no "
                                "randomisation)");
  if (n == 0) return;
  ctx.randReset(2);
  ctx.randSeed(static_cast<int>(n));
}

/// The clock cycles a trace keeps: SCW_FST_WINDOW=FROM:TO (the harness's own cycles, reset
/// included), or every cycle when unset. A long run traced whole is gigabytes; a window around
/// the cycle of interest is what one opens (scw soak writes one around its first divergence).
struct TraceWindow {
  std::uint64_t from = 0, to = ~std::uint64_t{0};
  static TraceWindow from_env() {
    TraceWindow w;
    const char* v = std::getenv("SCW_FST_WINDOW");
    if (v == nullptr || *v == '\0') return w;
    char* mid = nullptr;
    char* end = nullptr;
    w.from = std::strtoull(v, &mid, 10);
    if (mid == v || *mid != ':') bad(v);
    w.to = std::strtoull(mid + 1, &end, 10);
    if (end == mid + 1 || *end != '\0' || w.to < w.from) bad(v);
    return w;
  }
  bool holds(std::uint64_t cycle) const { return cycle >= from && cycle <= to; }

 private:
  [[noreturn]] static void bad(const char* v) {
    throw std::invalid_argument(std::string("SCW_FST_WINDOW='") + v +
                                "' is not a cycle window: give FROM:TO, two whole numbers, FROM "
                                "<= TO (unset: every cycle)");
  }
};

/// The Verilator symbol-table class of model `VM`, which holds the whole of its state (every
/// module instance's variables, and the input ports). SCW_MODEL_STATE(VM) names it where
/// VM__Syms.h is included (sim/builds/, for every model of a pipeline build); elsewhere it is
/// unknown (void) and the harness never skips a cycle (Harness::settle).
template <typename VM>
struct ModelSyms {
  using type = void;
};
#define SCW_MODEL_STATE(VM)    \
  namespace scw::sim {         \
  template <>                  \
  struct ModelSyms<::VM> {     \
    using type = ::VM##__Syms; \
  };                           \
  }

/// SCW_SKIP_IDLE=0 in the environment: every cycle of every model is evaluated (Harness::settle
/// skips none), to rule the skipping out when something looks wrong. It changes no result.
inline bool skipping_off() {
  const char* v = std::getenv("SCW_SKIP_IDLE");
  return v != nullptr && std::string(v) == "0";
}

/// A context for one model Verilated single-threaded (scw Verilates every block without
/// --threads). Verilator 5.006's context otherwise starts a pool of (processors - 1) worker
/// threads when its first model is added, which such a model never uses: with a context per
/// block, a chain of 11 blocks on a 64-core node would start about 700 idle threads. The count
/// is fixed before the model is made (Verilator refuses a change after).
inline std::unique_ptr<VerilatedContext> single_model_context() {
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->threads(1);
  return ctx;
}

/// Owns a VerilatedContext and one model `VM` with ports `clk_i` and `rst_ni`.
/// Set the environment variable SCW_FST_DIR to a folder and every harness writes
/// `<folder>/<name>.fst` (open it with GTKWave), only the cycles of SCW_FST_WINDOW when that is
/// set; unset, nothing is traced and nothing is paid.
template <typename VM>
class Harness {
 public:
  explicit Harness(const std::string& name) : ctx_(single_model_context()) {
    const char* dir = std::getenv("SCW_FST_DIR");
    const bool tracing = kTraced && dir != nullptr && *dir != '\0';
    if (tracing) {
      window_ = TraceWindow::from_env();
      ctx_->traceEverOn(true);
    }
    randomise_unreset_state(*ctx_);
    dut_ = std::make_unique<VM>(ctx_.get(), name.c_str());
    if constexpr (kTraced) {
      if (tracing) {
        std::filesystem::create_directories(dir);
        trace_ = std::make_unique<VerilatedFstC>();
        dut_->trace(trace_.get(), 99);
        trace_->open((std::filesystem::path(dir) / (name + ".fst")).c_str());
      }
    }
    dut_->clk_i = 0;
    dut_->rst_ni = 1;
    dut_->eval();
    if constexpr (kStateKnown) {
      if (!tracing && !skipping_off())
        quiet_ = std::make_unique<QuietCycles>(
            reinterpret_cast<unsigned char*>(dut_->rootp->vlSymsp), sizeof(Syms));
    }
  }
  ~Harness() {
    // Verilator 5.006 erases a model's scopes from the thread's *current* context, which is
    // the last one evaluated on this thread, possibly another harness's, already destroyed
    // (a hang or worse). Point it at ours first.
    Verilated::threadContextp(ctx_.get());
    if constexpr (kTraced) {
      if (trace_) trace_->close();
    }
    dut_->final();
    dut_.reset();
  }
  Harness(const Harness&) = delete;
  Harness& operator=(const Harness&) = delete;

  VM& dut() { return *dut_; }
  std::uint64_t cycles() const { return cycles_; }

  /// Settles combinational logic after inputs change (no clock edge; after tick(), the falling
  /// edge too).
  void eval() {
    thaw();
    settle_now();
  }
  /// eval() for an adapter that says what it drove (`key`, QuietKey) and what it reads (`out`,
  /// the model to a QuietKey): the cycles in which the model only runs round a loop under
  /// unchanged inputs are skipped, settling and clock edge (sim/rtl/quiet_cycles.hpp; only for
  /// models whose state is known, ModelSyms, and untraced).
  template <typename Out>
  void settle(std::uint32_t key, Out&& out) {
    if (!quiet_) return eval();
    if (quiet_->skip(
            key, [this] { edge(); }, [this] { settle_now(); }))
      return;
    settle_now();
    quiet_->settled(key, out(static_cast<const VM&>(*dut_)));
  }
  /// Cycles skipped by settle() so far.
  std::uint64_t skipped() const { return quiet_ ? quiet_->skipped() : 0; }
  /// Holds rst_ni low for `cycles` clock cycles (the RTL resets synchronously, on these edges).
  void reset(int cycles = 2) {
    thaw();
    dut_->rst_ni = 0;
    for (int i = 0; i < cycles; ++i) tick();
    dut_->rst_ni = 1;
    eval();
  }
  /// One clock cycle: rising edge with the current inputs, then the falling edge.
  ///
  /// Traced, each half is evaluated and dumped. Untraced, the falling edge is left to the next
  /// eval() (no RTL of the project acts on a falling clock edge, and outputs depend only on state
  /// and inputs, so they read the same), and the eval before the rising edge is made only when
  /// none was made since the last edge: Verilator must see the clock low once between two
  /// rising edges, and it settles the logic fed by inputs changed since (its `ico` phase) before
  /// it fires the edge in the same eval(). The adapters settle every cycle (settle()) to
  /// read their outputs, so they pay one eval() a cycle here instead of three
  /// (docs/performance.md, "Simulation speed").
  void tick() {
    if (quiet_ && quiet_->frozen()) {
      ++cycles_;
      ctx_->timeInc(2);
      return;
    }
    if (tracing()) {
      dut_->eval();
      dump();
      dut_->clk_i = 1;
      dut_->eval();
      ctx_->timeInc(1);
      dump();
      dut_->clk_i = 0;
      dut_->eval();
      ctx_->timeInc(1);
    } else {
      if (!low_seen_) dut_->eval();
      edge();
      ctx_->timeInc(2);
    }
    ++cycles_;
  }

 private:
  using Syms = typename ModelSyms<VM>::type;
  static constexpr bool kStateKnown = !std::is_void_v<Syms>;

  /// Leaves a skipped loop at the phase it has reached (sim/rtl/quiet_cycles.hpp) and forgets
  /// the watch: the caller drives the model by other means. Between a clock edge and the next
  /// settle, as eval() and reset() are called.
  void thaw() {
    if (!quiet_) return;
    quiet_->skip(
        QuietKey::kBusy, [this] { edge(); }, [this] { settle_now(); });
    quiet_->forget();
  }
  void settle_now() {
    dut_->eval();
    low_seen_ = true;
  }
  /// The rising edge, the model having seen the clock low; the falling one is left to the next
  /// eval().
  void edge() {
    dut_->clk_i = 1;
    dut_->eval();
    dut_->clk_i = 0;
    low_seen_ = false;
  }

  bool tracing() const {
    if constexpr (kTraced) return trace_ != nullptr;
    return false;
  }
  void dump() {
    if constexpr (kTraced) {
      if (trace_ && window_.holds(cycles_)) trace_->dump(ctx_->time());
    }
  }

  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<VM> dut_;
  static constexpr bool kTraced = detail::has_trace<VM>::value;
  // Untraced models link no FST writer, so they hold no pointer to one either.
  std::conditional_t<kTraced, std::unique_ptr<VerilatedFstC>, std::unique_ptr<int>> trace_;
  TraceWindow window_;
  std::uint64_t cycles_ = 0;
  bool low_seen_ = true;  // an eval() saw the clock low since the last rising edge
  // Skipping still cycles (settle()), when the model's state is known and it is not traced.
  std::unique_ptr<QuietCycles> quiet_;
};

}  // namespace scw::sim
