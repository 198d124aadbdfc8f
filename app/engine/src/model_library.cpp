// The bundled model library's index (see model_library.h).
#include "inlay/engine/model_library.h"

#include "inlay/engine/data_dirs.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace inlay {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// One piece from its JSON entry; `key` is "pieces[i]".
Expected<LibraryPiece> pieceOf(const json& p, const fs::path& dir, const std::string& key) {
  if (!p.is_object()) return Error{"", key, "expected an object"};
  LibraryPiece piece;
  for (auto [field, out] : {std::pair{"name", &piece.name},
                            {"title", &piece.title},
                            {"category", &piece.category},
                            {"file", &piece.file},
                            {"thumbnail", &piece.thumbnail},
                            {"material", &piece.material}}) {
    if (!p.contains(field) || !p[field].is_string() || p[field].get<std::string>().empty())
      return Error{"", key + "." + field, "expected a non-empty string"};
    *out = p[field].get<std::string>();
  }
  const json d = p.value("dimensions_m", json());
  int axis = 0;
  for (const char* field : {"width", "depth", "height"}) {
    const json v = d.is_object() ? d.value(field, json()) : json();
    if (!v.is_number() || !(v.get<double>() > 0) || !std::isfinite(v.get<double>()))
      return Error{"", key + ".dimensions_m." + field, "expected a positive number of metres"};
    piece.sizeM[axis++] = v.get<double>();
  }
  for (auto [field, path] : {std::pair{"file", &piece.file}, {"thumbnail", &piece.thumbnail}}) {
    const fs::path f = dir / *path;
    std::error_code ec;
    if (!fs::is_regular_file(f, ec)) return Error{"", key + "." + field, "no such file: " + f.string()};
    *path = f.string();
  }
  return piece;
}

}  // namespace

std::string modelLibraryDir() {
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("INLAY_MODELS_DIR")) candidates.emplace_back(env);
  for (const std::string& dir : dataDirCandidates("models")) candidates.emplace_back(dir);
  std::error_code ec;
  for (const auto& c : candidates)
    if (fs::is_regular_file(c / "library.json", ec)) return fs::weakly_canonical(c).string();
  return {};
}

Expected<std::vector<LibraryPiece>> loadModelLibrary(const std::string& dir) {
  const fs::path index = fs::path(dir) / "library.json";
  std::ifstream in(index);
  if (!in) return Error{index.string(), "", "cannot be read"};
  const json j = json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) return Error{index.string(), "", "not a JSON object"};
  if (j.value("format", "") != "inlay-model-library")
    return Error{index.string(), "format", "expected \"inlay-model-library\""};
  const json pieces = j.value("pieces", json());
  if (!pieces.is_array()) return Error{index.string(), "pieces", "expected an array"};
  std::vector<LibraryPiece> out;
  for (size_t i = 0; i < pieces.size(); ++i) {
    auto p = pieceOf(pieces[i], fs::path(dir), "pieces[" + std::to_string(i) + "]");
    if (!p) return p.error().inFile(index.string());
    out.push_back(std::move(*p));
  }
  return out;
}

}  // namespace inlay
