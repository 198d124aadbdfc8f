// inlay-cli batch: many renders from one manifest (docs/batch.md).
//
//   inlay-cli batch MANIFEST.jsonl [--jobs N] [--shard K/N] [--spp N] [--seconds S]
//                   [--noise E] [--seed K] [--threads T] [--quiet]
//
// One JSON object per line: {"scene": ..., "output": ..., "objects": [...], "render": {...}}.
// Lines of one scene share its preparation (camera, room, lighting: done once); each line
// only places its objects and renders. A line whose output exists is skipped (resumable); a
// failed line is reported and the others go on; the exit status is 0 when every line of the
// shard is done, 2 when a line had bad input, 1 on an internal failure or an interruption.
#pragma once

#include "inlay/modeling/core.h"

#include <atomic>

namespace inlay::cli {

// argv[0] is "batch". `cancel` and `interrupted` are the program's Ctrl-C state.
int runBatch(int argc, char** argv, CancelToken& cancel, const std::atomic<bool>& interrupted);

}  // namespace inlay::cli
