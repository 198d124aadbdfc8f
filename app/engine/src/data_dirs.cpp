#include "inlay/engine/data_dirs.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace inlay {

std::vector<std::string> dataDirCandidates(const std::string& name) {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  if (const char* env = std::getenv("INLAY_DATA_DIR"); env && *env)
    out.push_back((fs::path(env) / name).string());
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec)
    out.push_back((exe.parent_path() / ".." / "share" / "inlay" / name).lexically_normal().string());
  out.push_back((fs::path(INLAY_SOURCE_RESOURCES_DIR) / name).string());
  return out;
}

std::string findDataDir(const std::string& name) {
  namespace fs = std::filesystem;
  for (const std::string& c : dataDirCandidates(name)) {
    std::error_code ec;
    if (fs::is_directory(c, ec)) return fs::weakly_canonical(c, ec).string();
  }
  return {};
}

}  // namespace inlay
