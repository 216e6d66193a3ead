// SPDX-License-Identifier: Apache-2.0
// C++ twins of the RTL elastic blocks (scw_fifo, scw_stream_reg, scw_skid_buf), cycle-exact.
#pragma once

#include <string>

#include "sim/core/channel.hpp"
#include "sim/core/cycle_model.hpp"

namespace scw::sim {

/// scw_fifo as a cycle model: a Fifo driven through the stream handshake.
template <typename T>
class FifoModel {
 public:
  using in_type = T;
  using out_type = T;
  FifoModel(std::string name, int depth) : fifo_(std::move(name), depth) {}

  StreamOutputs<T> eval(bool in_valid, const T& in, bool out_ready) {
    StreamOutputs<T> o;
    o.in_ready = fifo_.can_push();
    o.out_valid = fifo_.can_pop();
    if (o.out_valid) o.out = fifo_.front();
    push_ = in_valid && o.in_ready;
    pop_ = o.out_valid && out_ready;
    in_ = in;
    return o;
  }
  void tick() {
    if (pop_) fifo_.pop();
    if (push_) fifo_.push(in_);
    fifo_.commit(cycle_++);
  }
  const Fifo<T>& fifo() const { return fifo_; }

 private:
  Fifo<T> fifo_;
  T in_{};
  bool push_ = false;
  bool pop_ = false;
  std::int64_t cycle_ = 0;
};

/// scw_stream_reg: registers valid and data; in_ready = !valid || out_ready.
template <typename T>
class StreamReg {
 public:
  using in_type = T;
  using out_type = T;

  StreamOutputs<T> eval(bool in_valid, const T& in, bool out_ready) {
    in_ready_ = !valid_ || out_ready;
    in_valid_ = in_valid;
    in_ = in;
    return {in_ready_, valid_, data_};
  }
  void tick() {
    if (in_ready_) {
      if (in_valid_) data_ = in_;
      valid_ = in_valid_;
    }
  }

 private:
  bool valid_ = false;
  T data_{};
  bool in_ready_ = false;
  bool in_valid_ = false;
  T in_{};
};

/// scw_skid_buf: main register plus one skid entry; in_ready = !skid_valid (registered).
template <typename T>
class SkidBuf {
 public:
  using in_type = T;
  using out_type = T;

  StreamOutputs<T> eval(bool in_valid, const T& in, bool out_ready) {
    accept_ = in_valid && !skid_valid_;
    drain_ = !main_valid_ || out_ready;
    in_ = in;
    return {!skid_valid_, main_valid_, main_};
  }
  void tick() {
    if (drain_) {
      if (skid_valid_) {
        main_ = skid_;
      } else if (accept_) {
        main_ = in_;
      }
      main_valid_ = skid_valid_ || accept_;
      skid_valid_ = false;
    } else if (accept_) {
      skid_ = in_;
      skid_valid_ = true;
    }
  }

 private:
  bool main_valid_ = false;
  bool skid_valid_ = false;
  T main_{};
  T skid_{};
  bool accept_ = false;
  bool drain_ = false;
  T in_{};
};

}  // namespace scw::sim
