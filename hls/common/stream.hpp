// SPDX-License-Identifier: Apache-2.0
// The stage tops' port type: a bounded, named stream shaped like the vendor's hls::stream, and
// array views with the same read side, so one loop body serves streams and arrays.
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>

// An HLS tool brings its own stream (with its FIFO, depth pragma and co-simulation); ours is
// for g++ only. The vendor header is taken when it is there and asked for: SCW_VENDOR_HLS_STREAM
// (set it in the tool's -cflags), or __SYNTHESIS__, which the tool sets when it synthesises.
#if (defined(SCW_VENDOR_HLS_STREAM) || defined(__SYNTHESIS__)) && __has_include(<hls_stream.h>)
#include <hls_stream.h>
#define SCW_HLS_VENDOR_STREAM 1
#endif

namespace scw::hls {

#ifdef SCW_HLS_VENDOR_STREAM
/// The vendor's stream. `Depth` is not part of its type: tops set it with
/// `#pragma HLS STREAM variable=... depth=...`. `::hls`, because `scw::hls` would shadow it.
template <typename T, int Depth>
using stream = ::hls::stream<T>;
#else
/// Reading an empty stream or writing a full one: in hardware the process would block for ever,
/// so the C simulation stops there and names the stream (hlslib's Stream does the same).
class StreamError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A FIFO of at most `Depth` entries of `T` in a fixed ring (no heap), with the vendor
/// stream's blocking read()/write() and its non-blocking looks empty()/full()/size().
/// In a sequential C simulation a producer runs to its end before its consumer starts, so a
/// link between two processes needs the depth of everything that crosses it in one call.
template <typename T, int Depth>
class stream {
 public:
  static_assert(Depth >= 1, "a stream of at least one entry");
  static constexpr int kDepth = Depth;

  explicit stream(const char* name = "stream") : name_(name) {}
  stream(const stream&) = delete;  // a stream is a wire: one producer, one consumer
  stream& operator=(const stream&) = delete;

  bool empty() const { return count_ == 0; }
  bool full() const { return count_ == Depth; }
  int size() const { return count_; }
  const char* name() const { return name_; }

  T read() {
#ifndef __SYNTHESIS__  // hardware would wait; a synthesis check compiles without exceptions
    if (empty()) throw StreamError(std::string("stream '") + name_ + "': read while empty");
#endif
    const T v = slots_[static_cast<std::size_t>(head_)];
    head_ = head_ == Depth - 1 ? 0 : head_ + 1;
    --count_;
    return v;
  }
  void read(T& v) { v = read(); }
  void write(const T& v) {
#ifndef __SYNTHESIS__
    if (full()) {
      throw StreamError(std::string("stream '") + name_ + "': write while full (depth " +
                        std::to_string(Depth) + ")");
    }
#endif
    const int tail = head_ + count_ < Depth ? head_ + count_ : head_ + count_ - Depth;
    slots_[static_cast<std::size_t>(tail)] = v;
    ++count_;
  }

 private:
  const char* name_;
  std::array<T, Depth> slots_{};
  int head_ = 0, count_ = 0;
};
#endif

/// `n` beats of an array with a stream's read side: how the frame functions' array callers
/// (tests, vector sets) drive the same loop the stream tops run.
template <typename T>
class ArrayIn {
 public:
  ArrayIn(const T* data, int n) : data_(data), n_(data == nullptr ? 0 : n) {}
  bool empty() const { return at_ >= n_; }
  int size() const { return n_ - at_; }
  T read() { return data_[at_++]; }

 private:
  const T* data_;
  int n_, at_ = 0;
};

/// An array with a stream's write side; the caller sizes it (never full).
template <typename T>
class ArrayOut {
 public:
  explicit ArrayOut(T* data) : data_(data) {}
  bool full() const { return false; }
  void write(const T& v) { data_[written_++] = v; }
  int written() const { return written_; }

 private:
  T* data_;
  int written_ = 0;
};

/// An output nobody reads (a side output its caller does not want).
struct Discard {
  bool full() const { return false; }
  template <typename T>
  void write(const T&) {}
};

/// Picks a frame function's port overload over its array one: a port is a stream or a view,
/// never a pointer (a pointer lvalue would otherwise bind to the port template).
template <typename Port>
using if_port = std::enable_if_t<!std::is_pointer_v<Port>, int>;

/// A one-beat look-ahead register in front of a stream: a stage that decides whether to take a
/// beat from the beat itself (a sof, a frame's first word) sees it before taking it, which the
/// vendor stream cannot do (no peek). Filled and taken in the same loop iteration, it offers
/// the next beat at every clock, as the array frame functions did.
template <typename T>
struct Lookahead {
  T beat{};
  bool valid = false;
  template <typename In>
  void fill(In& in) {
    if (!valid && !in.empty()) {
      beat = in.read();
      valid = true;
    }
  }
  void take() { valid = false; }
};

}  // namespace scw::hls
