// GLB writer for library pieces (see glb_writer.h).
#include "glb_writer.h"

#include "inlay/modeling/image_io.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace inlay::library {

namespace {

using json = nlohmann::json;

constexpr int kFloat = 5126, kUshort = 5123, kUint = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// The document under construction and its binary chunk.
struct Doc {
  json gltf;
  std::string bin;

  int view(const void* data, size_t bytes, int target) {
    while (bin.size() % 4) bin.push_back('\0');
    gltf["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}, {"target", target}});
    bin.append(static_cast<const char*>(data), bytes);
    return int(gltf["bufferViews"].size()) - 1;
  }
  int accessor(json a) {
    gltf["accessors"].push_back(std::move(a));
    return int(gltf["accessors"].size()) - 1;
  }
};

json materialJson(const AssetMaterial& m, std::vector<std::string>& extensions) {
  const Vec3 c = m.baseColor.cwiseMax(0.0).cwiseMin(1.0);
  json out = {{"name", m.name},
              {"pbrMetallicRoughness",
               {{"baseColorFactor", {c.x(), c.y(), c.z(), 1.0}},
                {"metallicFactor", std::clamp(m.metallic, 0.0, 1.0)},
                {"roughnessFactor", std::clamp(m.roughness, 0.0, 1.0)}}}};
  const double strength = m.emission.maxCoeff();
  if (strength > 0) {
    const Vec3 e = m.emission / std::max(1.0, strength);
    out["emissiveFactor"] = {e.x(), e.y(), e.z()};
    if (strength > 1) {
      out["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", strength}};
      if (std::find(extensions.begin(), extensions.end(), "KHR_materials_emissive_strength") ==
          extensions.end())
        extensions.push_back("KHR_materials_emissive_strength");
    }
  }
  return out;
}

// The triangles of material `material` as one primitive with its own compact vertex arrays.
json primitive(Doc& doc, const TriangleMesh& mesh, uint32_t material) {
  std::vector<int64_t> remap(mesh.positions.size(), -1);
  std::vector<Vec3f> pos, nrm;
  std::vector<Vec2f> uv;
  std::vector<uint32_t> idx;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (mesh.triangleMaterial[t] != material) continue;
    for (uint32_t v : mesh.triangles[t]) {
      if (remap[v] < 0) {
        remap[v] = int64_t(pos.size());
        pos.push_back(mesh.positions[v]);
        nrm.push_back(mesh.normals[v]);
        uv.push_back(mesh.uvs[v]);
      }
      idx.push_back(uint32_t(remap[v]));
    }
  }
  if (idx.empty()) return nullptr;
  Vec3f lo = pos[0], hi = pos[0];
  for (const Vec3f& p : pos) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  json attributes;
  attributes["POSITION"] =
      doc.accessor({{"bufferView", doc.view(pos.data(), pos.size() * sizeof(Vec3f), kArrayBuffer)},
                    {"componentType", kFloat},
                    {"count", pos.size()},
                    {"type", "VEC3"},
                    {"min", {lo.x(), lo.y(), lo.z()}},
                    {"max", {hi.x(), hi.y(), hi.z()}}});
  attributes["NORMAL"] =
      doc.accessor({{"bufferView", doc.view(nrm.data(), nrm.size() * sizeof(Vec3f), kArrayBuffer)},
                    {"componentType", kFloat},
                    {"count", nrm.size()},
                    {"type", "VEC3"}});
  attributes["TEXCOORD_0"] =
      doc.accessor({{"bufferView", doc.view(uv.data(), uv.size() * sizeof(Vec2f), kArrayBuffer)},
                    {"componentType", kFloat},
                    {"count", uv.size()},
                    {"type", "VEC2"}});
  int indices;
  if (pos.size() <= 65535) {
    const std::vector<uint16_t> small(idx.begin(), idx.end());
    indices =
        doc.accessor({{"bufferView", doc.view(small.data(), small.size() * 2, kElementArrayBuffer)},
                      {"componentType", kUshort},
                      {"count", small.size()},
                      {"type", "SCALAR"}});
  } else {
    indices = doc.accessor({{"bufferView", doc.view(idx.data(), idx.size() * 4, kElementArrayBuffer)},
                            {"componentType", kUint},
                            {"count", idx.size()},
                            {"type", "SCALAR"}});
  }
  return {{"attributes", attributes}, {"indices", indices}, {"material", material}, {"mode", 4}};
}

std::string packGlb(const json& gltf, std::string bin) {
  std::string text = gltf.dump();
  while (text.size() % 4) text.push_back(' ');
  while (bin.size() % 4) bin.push_back('\0');
  auto u32 = [](std::string& out, uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  std::string glb;
  u32(glb, 0x46546C67u);  // "glTF"
  u32(glb, 2);
  u32(glb, uint32_t(12 + 8 + text.size() + 8 + bin.size()));
  u32(glb, uint32_t(text.size()));
  u32(glb, 0x4E4F534Au);  // "JSON"
  glb += text;
  u32(glb, uint32_t(bin.size()));
  u32(glb, 0x004E4942u);  // "BIN\0"
  glb += bin;
  return glb;
}

}  // namespace

std::string glbOf(const TriangleMesh& mesh, const std::string& name) {
  INLAY_CHECK(mesh.normals.size() == mesh.positions.size() && mesh.uvs.size() == mesh.positions.size());
  INLAY_CHECK(mesh.triangleMaterial.size() == mesh.triangles.size() && !mesh.materials.empty());
  Doc doc;
  doc.gltf["asset"] = {{"version", "2.0"},
                       {"generator", "inlay-make-library"},
                       {"copyright", "The Inlay authors; made procedurally by inlay-make-library"}};
  doc.gltf["bufferViews"] = json::array();
  doc.gltf["accessors"] = json::array();
  std::vector<std::string> extensions;
  json materials = json::array(), primitives = json::array();
  for (uint32_t m = 0; m < mesh.materials.size(); ++m) {
    materials.push_back(materialJson(mesh.materials[m], extensions));
    if (json p = primitive(doc, mesh, m); !p.is_null()) primitives.push_back(std::move(p));
  }
  doc.gltf["materials"] = materials;
  doc.gltf["meshes"] = json::array({{{"name", name}, {"primitives", primitives}}});
  doc.gltf["nodes"] = json::array({{{"name", name}, {"mesh", 0}}});
  doc.gltf["scenes"] = json::array({{{"name", name}, {"nodes", {0}}}});
  doc.gltf["scene"] = 0;
  if (!extensions.empty()) doc.gltf["extensionsUsed"] = extensions;
  while (doc.bin.size() % 4) doc.bin.push_back('\0');
  doc.gltf["buffers"] = json::array({{{"byteLength", doc.bin.size()}}});
  return packGlb(doc.gltf, doc.bin);
}

Status writeGlb(const TriangleMesh& mesh, const std::string& name, const std::string& path) {
  return writeFileAtomically(path, glbOf(mesh, name));
}

}  // namespace inlay::library
