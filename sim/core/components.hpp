// SPDX-License-Identifier: Apache-2.0
// Components for the simulator: any one-in one-out cycle model, a beat source and a sink.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "sim/core/simulator.hpp"
#include "sim/core/stall.hpp"

namespace scw::sim {

/// Puts a cycle model (C++ twin or RtlStream) between two FIFOs. Its in_valid is "the input
/// FIFO has a beat" and its out_ready is "the output FIFO has space", both as of the start of
/// the cycle, exactly as if the RTL block were wired to two scw_fifo instances.
template <typename Model>
class StreamComponent : public Component {
 public:
  using In = typename Model::in_type;
  using Out = typename Model::out_type;

  StreamComponent(std::string name, Model model, Fifo<In>& in, Fifo<Out>& out)
      : Component(std::move(name)), model_(std::move(model)), in_(in), out_(out) {
    connect_in(in_);
    connect_out(out_);
  }

  void eval() override {
    const bool in_valid = in_.can_pop();
    const In beat = in_valid ? in_.front() : In{};
    const bool out_ready = out_.can_push();
    const auto o = model_.eval(in_valid, beat, out_ready);
    if (in_valid && o.in_ready) in_.pop();
    if (o.out_valid && out_ready) out_.push(o.out);
  }
  void tick() override { model_.tick(); }

  Model& model() { return model_; }

 private:
  Model model_;
  Fifo<In>& in_;
  Fifo<Out>& out_;
};

/// Feeds a list of beats into a FIFO, idling on the cycles its stall pattern says.
template <typename T>
class Source : public Component {
 public:
  Source(std::string name, Fifo<T>& out, std::vector<T> beats, const StallPattern& p = {})
      : Component(std::move(name)), out_(out), beats_(std::move(beats)),
        gen_(p, StallGen::Side::kInput) {
    connect_out(out_);
  }
  void eval() override {
    if (next_ >= beats_.size()) return;
    if (!offering_) offering_ = gen_.next();
    if (offering_ && out_.can_push()) {
      out_.push(beats_[next_++]);
      offering_ = false;
    }
  }
  void tick() override {}
  bool done() const { return next_ >= beats_.size(); }
  /// Offers `more` after the beats it holds (the next frame of a sequence fed as it is read);
  /// the beats already sent are dropped first when all are.
  void append(std::vector<T> more) {
    if (done()) {
      beats_ = std::move(more);
      next_ = 0;
    } else {
      beats_.insert(beats_.end(), more.begin(), more.end());
    }
  }

 private:
  Fifo<T>& out_;
  std::vector<T> beats_;
  StallGen gen_;
  std::size_t next_ = 0;
  bool offering_ = false;
};

/// Drains a FIFO into a list, refusing on the cycles its stall pattern says.
template <typename T>
class Sink : public Component {
 public:
  Sink(std::string name, Fifo<T>& in, const StallPattern& p = {})
      : Component(std::move(name)), in_(in), gen_(p, StallGen::Side::kOutput) {
    connect_in(in_);
  }
  void eval() override {
    if (gen_.next() && in_.can_pop()) {
      beats_.push_back(in_.front());
      in_.pop();
    }
  }
  void tick() override {}
  const std::vector<T>& beats() const { return beats_; }

 private:
  Fifo<T>& in_;
  StallGen gen_;
  std::vector<T> beats_;
};

/// Copies every beat of one FIFO into two, in lockstep: a beat leaves when both have room (the
/// twin of the fork in rtl_models/pipeline/scw_pipeline.sv, whose two readies are FIFO flags).
template <typename T>
class Fork : public Component {
 public:
  Fork(std::string name, Fifo<T>& in, Fifo<T>& a, Fifo<T>& b)
      : Component(std::move(name)), in_(in), a_(a), b_(b) {
    connect_in(in_);
    connect_out(a_);
    connect_out(b_);
  }
  void eval() override {
    if (!in_.can_pop() || !a_.can_push() || !b_.can_push()) return;
    a_.push(in_.front());
    b_.push(in_.front());
    in_.pop();
  }
  void tick() override {}

 private:
  Fifo<T>& in_;
  Fifo<T>& a_;
  Fifo<T>& b_;
};

/// Puts a source-shaped model in front of a FIFO, running whenever `run` says (default:
/// always), e.g. the map expander feeding a rectify stage's map FIFO.
template <typename Model>
class SourceModelComponent : public Component {
 public:
  using Out = typename Model::out_type;

  SourceModelComponent(std::string name, Model model, Fifo<Out>& out,
                       std::function<bool()> run = {})
      : Component(std::move(name)), model_(std::move(model)), out_(out), run_(std::move(run)) {
    connect_out(out_);
  }

  void eval() override {
    const bool out_ready = out_.can_push();
    const auto o = model_.eval(run_ ? run_() : true, out_ready);
    if (o.out_valid && out_ready) out_.push(o.out);
  }
  void tick() override { model_.tick(); }

  Model& model() { return model_; }

 private:
  Model model_;
  Fifo<Out>& out_;
  std::function<bool()> run_;
};

}  // namespace scw::sim
