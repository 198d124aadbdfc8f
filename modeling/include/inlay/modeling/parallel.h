// inlay::parallelFor: tbb::parallel_for whose fork and join ThreadSanitizer can see.
//
// Debian's oneTBB is not built with TSan, so the hand-offs inside it (the caller publishing the
// loop's inputs to the workers, each worker's results reaching the caller when parallel_for
// returns) are invisible to it: it then reports every buffer written by a worker and read
// after the loop as a race. parallelFor states both edges explicitly with TSan's annotations:
// the caller releases on `fork` before the loop and every chunk acquires it first; every chunk
// releases on `join` when done and the caller acquires it after the loop. Two addresses, so a
// chunk never inherits another chunk's writes: real races between chunks are still reported.
// Without TSan the annotations are empty and this is exactly tbb::parallel_for.
//
// Every parallel loop in Inlay goes through here (render, lighting). Thread-safe as
// tbb::parallel_for is; the body may be called from any TBB worker or the calling thread.
#pragma once

#include "inlay/modeling/tsan_edge.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <cstddef>
#include <cstdint>

namespace inlay {

namespace detail {

#ifdef INLAY_TSAN
// Called right after tbb::parallel_for returns, with `callerFrame` the frame address of the
// function that called it. tbb::parallel_for keeps its wait_node (tree root: parent pointer,
// reference count, wait_context) on the caller's stack: in its own frames below the caller's,
// or inside the caller's frame when the compiler inlines it. The TBB worker that finishes the
// last chunk touches the wait_node last, in header code TSan sees (fold_tree: a decrement, a
// read, then the wait_context's seq_cst decrement, a release), after our `join` edge; the
// caller's matching acquire is inside libtbb's uninstrumented wait. TSan then reports the
// caller's next use of that stack slot (the next loop's wait_node, or any local of ours the
// compiler puts there) as racing with the worker. Acquiring on every word from below
// parallel_for's dead frames up to the caller's frame states the edge libtbb's wait really
// provides: what the workers released there happened before parallel_for returned. Only words
// on which some thread released carry a sync object; the others cost a lookup.
[[gnu::noinline]] inline void acquireTbbFrames(const void* callerFrame) noexcept {
  // parallel_for's own frames, when not inlined, take a few hundred bytes below this one.
  constexpr std::uintptr_t kBelow = 2048;
  const auto low = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0)) - kBelow;
  const auto high = reinterpret_cast<std::uintptr_t>(callerFrame);
  for (std::uintptr_t a = low & ~std::uintptr_t{3}; a < high; a += 4)
    __tsan_acquire(reinterpret_cast<void*>(a));
}
#else
inline void acquireTbbFrames(const void*) noexcept {}
#endif

}  // namespace detail

// tbb::parallel_for(range, body) with the fork and join edges annotated (see the top).
template <class Range, class Body>
void parallelFor(const Range& range, const Body& body) {
  TsanEdge fork, join;
  fork.release();
  tbb::parallel_for(range, [&](const Range& chunk) {
    fork.acquire();
    body(chunk);
    join.release();
  });
  join.acquire();
  detail::acquireTbbFrames(__builtin_frame_address(0));
}

// Runs `alongside` as a TBB task and `here` on the calling thread, then waits for both: two
// independent jobs side by side (the response check's two candidates, app/engine/pipeline.cpp).
// `here` runs isolated: while it waits inside its own parallel loops the calling thread never
// picks up `alongside` whole (which would hold `here` back until `alongside` ended); a worker
// that runs `alongside` may still help `here`'s loops and the other way round. With no free
// worker (one core, or a thread limit of 1) `alongside` runs on the calling thread after `here`.
// The fork and join are stated to TSan as parallelFor states them. Neither may throw past its
// call (an exception from `here` still waits for `alongside` before it propagates).
template <class Here, class Alongside>
void runAlongside(const Here& here, const Alongside& alongside) {
  TsanEdge fork, join;
  fork.release();
  tbb::task_group group;
  group.run([&] {
    fork.acquire();
    alongside();
    join.release();
  });
  try {
    tbb::this_task_arena::isolate([&] { here(); });
  } catch (...) {
    group.wait();
    throw;
  }
  group.wait();
  join.acquire();
  detail::acquireTbbFrames(__builtin_frame_address(0));
}

}  // namespace inlay
