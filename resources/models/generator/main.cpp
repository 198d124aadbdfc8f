// inlay-make-library: builds Inlay's model library procedurally (every vertex made here, so the
// project may license all of it) and writes it into resources/models/:
//   <name>.glb for each piece (glTF 2.0 binary, metres, PBR metallic-roughness),
//   library.json (the index: name, title, file, thumbnail, category, dimensions, material note),
// and with --thumbnails renders each piece into the bundled example with Inlay's path tracer:
//   thumbnails/<name>.png and a contact sheet (default docs/images/model-library.png).
// Every written .glb is read back with Inlay's loader (loadMesh) and with Assimp's validating
// importer; a mismatch stops the run (exit status 1).
#include "glb_writer.h"
#include "pieces.h"
#include "thumbnails.h"

#include "inlay/modeling/image_io.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;
using namespace inlay;
using namespace inlay::library;

namespace {

struct Args {
  std::string outDir = INLAY_MODELS_DIR;
  std::string sheet = INLAY_DOCS_IMAGES_DIR "/model-library.png";
  bool thumbnails = false;
  ThumbnailOptions thumbnail;
};

const char* kUsage =
    "usage: inlay-make-library [--out DIR] [--thumbnails] [--sheet PNG] [--spp N] [--size PX]\n"
    "  --out DIR      where the .glb files, library.json and thumbnails/ go (default: the source\n"
    "                 tree's resources/models)\n"
    "  --thumbnails   also render thumbnails/<name>.png in the bundled example and the contact sheet\n"
    "  --sheet PNG    the contact sheet (default: the source tree's docs/images/model-library.png)\n"
    "  --spp N        thumbnail samples per pixel (default 64)\n"
    "  --size PX      thumbnail side in pixels (default 160)\n";

bool parseArgs(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
    if (k == "--thumbnails") {
      a.thumbnails = true;
    } else if (k == "--out" || k == "--sheet" || k == "--spp" || k == "--size") {
      const char* v = value();
      if (!v) return std::fprintf(stderr, "inlay-make-library: %s needs a value\n", k.c_str()), false;
      if (k == "--out") a.outDir = v;
      if (k == "--sheet") a.sheet = v;
      if (k == "--spp") a.thumbnail.spp = std::atoi(v);
      if (k == "--size") a.thumbnail.sizePx = std::atoi(v);
    } else {
      std::fputs(kUsage, stderr);
      return k == "--help" ? (std::exit(0), true) : false;
    }
  }
  if (a.thumbnail.spp < 1 || a.thumbnail.sizePx < 16 || a.thumbnail.sizePx > 1024)
    return std::fprintf(stderr, "inlay-make-library: --spp must be >= 1 and --size in [16, 1024]\n"),
           false;
  return true;
}

// The written file read back by Inlay's loader and by Assimp's validating importer: same
// triangles, same bounds, same material count. Empty when it matches.
std::string readBackProblem(const Piece& piece, const std::string& path) {
  auto loaded = loadMesh(path);
  if (!loaded) return "loadMesh: " + loaded.error().message();
  if (loaded->triangles.size() != piece.mesh.triangles.size())
    return "loadMesh reads " + std::to_string(loaded->triangles.size()) + " triangles, " +
           std::to_string(piece.mesh.triangles.size()) + " written";
  const Eigen::AlignedBox3f a = loaded->bounds(), b = piece.mesh.bounds();
  if ((a.min() - b.min()).cwiseAbs().maxCoeff() > 1e-5f ||
      (a.max() - b.max()).cwiseAbs().maxCoeff() > 1e-5f)
    return "loadMesh reads other bounds";
  // Assimp may add its default material after the file's.
  if (loaded->materials.size() < piece.mesh.materials.size()) return "loadMesh reads fewer materials";
  for (size_t m = 0; m < piece.mesh.materials.size(); ++m)
    if (loaded->materials[m].name != piece.mesh.materials[m].name)
      return "loadMesh reads material " + std::to_string(m) + " as '" + loaded->materials[m].name + "'";
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
    return std::string("Assimp: ") + importer.GetErrorString();
  size_t faces = 0;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) faces += scene->mMeshes[i]->mNumFaces;
  if (faces != piece.mesh.triangles.size()) return "Assimp reads " + std::to_string(faces) + " faces";
  return "";
}

double roundMm(float metres) { return std::round(double(metres) * 1000.0) / 1000.0; }

nlohmann::json entryOf(const Piece& p, uintmax_t bytes) {
  const Eigen::Vector3f size = p.mesh.bounds().sizes();
  return {{"name", p.name},
          {"title", p.title},
          {"file", p.name + ".glb"},
          {"thumbnail", "thumbnails/" + p.name + ".png"},
          {"category", p.category},
          {"dimensions_m",
           {{"width", roundMm(size.x())}, {"depth", roundMm(size.z())}, {"height", roundMm(size.y())}}},
          {"material", p.materialNote},
          {"triangles", p.mesh.triangles.size()},
          {"bytes", bytes},
          {"thumbnail_yaw_deg", p.thumbnailYawDeg}};
}

int writeModels(const std::vector<Piece>& pieces, const Args& a) {
  nlohmann::json index = {
      {"format", "inlay-model-library"},
      {"version", 1},
      {"units", "metres; y up; each piece stands on y = 0, centred, its front toward +z"},
      {"generator", "inlay-make-library (resources/models/generator)"},
      {"pieces", nlohmann::json::array()}};
  std::printf("%-14s %-22s %9s %8s\n", "piece", "w x d x h (m)", "triangles", "bytes");
  for (const Piece& p : pieces) {
    const std::string path = (fs::path(a.outDir) / (p.name + ".glb")).string();
    if (auto st = writeGlb(p.mesh, p.name, path); !st)
      return std::fprintf(stderr, "inlay-make-library: %s\n", st.error().message().c_str()), 1;
    if (const std::string why = readBackProblem(p, path); !why.empty())
      return std::fprintf(stderr, "inlay-make-library: %s: %s\n", path.c_str(), why.c_str()), 1;
    const uintmax_t bytes = fs::file_size(path);
    index["pieces"].push_back(entryOf(p, bytes));
    const Eigen::Vector3f s = p.mesh.bounds().sizes();
    std::printf("%-14s %5.3f x %5.3f x %5.3f %9zu %8ju\n", p.name.c_str(), s.x(), s.z(), s.y(),
                p.mesh.triangles.size(), bytes);
  }
  if (auto st =
          writeFileAtomically((fs::path(a.outDir) / "library.json").string(), index.dump(2) + "\n");
      !st)
    return std::fprintf(stderr, "inlay-make-library: %s\n", st.error().message().c_str()), 1;
  return 0;
}

int writeThumbnails(const std::vector<Piece>& pieces, const Args& a) {
  std::vector<std::string> warnings;
  auto room = prepareExampleRoom(&warnings);
  if (!room) return std::fprintf(stderr, "inlay-make-library: %s\n", room.error().message().c_str()), 1;
  fs::create_directories(fs::path(a.outDir) / "thumbnails");
  std::vector<ImageF> thumbs;
  std::vector<std::string> titles;
  for (const Piece& p : pieces) {
    const std::string glb = (fs::path(a.outDir) / (p.name + ".glb")).string();
    auto mesh = loadMesh(glb);
    if (!mesh)
      return std::fprintf(stderr, "inlay-make-library: %s\n", mesh.error().message().c_str()), 1;
    ThumbnailStats stats;
    auto image = renderThumbnail(*room, *mesh, mesh->bounds().sizes().y(), p.thumbnailYawDeg,
                                 a.thumbnail, &stats);
    if (!image)
      return std::fprintf(stderr, "inlay-make-library: %s: %s\n", p.name.c_str(),
                          image.error().message().c_str()),
             1;
    if (stats.nonFiniteSamples > 0)
      warnings.push_back(p.name + ": " + std::to_string(stats.nonFiniteSamples) +
                         " non-finite samples dropped");
    const std::string png = (fs::path(a.outDir) / "thumbnails" / (p.name + ".png")).string();
    if (auto st = saveImage(png, *image); !st)
      return std::fprintf(stderr, "inlay-make-library: %s\n", st.error().message().c_str()), 1;
    std::printf("%-14s thumbnail at (%.0f, %.0f) px, %.1f s\n", p.name.c_str(), stats.basePx.x(),
                stats.basePx.y(), stats.seconds);
    thumbs.push_back(std::move(*image));
    titles.push_back(p.title);
  }
  const ImageF sheet = contactSheet(thumbs, titles, 4, &warnings);
  if (auto st = saveImage(a.sheet, sheet); !st)
    return std::fprintf(stderr, "inlay-make-library: %s\n", st.error().message().c_str()), 1;
  for (const auto& w : warnings) std::fprintf(stderr, "inlay-make-library: warning: %s\n", w.c_str());
  std::printf("contact sheet: %s\n", a.sheet.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  if (!parseArgs(argc, argv, a)) return 2;
  std::vector<Piece> pieces;
  try {
    pieces = buildLibrary();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "inlay-make-library: %s\n", e.what());
    return 1;
  }
  std::error_code ec;
  fs::create_directories(a.outDir, ec);
  if (int rc = writeModels(pieces, a); rc != 0) return rc;
  return a.thumbnails ? writeThumbnails(pieces, a) : 0;
}
