// SPDX-License-Identifier: Apache-2.0
// SCW_INLINE: a kernel's per-clock helper inlined into its clock() whatever the compiler's size
// heuristics say.
//
// Why: at -O3 g++ leaves the rectify kernel's read and write sides out of line (its clock() is
// large); called, the small structs they return (the emitted beat and its valid flag) go through
// memory as byte stores read back as words, which stall store forwarding. Inlined, they stay in
// registers: the rectifier's clocked loop ran 1.5 x faster, the disparity stage's 1.1 x
// (docs/performance.md, "scw run against the OpenCV chain"). An HLS tool inlines such helpers
// itself (or with `#pragma HLS INLINE`); the attribute changes no result.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define SCW_INLINE [[gnu::always_inline]] inline
#else
#define SCW_INLINE inline
#endif
