// Where the programs find their read-only data (the bundled example, the model library), both
// when installed (`cmake --install build --prefix P`, the .deb) and when run from a build tree.
//
// An installed program finds its data relative to its own executable, so a prefix can be moved
// (P/bin/inlay-cli reads P/share/inlay/<name>); a program in a build tree falls back to the
// source tree it was built from (resources/<name>). Thread-safe (reads the environment and
// /proc/self/exe only).
#pragma once

#include <string>
#include <vector>

namespace inlay {

// The folders searched for the data folder `name` ("example", "models"), first match wins:
//   $INLAY_DATA_DIR/<name>               an override (tests, a relocated data folder)
//   <exe folder>/../share/inlay/<name>   the install layout (bin/ beside share/)
//   <source tree>/resources/<name>       the build tree's source (compiled in)
std::vector<std::string> dataDirCandidates(const std::string& name);

// The first candidate that exists as a folder; empty when none does.
std::string findDataDir(const std::string& name);

}  // namespace inlay
