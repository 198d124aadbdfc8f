// glTF 2.0 writer (see gltf_export.h). The JSON is built with nlohmann; geometry goes into one
// binary buffer (4-byte aligned views); textures are PNGs written by image_io (sRGB 8-bit, as
// glTF's baseColorTexture wants).
#include "inlay/render/gltf_export.h"

#include "inlay/modeling/image_io.h"
#include "sampling.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace inlay {

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

constexpr int kFloat = 5126, kUint = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// One glTF document under construction: JSON plus the binary buffer it points into.
class Builder {
 public:
  json doc;
  std::string bin;

  Builder() {
    doc["asset"] = {{"version", "2.0"}, {"generator", "inlay"}};
    for (const char* k : {"buffers", "bufferViews", "accessors", "meshes", "materials", "nodes",
                          "textures", "images", "samplers", "cameras"})
      doc[k] = json::array();
    doc["samplers"].push_back(
        {{"magFilter", 9729}, {"minFilter", 9729}, {"wrapS", 33071}, {"wrapT", 33071}});
  }

  int view(const void* data, size_t bytes, int target) {
    while (bin.size() % 4) bin.push_back('\0');
    json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
    if (target) v["target"] = target;
    bin.append(static_cast<const char*>(data), bytes);
    return push("bufferViews", v);
  }
  int vec3Accessor(const std::vector<Vec3f>& v, bool withBounds) {
    json a = {{"bufferView", view(v.data(), v.size() * sizeof(Vec3f), kArrayBuffer)},
              {"componentType", kFloat},
              {"count", v.size()},
              {"type", "VEC3"}};
    if (withBounds) {
      Vec3f lo = v[0], hi = v[0];
      for (const Vec3f& p : v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      a["min"] = {lo.x(), lo.y(), lo.z()};
      a["max"] = {hi.x(), hi.y(), hi.z()};
    }
    return push("accessors", a);
  }
  int vec2Accessor(const std::vector<Vec2f>& v) {
    return push("accessors", {{"bufferView", view(v.data(), v.size() * sizeof(Vec2f), kArrayBuffer)},
                              {"componentType", kFloat},
                              {"count", v.size()},
                              {"type", "VEC2"}});
  }
  int indexAccessor(const std::vector<uint32_t>& idx) {
    return push("accessors", {{"bufferView", view(idx.data(), idx.size() * 4, kElementArrayBuffer)},
                              {"componentType", kUint},
                              {"count", idx.size()},
                              {"type", "SCALAR"}});
  }
  // A primitive from flat arrays (normals and uvs may be empty).
  json primitive(const std::vector<Vec3f>& positions, const std::vector<Vec3f>& normals,
                 const std::vector<Vec2f>& uvs, const std::vector<uint32_t>& indices, int material) {
    json attributes = {{"POSITION", vec3Accessor(positions, true)}};
    if (!normals.empty()) attributes["NORMAL"] = vec3Accessor(normals, false);
    if (!uvs.empty()) attributes["TEXCOORD_0"] = vec2Accessor(uvs);
    return {{"attributes", attributes}, {"indices", indexAccessor(indices)}, {"material", material}};
  }
  int push(const char* key, json value) {
    doc[key].push_back(std::move(value));
    return int(doc[key].size()) - 1;
  }
  void useExtension(const std::string& name) {
    auto& used = doc["extensionsUsed"];
    if (std::find(used.begin(), used.end(), name) == used.end()) used.push_back(name);
  }
};

json emissiveMaterial(Builder& b, const std::string& name, const Vec3& radiance) {
  const double strength = std::max(1e-12, detail::maxComponent(radiance));
  const Vec3 colour = radiance / strength;
  b.useExtension("KHR_materials_emissive_strength");
  return {{"name", name},
          {"pbrMetallicRoughness",
           {{"baseColorFactor", {0, 0, 0, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 1}}},
          {"emissiveFactor", {colour.x(), colour.y(), colour.z()}},
          {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", strength}}}}}};
}

json objectMaterial(Builder& b, const Material& m, const std::string& name) {
  using K = Material::Kind;
  if (m.kind == K::Emissive) return emissiveMaterial(b, name, m.emission.cwiseMax(0.0));
  const Vec3 a = m.albedo.cwiseMax(0.0).cwiseMin(1.0);
  const bool glass = m.kind == K::Glass || m.kind == K::RoughGlass;
  const bool metal = m.kind == K::Conductor || m.kind == K::Mirror;
  const double roughness = m.kind == K::Diffuse ? 1.0
                           : m.kind == K::Mirror || m.kind == K::Glass
                               ? 0.0
                               : std::clamp(m.roughness, 0.0, 1.0);
  const Vec3 base = glass ? Vec3(Vec3::Ones()) : a;
  json mat = {{"name", name},
              {"pbrMetallicRoughness",
               {{"baseColorFactor", {base.x(), base.y(), base.z(), 1}},
                {"metallicFactor", metal ? 1 : 0},
                {"roughnessFactor", roughness}}}};
  if (glass || m.kind == K::Glossy) {
    b.useExtension("KHR_materials_ior");
    mat["extensions"]["KHR_materials_ior"] = {{"ior", m.ior}};
  }
  if (glass) {
    b.useExtension("KHR_materials_transmission");
    mat["extensions"]["KHR_materials_transmission"] = {{"transmissionFactor", 1.0}};
  }
  return mat;
}

// Triangles of one room surface sharing a plane orientation: one textured primitive.
struct PlanarGroup {
  Vec3 normal;
  std::vector<std::array<Vec3, 3>> triangles;
};

std::vector<PlanarGroup> planarGroups(const TriangleMesh& mesh) {
  std::vector<PlanarGroup> groups;
  for (const auto& t : mesh.triangles) {
    if (std::max({t[0], t[1], t[2]}) >= mesh.positions.size()) continue;
    const std::array<Vec3, 3> p = {mesh.positions[t[0]].cast<double>(),
                                   mesh.positions[t[1]].cast<double>(),
                                   mesh.positions[t[2]].cast<double>()};
    const Vec3 n = (p[1] - p[0]).cross(p[2] - p[0]);
    if (!(n.norm() > 0) || !n.allFinite()) continue;
    const Vec3 u = n.normalized();
    auto g = std::find_if(groups.begin(), groups.end(),
                          [&](const PlanarGroup& q) { return q.normal.dot(u) > 0.999; });
    if (g == groups.end()) g = groups.insert(groups.end(), PlanarGroup{u, {}});
    g->triangles.push_back(p);
  }
  return groups;
}

// The albedo of one planar group baked into a texture: texel centres inside a triangle (up to
// one texel beyond its edges, so bilinear filtering finds no background at seams) take the
// projected albedo of the surface point they map to.
ImageF bakeGroup(const ProjectedAlbedo& albedo, int surfaceId, const PlanarGroup& g, const Vec2& lo,
                 const Vec2& size, const detail::Frame& frame, int w, int h, const Vec3& fill) {
  ImageF tex(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) tex.setRgb(x, y, fill);
  auto toTexel = [&](const Vec3& p) {
    return Vec2((p.dot(frame.s) - lo.x()) / size.x() * w, (p.dot(frame.t) - lo.y()) / size.y() * h);
  };
  for (const auto& tri : g.triangles) {
    const Vec2 a = toTexel(tri[0]), b = toTexel(tri[1]), c = toTexel(tri[2]);
    const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (!(std::abs(area) > 1e-12)) continue;
    const double slack = 1.5 / std::max(1.0, std::sqrt(std::abs(area)));
    const int x0 = std::max(0, int(std::floor(std::min({a.x(), b.x(), c.x()}) - 1)));
    const int x1 = std::min(w - 1, int(std::ceil(std::max({a.x(), b.x(), c.x()}) + 1)));
    const int y0 = std::max(0, int(std::floor(std::min({a.y(), b.y(), c.y()}) - 1)));
    const int y1 = std::min(h - 1, int(std::ceil(std::max({a.y(), b.y(), c.y()}) + 1)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Vec2 q(x + 0.5, y + 0.5);
        double l1 = ((q - a).x() * (c - a).y() - (q - a).y() * (c - a).x()) / area;
        double l2 = ((b - a).x() * (q - a).y() - (b - a).y() * (q - a).x()) / area;
        double l0 = 1 - l1 - l2;
        if (std::min({l0, l1, l2}) < -slack) continue;
        l0 = std::max(0.0, l0), l1 = std::max(0.0, l1), l2 = std::max(0.0, l2);
        const double s = l0 + l1 + l2;
        const Vec3 p = (l0 * tri[0] + l1 * tri[1] + l2 * tri[2]) / s;
        tex.setRgb(x, y, albedo.lookup(surfaceId, p).cwiseMax(0.0).cwiseMin(1.0));
      }
  }
  return tex;
}

Expected<std::string> pngBytes(const ImageF& image, const fs::path& scratch) {
  if (Status s = saveImage(scratch.string(), image); !s.ok()) return s.error();
  std::ifstream in(scratch, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  std::error_code ec;
  fs::remove(scratch, ec);
  return bytes.str();
}

struct Writer {
  Builder b;
  const fs::path path;
  const bool binary;
  std::vector<std::pair<fs::path, std::string>> sideFiles;  // .gltf: PNGs and .bin
  int textureCount = 0;

  Writer(const std::string& p, bool glb) : path(p), binary(glb) {}

  Expected<int> texture(const ImageF& image) {
    const fs::path scratch = fs::temp_directory_path() / ("inlay_gltf_" + std::to_string(::getpid()) +
                                                          "_" + std::to_string(textureCount) + ".png");
    Expected<std::string> png = pngBytes(image, scratch);
    if (!png.ok()) return png.error();
    json img;
    if (binary) {
      img = {{"bufferView", b.view(png->data(), png->size(), 0)}, {"mimeType", "image/png"}};
    } else {
      const std::string name = path.stem().string() + "_albedo_" + std::to_string(textureCount) + ".png";
      img = {{"uri", name}};
      sideFiles.emplace_back(path.parent_path() / name, std::move(*png));
    }
    ++textureCount;
    const int image_ = b.push("images", img);
    return b.push("textures", {{"sampler", 0}, {"source", image_}});
  }

  // A room surface's material: its baked albedo, matte; or as the user marked it (the
  // renderer's room BSDFs): a mirror is a smooth metal of its reflectance (metallic 1,
  // roughness 0, no albedo texture: a mirror shows no albedo of its own), a glossy surface
  // keeps the albedo under a dielectric coat of its roughness and ior.
  json roomSurfaceMaterial(const std::string& surfaceName, int albedoTexture, const Material* marked) {
    using K = Material::Kind;
    if (marked && marked->kind == K::Mirror) {
      const Vec3 r = marked->albedo.cwiseMax(0.0).cwiseMin(1.0);
      return {{"name", surfaceName + "_mirror"},
              {"pbrMetallicRoughness",
               {{"baseColorFactor", {r.x(), r.y(), r.z(), 1}},
                {"metallicFactor", 1},
                {"roughnessFactor", 0}}}};
    }
    json mat = {{"name", surfaceName + "_albedo"},
                {"pbrMetallicRoughness",
                 {{"baseColorTexture", {{"index", albedoTexture}}},
                  {"metallicFactor", 0},
                  {"roughnessFactor", 1}}}};
    if (marked && marked->kind == K::Glossy) {
      mat["name"] = surfaceName + "_glossy";
      mat["pbrMetallicRoughness"]["roughnessFactor"] = std::clamp(marked->roughness, 0.0, 1.0);
      b.useExtension("KHR_materials_ior");
      mat["extensions"]["KHR_materials_ior"] = {{"ior", marked->ior}};
    }
    return mat;
  }

  Status room(const RenderScene& scene, const GltfExportOptions& options, json& children) {
    for (size_t id = 0; id < scene.room.surfaces.size(); ++id) {
      const Surface& surf = scene.room.surfaces[id];
      if (surf.kind == SurfaceKind::OccluderCard) continue;
      json primitives = json::array();
      const Vec3 fill = id < scene.roomAlbedo.surfaceMean.size() ? scene.roomAlbedo.surfaceMean[id]
                                                                 : Vec3::Constant(0.5);
      for (const PlanarGroup& g : planarGroups(surf.meshWorld)) {
        const detail::Frame frame(g.normal);
        Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
        for (const auto& t : g.triangles)
          for (const Vec3& p : t) {
            const Vec2 q(p.dot(frame.s), p.dot(frame.t));
            lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
          }
        const Vec2 size = (hi - lo).cwiseMax(1e-6);
        const int w =
            std::clamp(int(std::ceil(size.x() * options.texelsPerMetre)), 4, options.maxTextureSize);
        const int h =
            std::clamp(int(std::ceil(size.y() * options.texelsPerMetre)), 4, options.maxTextureSize);
        Expected<int> tex = texture(bakeGroup(scene.roomAlbedo, int(id), g, lo, size, frame, w, h,
                                              fill.cwiseMax(0.0).cwiseMin(1.0)));
        if (!tex.ok()) return tex.error();
        const Material* marked = id < scene.roomMaterials.size() && scene.roomMaterials[id]
                                     ? &*scene.roomMaterials[id]
                                     : nullptr;
        const int material = b.push("materials", roomSurfaceMaterial(surf.name, *tex, marked));
        std::vector<Vec3f> pos, nrm;
        std::vector<Vec2f> uv;
        std::vector<uint32_t> idx;
        for (const auto& t : g.triangles)
          for (const Vec3& p : t) {
            idx.push_back(uint32_t(pos.size()));
            pos.push_back(p.cast<float>());
            nrm.push_back(g.normal.cast<float>());
            uv.emplace_back(float((p.dot(frame.s) - lo.x()) / size.x()),
                            float((p.dot(frame.t) - lo.y()) / size.y()));
          }
        primitives.push_back(b.primitive(pos, nrm, uv, idx, material));
      }
      if (primitives.empty()) continue;
      const int mesh = b.push("meshes", {{"name", surf.name}, {"primitives", primitives}});
      children.push_back(b.push("nodes", {{"name", surf.name}, {"mesh", mesh}}));
    }
    return Status::Ok();
  }

  void lights(const RenderScene& scene, json& children, std::vector<std::string>* warnings) {
    for (size_t i = 0; i < scene.lights.size(); ++i) {
      const AreaLight& l = scene.lights[i];
      const Vec3 n = l.normal();
      if (!n.allFinite() || !(l.area() > 0) || !l.radiance.allFinite() || !(l.radiance.maxCoeff() > 0)) {
        if (warnings)
          warnings->push_back("light " + std::to_string(i) + ": degenerate or dark, not exported");
        continue;
      }
      const auto c = detail::emitterCorners(l);
      std::vector<Vec3f> pos, nrm;
      for (const Vec3& p : c) pos.push_back(p.cast<float>()), nrm.push_back(n.cast<float>());
      const std::string name = "light_" + std::to_string(i);
      const int material = b.push("materials", emissiveMaterial(b, name, l.radiance.cwiseMax(0.0)));
      const int mesh = b.push(
          "meshes",
          {{"name", name},
           {"primitives", json::array({b.primitive(pos, nrm, {}, {0, 1, 2, 0, 2, 3}, material)})}});
      children.push_back(b.push("nodes", {{"name", name}, {"mesh", mesh}}));
    }
    if (!scene.suns.empty() && warnings)
      warnings->push_back("sun shafts (masked directional light) have no glTF equivalent: not exported");
  }

  void camera(const Camera& cam, json& children) {
    const double w = std::max(1, cam.widthPx), h = std::max(1, cam.heightPx);
    const int c = b.push("cameras", {{"type", "perspective"},
                                     {"perspective",
                                      {{"yfov", 2 * std::atan(0.5 * h / cam.focalPx)},
                                       {"aspectRatio", w / h},
                                       {"znear", 0.01},
                                       {"zfar", 1000.0}}},
                                     {"extras",
                                      {{"width_px", cam.widthPx},
                                       {"height_px", cam.heightPx},
                                       {"focal_px", cam.focalPx},
                                       {"principal_px", {cam.principalPx.x(), cam.principalPx.y()}}}}});
    const Eigen::Quaterniond q(cam.worldFromCamera);
    const Vec3 t = cam.centreWorld();
    children.push_back(b.push("nodes", {{"name", "camera"},
                                        {"camera", c},
                                        {"rotation", {q.x(), q.y(), q.z(), q.w()}},
                                        {"translation", {t.x(), t.y(), t.z()}}}));
  }

  // An object's primitives: one per part material (InsertedObject::partMaterials) sharing the
  // vertex accessors, or one with the object's material.
  json objectPrimitives(const InsertedObject& o, const std::string& name) {
    const TriangleMesh& m = *o.meshObject;
    const bool parts = !o.partMaterials.empty() && m.triangleMaterial.size() == m.triangles.size();
    const size_t count = parts ? o.partMaterials.size() : 1;
    std::vector<std::vector<uint32_t>> idx(count);
    for (size_t t = 0; t < m.triangles.size(); ++t) {
      const auto& tri = m.triangles[t];
      const size_t k = parts ? m.triangleMaterial[t] : 0;
      if (k < count && std::max({tri[0], tri[1], tri[2]}) < m.positions.size())
        idx[k].insert(idx[k].end(), {tri[0], tri[1], tri[2]});
    }
    json attributes = {{"POSITION", b.vec3Accessor(m.positions, true)}};
    if (m.normals.size() == m.positions.size()) attributes["NORMAL"] = b.vec3Accessor(m.normals, false);
    json primitives = json::array();
    for (size_t k = 0; k < count; ++k) {
      if (idx[k].empty()) continue;
      const Material& mat = parts ? o.partMaterials[k] : o.material;
      const std::string matName = parts ? name + "_part_" + std::to_string(k) : name;
      const int material = b.push("materials", objectMaterial(b, mat, matName));
      primitives.push_back(
          {{"attributes", attributes}, {"indices", b.indexAccessor(idx[k])}, {"material", material}});
    }
    return primitives;
  }

  void objects(const RenderScene& scene, json& children, std::vector<std::string>* warnings) {
    for (size_t i = 0; i < scene.objects.size(); ++i) {
      const InsertedObject& o = scene.objects[i];
      const std::string name = "object_" + std::to_string(i);
      if (!o.meshObject || o.meshObject->empty() || !o.worldFromObject.allFinite()) {
        if (warnings) warnings->push_back(name + ": empty mesh or invalid transform, not exported");
        continue;
      }
      const int mesh = b.push("meshes", {{"name", name}, {"primitives", objectPrimitives(o, name)}});
      json matrix = json::array();
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) matrix.push_back(o.worldFromObject(r, c));
      children.push_back(b.push("nodes", {{"name", name}, {"mesh", mesh}, {"matrix", matrix}}));
    }
  }

  Status write() {
    const std::string bufferName = path.stem().string() + ".bin";
    while (b.bin.size() % 4) b.bin.push_back('\0');
    json buffer = {{"byteLength", b.bin.size()}};
    if (!binary) buffer["uri"] = bufferName;
    b.doc["buffers"].push_back(buffer);
    for (const char* k : {"textures", "images", "cameras"})
      if (b.doc[k].empty()) b.doc.erase(k);
    if (!binary) {
      for (const auto& [file, bytes] : sideFiles)
        if (Status s = writeFileAtomically(file.string(), bytes); !s.ok()) return s;
      if (Status s = writeFileAtomically((path.parent_path() / bufferName).string(), b.bin); !s.ok())
        return s;
      return writeFileAtomically(path.string(), b.doc.dump(1));
    }
    std::string text = b.doc.dump();
    while (text.size() % 4) text.push_back(' ');
    auto u32 = [](std::string& out, uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    std::string glb;
    u32(glb, 0x46546C67u);  // "glTF"
    u32(glb, 2);
    u32(glb, uint32_t(12 + 8 + text.size() + 8 + b.bin.size()));
    u32(glb, uint32_t(text.size()));
    u32(glb, 0x4E4F534Au);  // "JSON"
    glb += text;
    u32(glb, uint32_t(b.bin.size()));
    u32(glb, 0x004E4942u);  // "BIN\0"
    glb += b.bin;
    return writeFileAtomically(path.string(), glb);
  }
};

}  // namespace

Status exportGltf(const RenderScene& scene, const std::string& path, const GltfExportOptions& options,
                  std::vector<std::string>* warnings) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".gltf" && ext != ".glb")
    return Error{path, "", "the export file must end in .gltf or .glb"};
  if (!(options.texelsPerMetre > 0) || options.maxTextureSize < 4)
    return Error{path, "", "texture density and size must be positive"};
  Writer w(path, ext == ".glb");
  json children = json::array();
  if (Status s = w.room(scene, options, children); !s.ok()) return s.error().inFile(path);
  w.lights(scene, children, warnings);
  w.camera(scene.camera, children);
  w.objects(scene, children, warnings);
  w.b.doc["scenes"] = json::array({{{"name", "inlay"}, {"nodes", children}}});
  w.b.doc["scene"] = 0;
  return w.write();
}

}  // namespace inlay
