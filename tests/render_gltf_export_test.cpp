// glTF export, checked by re-importing with Assimp (a reader we did not write): the room's
// surfaces with baked albedo textures that map back onto the photo's albedo, the lights as
// emissive quads of the right strength, the camera, and the objects with their materials.
#include "render_test_scenes.h"
#include "test_support.h"

#include "inlay/modeling/image_io.h"
#include "inlay/render/gltf_export.h"

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <nlohmann/json.hpp>

#include <fstream>

namespace inlay {
namespace {

RenderScene exportScene() {
  const int w = 64, h = 48;
  RenderScene s = test::roomScene(test::testCamera(w, h, 60, 1.3, -10), RoomBox{}, 0.5);
  s.roomAlbedo.albedo = ImageF(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      s.roomAlbedo.albedo.setRgb(x, y, Vec3(0.1 + 0.8 * x / w, 0.3, 0.9 - 0.6 * y / h));
  s.roomAlbedo.computeFirstSurfaces(s.room);
  s.lights.push_back(test::rectLight(Vec3(0, 2.6, -2), Vec3(0.4, 0, 0), Vec3(0, 0, 0.4), Vec3(6, 5, 4)));
  const Material::Kind kinds[] = {Material::Kind::Diffuse, Material::Kind::Conductor,
                                  Material::Kind::RoughGlass, Material::Kind::Emissive};
  for (int i = 0; i < 4; ++i) {
    InsertedObject o;
    o.meshObject = test::sphereMesh(0.2, 8, 16);
    o.worldFromObject = test::translation(Vec3(-0.9 + 0.6 * i, 0.2, -2.5));
    o.material.kind = kinds[i];
    o.material.albedo = Vec3(0.7, 0.5, 0.3);
    o.material.roughness = 0.4;
    o.material.emission = Vec3(3, 1.5, 0);
    s.objects.push_back(o);
  }
  return s;
}

const aiNode* findNode(const aiNode* n, const std::string& name) {
  if (name == n->mName.C_Str()) return n;
  for (unsigned i = 0; i < n->mNumChildren; ++i)
    if (const aiNode* f = findNode(n->mChildren[i], name)) return f;
  return nullptr;
}

const aiMaterial* materialNamed(const aiScene* sc, const std::string& name) {
  for (unsigned i = 0; i < sc->mNumMaterials; ++i)
    if (name == sc->mMaterials[i]->GetName().C_Str()) return sc->mMaterials[i];
  return nullptr;
}

TEST(GltfExport, AssimpReadsBackRoomLightsCameraAndObjects) {
  const RenderScene s = exportScene();
  const auto dir = test::tempDir("gltf_export");
  const std::string path = (dir / "room.gltf").string();
  std::vector<std::string> warnings;
  const Status st = exportGltf(s, path, {}, &warnings);
  ASSERT_TRUE(st.ok()) << st.error().message();
  EXPECT_TRUE(warnings.empty());

  Assimp::Importer importer;
  const aiScene* sc = importer.ReadFile(path, 0);
  ASSERT_NE(sc, nullptr) << importer.GetErrorString();
  EXPECT_EQ(sc->mNumMeshes, 6u + 1u + 4u);  // six box faces, one light, four objects
  ASSERT_EQ(sc->mNumCameras, 1u);
  // Assimp 5.2 stores yfov x aspect as its "horizontal" field of view.
  const double yfov = 2 * std::atan(0.5 * s.camera.heightPx / s.camera.focalPx);
  EXPECT_NEAR(sc->mCameras[0]->mHorizontalFOV / sc->mCameras[0]->mAspect, yfov, 1e-5);
  EXPECT_NEAR(sc->mCameras[0]->mAspect, 64.0 / 48.0, 1e-6);
  const aiNode* camNode = findNode(sc->mRootNode, "camera");
  ASSERT_NE(camNode, nullptr);
  EXPECT_NEAR(camNode->mTransformation.b4, 1.3, 1e-6);  // translation y: the camera height

  // The light: emissive colour x strength = its radiance (Assimp 5.2 reads the colour but not
  // KHR_materials_emissive_strength: the strength is read from the JSON).
  const aiMaterial* light = materialNamed(sc, "light_0");
  ASSERT_NE(light, nullptr);
  aiColor3D e;
  ASSERT_EQ(light->Get(AI_MATKEY_COLOR_EMISSIVE, e), AI_SUCCESS);
  std::ifstream in(path);
  const nlohmann::json doc = nlohmann::json::parse(in);
  auto strengthOf = [&](const std::string& name) {
    for (const auto& m : doc["materials"])
      if (m["name"] == name)
        return m["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"].get<double>();
    return 0.0;
  };
  EXPECT_NEAR(e.r * strengthOf("light_0"), 6.0, 1e-4);
  EXPECT_NEAR(e.b * strengthOf("light_0"), 4.0, 1e-4);
  // Objects: the metal is metallic, the rough glass transmits, the emissive one glows.
  float metallic = 0, transmission = 0;
  ASSERT_EQ(materialNamed(sc, "object_1")->Get(AI_MATKEY_METALLIC_FACTOR, metallic), AI_SUCCESS);
  EXPECT_EQ(metallic, 1.f);
  ASSERT_EQ(materialNamed(sc, "object_2")->Get(AI_MATKEY_TRANSMISSION_FACTOR, transmission), AI_SUCCESS);
  EXPECT_EQ(transmission, 1.f);
  EXPECT_NEAR(strengthOf("object_3"), 3.0, 1e-9);
  const aiNode* obj = findNode(sc->mRootNode, "object_2");
  ASSERT_NE(obj, nullptr);
  EXPECT_NEAR(obj->mTransformation.a4, 0.3, 1e-6);  // x translation of the third object

  // The back wall's texture, looked up through the re-imported UVs at the point the centre
  // pixel sees, gives that pixel's albedo.
  const aiNode* wallNode = findNode(sc->mRootNode, "wall_back");
  ASSERT_NE(wallNode, nullptr);
  const aiMesh* wall = sc->mMeshes[wallNode->mMeshes[0]];
  ASSERT_TRUE(wall->HasTextureCoords(0));
  aiString texPath;
  ASSERT_EQ(sc->mMaterials[wall->mMaterialIndex]->GetTexture(aiTextureType_DIFFUSE, 0, &texPath),
            AI_SUCCESS);
  const Expected<LoadedImage> tex = loadImage((dir / texPath.C_Str()).string());
  ASSERT_TRUE(tex.ok()) << tex.error().message();
  for (const Vec2& px : {Vec2(32.5, 20.5), Vec2(10.5, 12.5), Vec2(50.5, 25.5)}) {
    const Ray r = s.camera.rayThroughPixel(px);
    const Vec3 p = r.at((-4.0 - r.origin.z()) / r.direction.z());
    ASSERT_EQ(s.roomAlbedo.firstSurfacePerPixel[size_t(px.y()) * 64 + size_t(px.x())], 4);
    bool found = false;
    for (unsigned f = 0; f < wall->mNumFaces && !found; ++f) {
      const unsigned* ix = wall->mFaces[f].mIndices;
      auto P = [&](int k) {
        const aiVector3D& v = wall->mVertices[ix[k]];
        return Vec2(v.x, v.y);
      };
      const Vec2 a = P(0), b = P(1), c = P(2), q(p.x(), p.y());
      const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
      const double l1 = ((q - a).x() * (c - a).y() - (q - a).y() * (c - a).x()) / area;
      const double l2 = ((b - a).x() * (q - a).y() - (b - a).y() * (q - a).x()) / area;
      if (l1 < 0 || l2 < 0 || l1 + l2 > 1) continue;
      found = true;
      auto UV = [&](int k) {
        const aiVector3D& t = wall->mTextureCoords[0][ix[k]];
        return Vec2(t.x, t.y);
      };
      Vec2 uv = (1 - l1 - l2) * UV(0) + l1 * UV(1) + l2 * UV(2);
      uv.y() = 1 - uv.y();  // Assimp flips glTF's v on import
      const ImageF& t = tex->linearRgb;
      const Vec3 got = t.rgb(std::min(t.width - 1, int(uv.x() * t.width)),
                             std::min(t.height - 1, int(uv.y() * t.height)));
      const Vec3 want = s.roomAlbedo.albedo.rgb(int(px.x()), int(px.y()));
      EXPECT_LT((got - want).cwiseAbs().maxCoeff(), 0.04)
          << "pixel " << px.transpose() << " got " << got.transpose() << " want " << want.transpose();
    }
    EXPECT_TRUE(found);
  }
}

// Room surfaces the user marked (room.materials.<surface>) export as the renderer sees them: a
// mirror as a smooth metal of its reflectance, a glossy floor with its roughness over the
// baked albedo; unmarked surfaces stay matte.
TEST(GltfExport, MarkedRoomSurfacesKeepTheirMaterials) {
  RenderScene s = exportScene();
  s.roomMaterials.assign(s.room.surfaces.size(), std::nullopt);
  Material mirror, glossy;
  mirror.kind = Material::Kind::Mirror;
  mirror.albedo = Vec3(0.9, 0.85, 0.8);
  glossy.kind = Material::Kind::Glossy;
  glossy.roughness = 0.25;
  glossy.ior = 1.6;
  size_t back = 0, floor = 0;
  for (size_t i = 0; i < s.room.surfaces.size(); ++i) {
    if (s.room.surfaces[i].name == "wall_back") back = i;
    if (s.room.surfaces[i].name == "floor") floor = i;
  }
  ASSERT_NE(back, floor);
  s.roomMaterials[back] = mirror;
  s.roomMaterials[floor] = glossy;
  const auto dir = test::tempDir("gltf_export_marked");
  const std::string path = (dir / "room.glb").string();
  ASSERT_TRUE(exportGltf(s, path).ok());
  Assimp::Importer importer;
  const aiScene* sc = importer.ReadFile(path, 0);
  ASSERT_NE(sc, nullptr) << importer.GetErrorString();
  auto materialOf = [&](const std::string& node) {
    const aiNode* n = findNode(sc->mRootNode, node);
    return n ? sc->mMaterials[sc->mMeshes[n->mMeshes[0]]->mMaterialIndex] : nullptr;
  };
  float metallic = -1, roughness = -1;
  const aiMaterial* m = materialOf("wall_back");
  ASSERT_NE(m, nullptr);
  ASSERT_EQ(m->Get(AI_MATKEY_METALLIC_FACTOR, metallic), AI_SUCCESS);
  ASSERT_EQ(m->Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness), AI_SUCCESS);
  EXPECT_EQ(metallic, 1.f);
  EXPECT_EQ(roughness, 0.f);
  aiColor4D base;
  ASSERT_EQ(m->Get(AI_MATKEY_BASE_COLOR, base), AI_SUCCESS);
  EXPECT_NEAR(base.g, 0.85, 1e-6);
  const aiMaterial* g = materialOf("floor");
  ASSERT_NE(g, nullptr);
  ASSERT_EQ(g->Get(AI_MATKEY_METALLIC_FACTOR, metallic), AI_SUCCESS);
  ASSERT_EQ(g->Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness), AI_SUCCESS);
  EXPECT_EQ(metallic, 0.f);
  EXPECT_NEAR(roughness, 0.25, 1e-6);
  aiString tex;
  EXPECT_EQ(g->GetTexture(aiTextureType_DIFFUSE, 0, &tex), AI_SUCCESS);  // the albedo stays
  const aiMaterial* wall = materialOf("wall_left");
  ASSERT_NE(wall, nullptr);
  ASSERT_EQ(wall->Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness), AI_SUCCESS);
  EXPECT_EQ(roughness, 1.f);  // unmarked: matte
}

// An object with part materials (a lamp: a stand and a glowing shade) exports a primitive per
// part, each with its own material.
TEST(GltfExport, PartMaterialsExportAsOnePrimitiveEach) {
  RenderScene s = exportScene();
  s.objects.resize(1);
  TriangleMesh mesh = *test::sphereMesh(0.2, 8, 16);
  mesh.triangleMaterial.assign(mesh.triangles.size(), 0u);
  for (size_t t = 0; t < mesh.triangles.size() / 2; ++t) mesh.triangleMaterial[t] = 1;
  mesh.materials.resize(2);
  s.objects[0].meshObject = std::make_shared<TriangleMesh>(mesh);
  Material stand, shade;
  stand.kind = Material::Kind::Conductor;
  shade.kind = Material::Kind::Emissive;
  shade.emission = Vec3(1.5, 1.2, 0.8);
  s.objects[0].partMaterials = {stand, shade};
  const auto dir = test::tempDir("gltf_parts");
  const std::string path = (dir / "lamp.gltf").string();
  ASSERT_TRUE(exportGltf(s, path).ok());
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in);
  const nlohmann::json* object = nullptr;
  for (const auto& m : j["meshes"])
    if (m["name"] == "object_0") object = &m;
  ASSERT_NE(object, nullptr);
  ASSERT_EQ((*object)["primitives"].size(), 2u);
  size_t indices = 0;
  for (const auto& p : (*object)["primitives"])
    indices += j["accessors"][p["indices"].get<int>()]["count"].get<size_t>();
  EXPECT_EQ(indices, 3 * mesh.triangles.size());
  const auto& shadeMaterial = j["materials"][(*object)["primitives"][1]["material"].get<int>()];
  EXPECT_EQ(shadeMaterial["name"], "object_0_part_1");
  EXPECT_NEAR(
      shadeMaterial["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"].get<double>(),
      1.5, 1e-9);
  const auto& standMaterial = j["materials"][(*object)["primitives"][0]["material"].get<int>()];
  EXPECT_EQ(standMaterial["pbrMetallicRoughness"]["metallicFactor"], 1);
}

TEST(GltfExport, GlbHoldsEverythingAndBadPathsAreErrors) {
  const RenderScene s = exportScene();
  const auto dir = test::tempDir("gltf_glb");
  const std::string path = (dir / "room.glb").string();
  ASSERT_TRUE(exportGltf(s, path).ok());
  EXPECT_EQ(
      std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
  Assimp::Importer importer;
  const aiScene* sc = importer.ReadFile(path, 0);
  ASSERT_NE(sc, nullptr) << importer.GetErrorString();
  EXPECT_EQ(sc->mNumMeshes, 11u);
  EXPECT_EQ(sc->mNumTextures, 6u);  // one embedded albedo PNG per box face
  const Status bad = exportGltf(s, (dir / "room.obj").string());
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message().find("room.obj"), std::string::npos);
  EXPECT_FALSE(exportGltf(s, (dir / "no_such_dir" / "x.gltf").string()).ok());
}

}  // namespace
}  // namespace inlay
