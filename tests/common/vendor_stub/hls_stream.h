// SPDX-License-Identifier: Apache-2.0
// A stand-in for a vendor's <hls_stream.h> (not installable here): just enough of its shape for
// test_stream_vendor.cpp to check that scw::hls::stream maps to ::hls::stream.
#pragma once

#include <deque>

namespace hls {
template <typename T>
class stream {
 public:
  explicit stream(const char* = "") {}
  bool empty() const { return q_.empty(); }
  bool full() const { return false; }
  int size() const { return static_cast<int>(q_.size()); }
  T read() {
    T v = q_.front();
    q_.pop_front();
    return v;
  }
  void write(const T& v) { q_.push_back(v); }

 private:
  std::deque<T> q_;  // the vendor's C simulation model is unbounded too
};
}  // namespace hls
