// Two marks for small functions that the frames' paths go through.
//
// COSTA_HOT_INLINE: the few that are always expanded into their caller. The frame passes through
// several layers (node, router, PDO engine, channel, mapping); a call per layer would cost more
// than the work each does, and the compiler's own heuristics do not expand them all. Each marked
// function has one or two call sites, so the code grows little. Built for size (-Os), the
// compiler decides, as for every other function.
//
// COSTA_SHARED_INLINE: those that many callers share, on the hot paths and off them (sending a
// frame, finding the hook of an object, scheduling a deadline, ending an SDO transfer). Built
// for speed, the compiler expands them where it sees fit.
// Built for size, each is one copy, called: expanded at every caller, they would cost more
// flash than the calls save.
#pragma once

#if defined(__OPTIMIZE_SIZE__)
#define COSTA_HOT_INLINE inline
#define COSTA_SHARED_INLINE [[gnu::noinline]] inline
#else
#define COSTA_HOT_INLINE [[gnu::always_inline]] inline
#define COSTA_SHARED_INLINE inline
#endif
