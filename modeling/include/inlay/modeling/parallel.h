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

namespace inlay {

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
}

}  // namespace inlay
