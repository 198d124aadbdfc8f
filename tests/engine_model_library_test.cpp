// The bundled model library (resources/models, built by inlay-make-library): every piece that
// library.json lists loads cleanly with Inlay's own loader, has finite geometry with unit
// normals and UVs, is as big as the index says (within 1 cm), stands on y = 0 centred, stays
// under 50k triangles, and renders into the bundled example as the engine inserts it (preset
// "asset": a material per part, the lamps' shades lights) with no new warning and no
// non-finite sample. Needs nothing from ../shared.
#include "inlay/engine/pipeline.h"
#include "inlay/render/path_tracer.h"
#include "test_support.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <set>
#include <fstream>
#include <regex>

namespace inlay {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kModels = fs::path(INLAY_SOURCE_DIR) / "resources" / "models";

json libraryIndex() {
  std::ifstream in(kModels / "library.json");
  json j = json::parse(in, nullptr, false);
  EXPECT_FALSE(j.is_discarded()) << "resources/models/library.json is not JSON";
  return j;
}

struct Entry {
  std::string name, file, category;
  Vec3 sizeM;  // width (x), depth (z), height (y)
  size_t triangles = 0;
};

std::vector<Entry> entries() {
  std::vector<Entry> out;
  for (const json& p : libraryIndex().value("pieces", json::array())) {
    const json& d = p.at("dimensions_m");
    out.push_back(
        {p.at("name").get<std::string>(), (kModels / p.at("file").get<std::string>()).string(),
         p.at("category").get<std::string>(),
         Vec3(d.at("width").get<double>(), d.at("depth").get<double>(), d.at("height").get<double>()),
         p.at("triangles").get<size_t>()});
  }
  return out;
}

TEST(ModelLibrary, IndexListsTwelveOrMorePiecesWithTheirFiles) {
  const json index = libraryIndex();
  EXPECT_EQ(index.value("format", ""), "inlay-model-library");
  const auto list = entries();
  EXPECT_GE(list.size(), 12u);
  std::set<std::string> names;
  for (const json& p : index.at("pieces")) {
    const std::string name = p.at("name").get<std::string>();
    EXPECT_TRUE(names.insert(name).second) << "duplicate " << name;
    EXPECT_TRUE(fs::is_regular_file(kModels / p.at("file").get<std::string>())) << name;
    EXPECT_TRUE(fs::is_regular_file(kModels / p.at("thumbnail").get<std::string>())) << name;
    EXPECT_FALSE(p.at("title").get<std::string>().empty()) << name;
    EXPECT_FALSE(p.at("material").get<std::string>().empty()) << name;
  }
  uintmax_t bytes = 0;
  for (const auto& f : fs::recursive_directory_iterator(kModels / "thumbnails"))
    if (f.is_regular_file()) bytes += f.file_size();
  for (const auto& e : list) bytes += fs::file_size(e.file);
  EXPECT_LT(bytes, 3u << 20) << "the library's models and thumbnails should stay under 3 MB";
}

TEST(ModelLibrary, EveryPieceLoadsFiniteAndAsBigAsTheIndexSays) {
  for (const Entry& e : entries()) {
    SCOPED_TRACE(e.name);
    auto mesh = loadMesh(e.file);
    ASSERT_TRUE(mesh.ok()) << mesh.error().message();
    EXPECT_EQ(mesh->triangles.size(), e.triangles);
    EXPECT_LT(mesh->triangles.size(), 50000u);
    ASSERT_EQ(mesh->normals.size(), mesh->positions.size());
    ASSERT_EQ(mesh->uvs.size(), mesh->positions.size());
    for (size_t i = 0; i < mesh->positions.size(); ++i) {
      ASSERT_TRUE(mesh->positions[i].allFinite()) << "vertex " << i;
      ASSERT_NEAR(mesh->normals[i].norm(), 1.f, 1e-3f) << "normal " << i;
      ASSERT_TRUE(mesh->uvs[i].allFinite()) << "uv " << i;
    }
    // Vertex normals face the way their triangles wind (outward), not against them.
    size_t against = 0;
    for (const auto& t : mesh->triangles) {
      const Vec3f g = (mesh->positions[t[1]] - mesh->positions[t[0]])
                          .cross(mesh->positions[t[2]] - mesh->positions[t[0]]);
      against += g.dot(mesh->normals[t[0]] + mesh->normals[t[1]] + mesh->normals[t[2]]) < 0;
    }
    EXPECT_EQ(against, 0u);
    const Eigen::AlignedBox3f b = mesh->bounds();
    EXPECT_NEAR(b.sizes().x(), e.sizeM.x(), 0.01) << "width";
    EXPECT_NEAR(b.sizes().z(), e.sizeM.y(), 0.01) << "depth";
    EXPECT_NEAR(b.sizes().y(), e.sizeM.z(), 0.01) << "height";
    EXPECT_NEAR(b.min().y(), 0.f, 1e-3f) << "stands on y = 0";
    EXPECT_NEAR(b.center().x(), 0.f, 0.01f);
    EXPECT_NEAR(b.center().z(), 0.f, 0.01f);
    bool emissive = false;
    for (const AssetMaterial& m : mesh->materials) {
      EXPECT_TRUE(m.baseColor.minCoeff() >= 0 && m.baseColor.maxCoeff() <= 1) << m.name;
      EXPECT_TRUE(m.roughness >= 0 && m.roughness <= 1 && m.metallic >= 0 && m.metallic <= 1) << m.name;
      emissive = emissive || m.emission.maxCoeff() > 0;
    }
    EXPECT_EQ(emissive, e.category == "lighting") << "lamps glow, nothing else does";
  }
}

// A few samples at quarter resolution: finite, no dropped sample, and the piece is seen.
void expectCleanRender(const RenderScene& scene, const std::string& what) {
  PathTracer tracer(scene);
  DifferentialBuffers buf(scene.camera.widthPx / 4, scene.camera.heightPx / 4);
  ASSERT_TRUE(tracer.render(buf, 0, 2, 1));
  EXPECT_EQ(tracer.stats().nonFiniteSamples, 0u) << what;
  const ImageF with = buf.meanWith(), mask = buf.meanMask();
  for (float v : with.data) ASSERT_TRUE(std::isfinite(v)) << what;
  double seen = 0;
  for (float v : mask.data) seen += v;
  EXPECT_GT(seen, 1.0) << what << ": the piece covers no pixel";
}

// Warnings with their run times ("(1.59 s)") taken out, so two runs compare.
std::vector<std::string> withoutTimes(std::vector<std::string> warnings) {
  const std::regex seconds(R"(\([0-9.]+ s\))");
  for (std::string& w : warnings) w = std::regex_replace(w, seconds, "");
  return warnings;
}

TEST(ModelLibrary, EveryPieceRendersIntoTheExampleWithoutWarnings) {
  auto loaded = loadSceneFile((fs::path(INLAY_SOURCE_DIR) / "resources/example/scene.json").string());
  ASSERT_TRUE(loaded.ok()) << loaded.error().message();
  const auto list = entries();
  ASSERT_FALSE(list.empty());
  SceneDoc doc = loaded->doc;
  ObjectKeys& object = doc.objects.at(0);  // the example's sphere becomes the first piece
  object.mesh = object.meshResolved = list.front().file;
  object.heightM = list.front().sizeM.z();
  object.yawDeg = 30;
  object.material = MaterialKeys{};
  object.material.preset = "asset";
  PrepareOptions fast;
  fast.refineLights = false;
  auto ps = prepareScene(doc, fast);
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  // The example's own warnings (if any) are the baseline; a piece adds none.
  SceneDoc empty = doc;
  empty.objects.clear();
  auto baseline = prepareScene(empty, fast);
  ASSERT_TRUE(baseline.ok()) << baseline.error().message();
  EXPECT_EQ(withoutTimes(ps->warnings), withoutTimes(baseline->warnings));
  for (const Entry& e : list) {
    SCOPED_TRACE(e.name);
    object.mesh = object.meshResolved = e.file;
    object.heightM = e.sizeM.z();
    auto mesh = loadObjectMesh(object);
    ASSERT_TRUE(mesh.ok()) << mesh.error().message();
    auto placed = placeObject(*mesh, ps->geometry, ps->camera, object.basePx, object.heightM,
                              object.yawDeg, "objects[0]");
    ASSERT_TRUE(placed.ok()) << placed.error().message();
    RenderScene scene = ps->renderScene;
    InsertedObject one;  // as the pipeline inserts it: one object, a material per part
    one.meshObject = std::make_shared<const TriangleMesh>(*mesh);
    one.worldFromObject = placed->worldFromObject;
    setObjectMaterial(one, object.material);
    EXPECT_EQ(one.partMaterials.size(), mesh->materials.size() > 1 ? mesh->materials.size() : 0u);
    bool light = false;
    for (const Material& m : one.partMaterials) light = light || m.kind == Material::Kind::Emissive;
    EXPECT_EQ(light, e.category == "lighting") << "a lamp's shade is a light";
    scene.objects = {one};
    expectCleanRender(scene, "as one object");
  }
}

}  // namespace
}  // namespace inlay
