// Marks the few small functions on a per-frame hot path (a received RPDO, a SYNC sending its
// TPDOs) that are always expanded into their caller. The frame passes through several layers
// (node, router, PDO engine, channel, mapping); a call per layer would cost more than the work
// each does, and the compiler's own heuristics do not expand them all. Each marked function has
// one or two call sites, so the code grows little. Built for size (-Os), the compiler decides,
// as for every other function.
#pragma once

#if defined(__OPTIMIZE_SIZE__)
#define COSTA_HOT_INLINE inline
#else
#define COSTA_HOT_INLINE [[gnu::always_inline]] inline
#endif
