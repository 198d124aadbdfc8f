// Meshes: builtins, helpers, the importers on ../shared/models and on malformed files made here.
#include "inlay/modeling/mesh.h"

#include "test_support.h"

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace inlay {
namespace {

namespace fs = std::filesystem;

fs::path writeFile(const fs::path& dir, const std::string& name, const std::string& bytes) {
  fs::path p = dir / name;
  std::ofstream out(p, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  return p;
}
std::string readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

Vec3f faceNormal(const TriangleMesh& m, size_t t) {
  const auto& tri = m.triangles[t];
  return (m.positions[tri[1]] - m.positions[tri[0]]).cross(m.positions[tri[2]] - m.positions[tri[0]]);
}

// Signed volume (divergence theorem): positive for a closed mesh with outward winding.
double signedVolume(const TriangleMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles)
    v += m.positions[t[0]].cast<double>().dot(
             m.positions[t[1]].cast<double>().cross(m.positions[t[2]].cast<double>())) /
         6.0;
  return v;
}

TEST(Mesh, SphereIsAUnitDiameterIcosphere) {
  const TriangleMesh s = makeSphere(4);
  EXPECT_EQ(s.triangles.size(), 20u * 256u);
  EXPECT_EQ(s.positions.size(), 10u * 256u + 2u);  // V = 10 * 4^n + 2
  ASSERT_EQ(s.normals.size(), s.positions.size());
  for (size_t i = 0; i < s.positions.size(); ++i) {
    EXPECT_NEAR(s.positions[i].norm(), 0.5f, 1e-6f);
    EXPECT_NEAR((s.normals[i] - 2.f * s.positions[i]).norm(), 0.f, 1e-5f);
  }
  const auto b = s.bounds();
  EXPECT_NEAR(b.min().x(), -0.5f, 1e-3f);
  EXPECT_NEAR(b.max().y(), 0.5f, 1e-3f);
  // Outward winding and close to the ball's volume.
  EXPECT_NEAR(signedVolume(s), 4.0 / 3.0 * M_PI * 0.125, 0.01);
  EXPECT_EQ(makeSphere(0).triangles.size(), 20u);
}

TEST(Mesh, CubeHasFlatOutwardFaces) {
  const TriangleMesh c = makeCube();
  EXPECT_EQ(c.triangles.size(), 12u);
  EXPECT_EQ(c.positions.size(), 24u);
  const auto b = c.bounds();
  EXPECT_EQ(b.min(), Vec3f(-0.5f, -0.5f, -0.5f));
  EXPECT_EQ(b.max(), Vec3f(0.5f, 0.5f, 0.5f));
  for (size_t t = 0; t < c.triangles.size(); ++t) {
    const Vec3f n = faceNormal(c, t).normalized();
    for (uint32_t v : c.triangles[t]) EXPECT_NEAR((c.normals[v] - n).norm(), 0.f, 1e-6f);
    const Vec3f centroid = (c.positions[c.triangles[t][0]] + c.positions[c.triangles[t][1]] +
                            c.positions[c.triangles[t][2]]) /
                           3.f;
    EXPECT_GT(n.dot(centroid), 0.f);
  }
  EXPECT_NEAR(signedVolume(c), 1.0, 1e-6);
}

TEST(Mesh, VertexNormalsAreAreaWeighted) {
  TriangleMesh m;
  // A big triangle facing +z and a small one facing +x share vertex 0.
  m.positions = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, -1}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  m.computeVertexNormals();
  ASSERT_EQ(m.normals.size(), 5u);
  EXPECT_NEAR((m.normals[1] - Vec3f(0, 0, 1)).norm(), 0.f, 1e-6f);
  EXPECT_NEAR((m.normals[3] - Vec3f(1, 0, 0)).norm(), 0.f, 1e-6f);
  // Vertex 0: (0,0,16) + (1,0,0) normalised.
  EXPECT_NEAR((m.normals[0] - Vec3f(1, 0, 16).normalized()).norm(), 0.f, 1e-6f);
}

TEST(Mesh, AppendOffsetsIndicesAndKeepsAttributes) {
  TriangleMesh a = makeCube();
  const TriangleMesh s = makeSphere(1);
  a.append(s);
  EXPECT_EQ(a.positions.size(), 24u + s.positions.size());
  EXPECT_EQ(a.triangles.size(), 12u + s.triangles.size());
  EXPECT_EQ(a.normals.size(), a.positions.size());
  EXPECT_EQ(a.uvs.size(), a.positions.size());  // the sphere's are zero-filled
  EXPECT_EQ(a.triangles.back()[2], s.triangles.back()[2] + 24u);
  // Materials: one side with per-triangle materials gives every triangle one.
  TriangleMesh withMat = makeCube();
  withMat.materials = {AssetMaterial{"red", Vec3(1, 0, 0)}};
  withMat.triangleMaterial.assign(12, 0);
  TriangleMesh plain = makeCube();
  plain.normals.clear();
  plain.append(withMat);
  ASSERT_EQ(plain.triangleMaterial.size(), 24u);
  EXPECT_EQ(plain.materials[plain.triangleMaterial[20]].name, "red");
  EXPECT_NE(plain.materials[plain.triangleMaterial[0]].name, "red");
  EXPECT_EQ(plain.normals.size(), plain.positions.size());  // computed for the plain side
  TriangleMesh empty;
  empty.append(s);
  EXPECT_EQ(empty.triangles, s.triangles);
  EXPECT_EQ(empty.normals.size(), s.normals.size());
}

TEST(Mesh, Builtins) {
  auto s = loadMesh("builtin:sphere");
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->triangles.size(), makeSphere().triangles.size());
  auto c = loadMesh("builtin:cube");
  ASSERT_TRUE(c.ok());
  EXPECT_EQ(c->triangles.size(), 12u);
  auto bad = loadMesh("builtin:torus");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().reason.find("unknown builtin"), std::string::npos);
}

TEST(Mesh, ObjPolygonsNegativeIndicesAndCorners) {
  const auto dir = test::tempDir("obj_ok");
  const auto p = writeFile(dir, "pent.obj",
                           "# a pentagon and a relative-index triangle\n"
                           "o thing\nv 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\n"
                           "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
                           "usemtl whatever\ns 1\n"
                           "f 1/1/1 2/2/1 3/3/1 4/1/1 5/2/1\n"
                           "v 0 0 1\nf -1/1/1 -6/2/1 -5/3/1\n");
  auto m = loadMesh(p.string());
  ASSERT_TRUE(m.ok()) << m.error().message();
  EXPECT_EQ(m->triangles.size(), 4u);  // 3 from the (convex) pentagon + 1
  ASSERT_EQ(m->normals.size(), m->positions.size());
  ASSERT_EQ(m->uvs.size(), m->positions.size());
  // The relative triangle uses the last vertex (0,0,1) and the first two.
  const auto& t = m->triangles.back();
  EXPECT_EQ(m->positions[t[0]], Vec3f(0, 0, 1));
  EXPECT_EQ(m->positions[t[1]], Vec3f(0, 0, 0));
  EXPECT_EQ(m->positions[t[2]], Vec3f(2, 0, 0));
  // Plain faces without vt/vn keep the file's vertices as they are.
  const auto q = writeFile(dir, "quad.obj", "v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\nf 1 2 3 4\r\n");
  m = loadMesh(q.string());
  ASSERT_TRUE(m.ok()) << m.error().message();
  EXPECT_EQ(m->positions.size(), 4u);
  EXPECT_EQ(m->triangles.size(), 2u);
  EXPECT_TRUE(m->normals.empty());
}

TEST(Mesh, ObjMaterialsFromMtl) {
  const auto dir = test::tempDir("obj_mtl");
  writeFile(dir, "m.mtl",
            "# two materials\nnewmtl red\nKd 0.8 0.1 0.1\nNs 98\nNi 1.33\nd 0.25\n"
            "newmtl lamp\nKd 1 1 1\nKe 4 3 2\nPr 0.2\nPm 1\nNs 1000\nnewmtl unused\nKd 0 0 0\n");
  const auto p = writeFile(dir, "m.obj",
                           "mtllib m.mtl missing.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                           "f 1 2 3\nusemtl red\nf 1 2 3 4\nusemtl lamp\nf 1 3 4\n"
                           "usemtl nowhere\nf 2 3 4\n");
  auto m = loadMesh(p.string());
  ASSERT_TRUE(m.ok()) << m.error().message();
  ASSERT_EQ(m->triangles.size(), 5u);
  ASSERT_EQ(m->triangleMaterial.size(), 5u);
  auto mat = [&](size_t t) { return m->materials.at(m->triangleMaterial[t]); };
  EXPECT_EQ(mat(0).name, "default");  // before any usemtl
  EXPECT_EQ(mat(1).name, "red");
  EXPECT_EQ(mat(2).name, "red");
  EXPECT_EQ(mat(3).name, "lamp");
  EXPECT_EQ(mat(4).name, "nowhere");  // not in any MTL: defaults
  EXPECT_EQ(mat(1).baseColor, Vec3(0.8, 0.1, 0.1));
  EXPECT_NEAR(mat(1).roughness, std::sqrt(2.0 / 100.0), 1e-12);
  EXPECT_NEAR(mat(1).ior, 1.33, 1e-12);
  EXPECT_NEAR(mat(1).transmission, 0.75, 1e-12);
  EXPECT_EQ(mat(3).emission, Vec3(4, 3, 2));
  EXPECT_NEAR(mat(3).roughness, 0.2, 1e-12);  // Pr wins over Ns
  EXPECT_NEAR(mat(3).metallic, 1.0, 1e-12);
  EXPECT_EQ(mat(4).baseColor, AssetMaterial{}.baseColor);
}

struct BadMesh {
  const char* name;
  const char* file;
  std::string content;
  std::string element;     // expected Error::key ("" = any)
  std::string reasonPart;  // expected substring of Error::reason
};

class MeshBadInput : public ::testing::TestWithParam<BadMesh> {};

TEST_P(MeshBadInput, IsRefusedWithElementAndReason) {
  const BadMesh& c = GetParam();
  const auto dir = test::tempDir(std::string("mesh_bad_") + c.name);
  const auto p = writeFile(dir, c.file, c.content);
  auto m = loadMesh(p.string());
  ASSERT_FALSE(m.ok()) << c.name;
  EXPECT_EQ(m.error().file, p.string());
  if (!c.element.empty()) {
    EXPECT_EQ(m.error().key, c.element) << m.error().message();
  }
  EXPECT_NE(m.error().reason.find(c.reasonPart), std::string::npos) << m.error().message();
}

std::string plyHeader(const std::string& format, int vertices, int faces,
                      const std::string& indexType = "int") {
  return "ply\nformat " + format + " 1.0\ncomment test\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\n" + "element face " +
         std::to_string(faces) + "\nproperty list uchar " + indexType + " vertex_indices\nend_header\n";
}
std::string binaryTriangle() {
  std::string s;
  const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  s.append(reinterpret_cast<const char*>(v), sizeof v);
  s += char(3);
  const int32_t idx[3] = {0, 1, 2};
  s.append(reinterpret_cast<const char*>(idx), sizeof idx);
  return s;
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, MeshBadInput,
    ::testing::Values(
        BadMesh{"empty_obj", "e.obj", "", "", "empty file"},
        BadMesh{"comments_only", "c.obj", "# nothing\n\n", "", "no triangles"},
        BadMesh{"nan_vertex", "n.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "line 2", "non-finite"},
        BadMesh{"inf_vertex", "i.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n", "line 3", "non-finite"},
        BadMesh{"overflow_vertex", "o.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n", "line 2", ""},
        BadMesh{"index_too_big", "b.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "line 4",
                "out of range"},
        BadMesh{"index_zero", "z.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "line 4", "index 0"},
        BadMesh{"negative_before_start", "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n", "line 4",
                "before the first"},
        BadMesh{"normal_index", "vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n",
                "line 5", "normal index 2 out of range"},
        BadMesh{"two_vertex_face", "t.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "line 3", "at least 3"},
        BadMesh{"garbage_index", "g.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", "line 4", "malformed"},
        BadMesh{"degenerate_only", "d.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", "", "zero area"},
        BadMesh{"empty_ply", "e.ply", "", "", "empty file"},
        BadMesh{"not_ply", "x.ply", "solid cube\nendsolid\n", "header", "not a PLY"},
        BadMesh{"ply_no_end", "h.ply", "ply\nformat ascii 1.0\nelement vertex 3\n", "header",
                "end_header"},
        BadMesh{"ply_ascii_short", "s.ply", plyHeader("ascii", 5, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                "", ""},
        BadMesh{"ply_binary_lies", "l.ply", plyHeader("binary_little_endian", 3, 2) + binaryTriangle(),
                "face 1",
                "unexpected end of data: the file ends here, but header line 8 claims 2 "
                "'face' entries"},
        BadMesh{"ply_huge_count", "u.ply",
                plyHeader("binary_little_endian", 2000000000, 1) + binaryTriangle(), "header line 4",
                "more data than the file holds: 'vertex' claims 2000000000 entries, so the data "
                "after end_header needs at least 24000000000 bytes, but the file holds 49"},
        BadMesh{"ply_bad_index", "i.ply", plyHeader("ascii", 3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
                "face 0", "out of range"},
        BadMesh{"ply_negative_index", "n.ply",
                plyHeader("ascii", 3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "face 0", "out of range"},
        BadMesh{"ply_nan", "f.ply", plyHeader("ascii", 3, 1) + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n",
                "vertex 1", "non-finite"},
        // List lengths read as float (fuzz_mesh_ply: a NaN count was converted to an integer).
        BadMesh{"ply_nan_list_count", "c.ply",
                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nelement extra 1\nproperty list float int junk\nend_header\n"
                "0 0 0\n1 0 0\n0 1 0\nnan 1 2\n",
                "extra 0", "bad list length"},
        BadMesh{"ply_fractional_list_count", "v.ply",
                "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                "property float z\nproperty list float int junk\nend_header\n0 0 0 2.5 1 2\n",
                "vertex 0", "bad list length"},
        BadMesh{"ply_nan_index", "x.ply",
                plyHeader("ascii", 3, 1, "float") + "0 0 0\n1 0 0\n0 1 0\n3 0 nan 2\n", "face 0",
                "vertex index nan out of range"},
        BadMesh{"unknown_ext", "a.stl", "solid\n", "", "unsupported mesh format"},
        BadMesh{"gltf_not_json", "a.gltf", "{ this is not json", "JSON", "invalid"},
        // A 12-byte buffer whose view claims 36 bytes.
        BadMesh{"gltf_view_past_buffer", "v.gltf",
                R"({"asset": {"version": "2.0"},
                    "buffers": [{"byteLength": 12, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}],
                    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
                    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
                    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
                    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})",
                "bufferViews[0]", "past the end of buffer 0"},
        // The buffer claims more bytes than its data holds.
        BadMesh{"gltf_buffer_short", "b.gltf",
                R"({"asset": {"version": "2.0"},
                    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}],
                    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
                    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
                    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
                    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})",
                "buffers[0]", "exceeds"},
        // The accessor reads 3 x VEC3 from a 12-byte view.
        BadMesh{"gltf_accessor_past_view", "a.gltf",
                R"({"asset": {"version": "2.0"},
                    "buffers": [{"byteLength": 12, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}],
                    "bufferViews": [{"buffer": 0, "byteLength": 12}],
                    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
                    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
                    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})",
                "accessors[0]", "past the end of bufferView 0"},
        BadMesh{"glb_garbage", "g.glb", std::string("glTF\x02\0\0\0\xff\xff\xff\x7f", 12), "", ""}),
    [](const ::testing::TestParamInfo<BadMesh>& p) { return std::string(p.param.name); });

TEST(Mesh, PlyAsciiAndBinaryAndTristrips) {
  const auto dir = test::tempDir("ply_ok");
  auto a = loadMesh(
      writeFile(dir, "a.ply", plyHeader("ascii", 4, 1) + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
          .string());
  ASSERT_TRUE(a.ok()) << a.error().message();
  EXPECT_EQ(a->triangles.size(), 2u);
  auto b = loadMesh(
      writeFile(dir, "b.ply", plyHeader("binary_little_endian", 3, 1) + binaryTriangle()).string());
  ASSERT_TRUE(b.ok()) << b.error().message();
  EXPECT_EQ(b->triangles.size(), 1u);
  EXPECT_EQ(b->positions[1], Vec3f(1, 0, 0));
  // Big endian with normals and an extra element to skip.
  std::string be =
      "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nproperty float nx\nproperty float ny\n"
      "property float nz\nelement face 1\nproperty list uchar int vertex_indices\n"
      "element extra 1\nproperty list uchar short junk\nend_header\n";
  auto putBe = [&](const void* p, size_t n) {
    const char* c = static_cast<const char*>(p);
    for (size_t i = 0; i < n; ++i) be += c[n - 1 - i];
  };
  const float verts[3][6] = {{0, 0, 0, 0, 0, 2}, {1, 0, 0, 0, 0, 2}, {0, 1, 0, 0, 0, 2}};
  for (const auto& v : verts)
    for (float f : v) putBe(&f, 4);
  be += char(3);
  for (int32_t i : {0, 1, 2}) putBe(&i, 4);
  be += char(2);
  for (int16_t j : {int16_t(7), int16_t(8)}) putBe(&j, 2);
  auto c = loadMesh(writeFile(dir, "c.ply", be).string());
  ASSERT_TRUE(c.ok()) << c.error().message();
  ASSERT_EQ(c->normals.size(), 3u);
  EXPECT_NEAR((c->normals[0] - Vec3f(0, 0, 1)).norm(), 0.f, 1e-6f);  // normalised
  EXPECT_EQ(c->positions[2], Vec3f(0, 1, 0));
  // Triangle strips with a restart: 0 1 2 3 -1 2 1 4 -> (0,1,2) (2,1,3) | (2,1,4).
  const std::string strips =
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
      "property float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 2 0\n8 0 1 2 3 -1 2 1 4\n";
  auto s = loadMesh(writeFile(dir, "s.ply", strips).string());
  ASSERT_TRUE(s.ok()) << s.error().message();
  ASSERT_EQ(s->triangles.size(), 3u);
  EXPECT_EQ(s->triangles[1], (std::array<uint32_t, 3>{2, 1, 3}));
  // Consistent winding: every triangle faces +z.
  for (size_t t = 0; t < s->triangles.size(); ++t) EXPECT_GT(faceNormal(*s, t).z(), 0.f) << t;
}

// fuzz_mesh_ply's timeout: an element with no properties and a count of 6e18 was "read" entry by
// entry. It holds no bytes, so it is skipped whatever it claims.
TEST(Mesh, PlyElementWithoutPropertiesIsSkipped) {
  const auto dir = test::tempDir("ply_empty_element");
  const std::string ply =
      "ply\nformat ascii 1.0\nelement junk 6304763018308164717\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  auto m = loadMesh(writeFile(dir, "e.ply", ply).string());
  ASSERT_TRUE(m.ok()) << m.error().message();
  EXPECT_EQ(m->triangles.size(), 1u);
}

TEST(Mesh, LimitsAreEnforced) {
  const auto dir = test::tempDir("mesh_limits");
  const auto p = writeFile(dir, "q.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  MeshLimits l;
  l.maxTriangles = 1;
  EXPECT_FALSE(loadMesh(p.string(), l).ok());
  l = MeshLimits{};
  l.maxVertices = 3;
  EXPECT_FALSE(loadMesh(p.string(), l).ok());
  l = MeshLimits{};
  l.maxFileBytes = 10;
  auto m = loadMesh(p.string(), l);
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.error().reason.find("exceeds"), std::string::npos);
  EXPECT_TRUE(loadMesh(p.string()).ok());
  EXPECT_FALSE(loadMesh((dir / "missing.obj").string()).ok());
  EXPECT_FALSE(loadMesh(dir.string()).ok());  // a folder
}

// ../shared/models: every file loads with about the README's face count.
struct SharedModel {
  const char* file;
  size_t minTriangles, maxTriangles;
};

TEST(Mesh, SharedModelsLoad) {
  INLAY_REQUIRE_SHARED();
  const fs::path models = fs::path(test::sharedDir()) / "models";
  const SharedModel expected[] = {{"spot.obj", 5856, 5856},
                                  {"teapot.obj", 6320, 6320},
                                  {"stanford-bunny.obj", 69451, 69451},
                                  {"suzanne.obj", 968, 968},
                                  {"cow.obj", 5804, 5804},
                                  {"igea.ply", 250000, 280000},
                                  {"spot_red_plastic.glb", 5856, 5856},
                                  {"teapot_gold.glb", 6320, 6320},
                                  {"suzanne_glass.glb", 968, 968},
                                  {"cow_glowing.glb", 5804, 5804}};
  for (const SharedModel& e : expected) {
    const fs::path p = models / e.file;
    if (!fs::exists(p)) continue;
    const auto t0 = std::chrono::steady_clock::now();
    auto m = loadMesh(p.string());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_TRUE(m.ok()) << e.file << ": " << m.error().message();
    EXPECT_GE(m->triangles.size(), e.minTriangles) << e.file;
    EXPECT_LE(m->triangles.size(), e.maxTriangles) << e.file;
    EXPECT_FALSE(m->bounds().isEmpty()) << e.file;
    EXPECT_GT(m->bounds().sizes().minCoeff(), 0.f) << e.file;
    EXPECT_LT(s, 10.0) << e.file;
    if (!m->normals.empty()) {
      EXPECT_EQ(m->normals.size(), m->positions.size()) << e.file;
    }
  }
}

const AssetMaterial& materialOfFirstTriangle(const TriangleMesh& m) {
  EXPECT_EQ(m.triangleMaterial.size(), m.triangles.size());
  return m.materials.at(m.triangleMaterial.at(0));
}

TEST(Mesh, SharedGltfMaterials) {
  INLAY_REQUIRE_SHARED();
  const fs::path models = fs::path(test::sharedDir()) / "models";
  auto load = [&](const char* f) { return loadMesh((models / f).string()); };
  auto spot = load("spot_red_plastic.glb");
  ASSERT_TRUE(spot.ok()) << spot.error().message();
  {
    const AssetMaterial& m = materialOfFirstTriangle(*spot);
    EXPECT_NEAR((m.baseColor - Vec3(0.7, 0.08, 0.05)).norm(), 0, 1e-5);
    EXPECT_NEAR(m.roughness, 0.35, 1e-5);
    EXPECT_NEAR(m.metallic, 0.0, 1e-9);
    EXPECT_EQ(m.emission, Vec3::Zero());
  }
  auto gold = load("teapot_gold.glb");
  ASSERT_TRUE(gold.ok()) << gold.error().message();
  {
    const AssetMaterial& m = materialOfFirstTriangle(*gold);
    EXPECT_NEAR(m.metallic, 1.0, 1e-9);
    EXPECT_NEAR((m.baseColor - Vec3(1.0, 0.77, 0.34)).norm(), 0, 1e-5);
    EXPECT_NEAR(m.roughness, 0.2, 1e-5);
  }
  auto glass = load("suzanne_glass.glb");
  ASSERT_TRUE(glass.ok()) << glass.error().message();
  {
    const AssetMaterial& m = materialOfFirstTriangle(*glass);
    EXPECT_NEAR(m.transmission, 1.0, 1e-9);
    EXPECT_NEAR(m.ior, 1.5, 1e-9);
    EXPECT_NEAR(m.roughness, 0.0, 1e-9);
  }
  auto cow = load("cow_glowing.glb");
  ASSERT_TRUE(cow.ok()) << cow.error().message();
  {
    const AssetMaterial& m = materialOfFirstTriangle(*cow);
    // Emissive colour x KHR_materials_emissive_strength (5).
    EXPECT_NEAR((m.emission - Vec3(5.0, 3.0, 1.0)).norm(), 0, 1e-5);
  }
}

TEST(Mesh, TruncatedSharedFilesAreErrors) {
  INLAY_REQUIRE_SHARED();
  const fs::path models = fs::path(test::sharedDir()) / "models";
  const auto dir = test::tempDir("mesh_trunc");
  for (const char* f : {"spot_red_plastic.glb", "igea.ply"}) {
    if (!fs::exists(models / f)) continue;
    const std::string bytes = readBytes(models / f);
    for (size_t cut : {bytes.size() / 2, size_t(100), bytes.size() - 7}) {
      const auto p = writeFile(dir, std::string("cut_") + f, bytes.substr(0, cut));
      auto m = loadMesh(p.string());
      EXPECT_FALSE(m.ok()) << f << " cut at " << cut;
    }
  }
  // A truncated OBJ is still a valid OBJ (fewer faces) unless a face is cut mid-index.
  if (fs::exists(models / "cow.obj")) {
    const std::string bytes = readBytes(models / "cow.obj");
    const auto p = writeFile(dir, "cow_cut.obj", bytes.substr(0, bytes.size() / 2));
    auto m = loadMesh(p.string());
    if (m.ok()) {
      EXPECT_LT(m->triangles.size(), 5804u);
    }
  }
}

// --- Polygon faces: concave ones must stay inside their outline --------------------------------

// Twice the signed area of a polygon in the xy plane.
double doubleArea2d(const std::vector<Eigen::Vector2d>& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i)
    a += p[i].x() * p[(i + 1) % p.size()].y() - p[(i + 1) % p.size()].x() * p[i].y();
  return a;
}

// Even-odd point-in-polygon test.
bool insidePolygon(const Eigen::Vector2d& q, const std::vector<Eigen::Vector2d>& p) {
  bool in = false;
  for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
    if ((p[i].y() > q.y()) != (p[j].y() > q.y()) &&
        q.x() < (p[j].x() - p[i].x()) * (q.y() - p[i].y()) / (p[j].y() - p[i].y()) + p[i].x())
      in = !in;
  return in;
}

// The triangulation of a planar counter-clockwise polygon (given in 2D, placed in 3D on a tilted
// plane so the projection step is exercised): n - 2 triangles, all wound like the polygon, whose
// areas add up to the polygon's and whose centroids (and edge midpoints pulled inward) lie inside.
void expectTriangulates(const std::vector<Eigen::Vector2d>& poly) {
  const Eigen::Vector3d origin(0.3, -1.0, 2.0);
  const Eigen::Vector3d u = Eigen::Vector3d(1, 0.5, 0.2).normalized();
  const Eigen::Vector3d v = u.cross(Eigen::Vector3d(0.1, 0.2, 1)).normalized().cross(u).normalized();
  std::vector<Vec3f> corners;
  corners.reserve(poly.size());
  for (const auto& q : poly) corners.push_back((origin + q.x() * u + q.y() * v).cast<float>());
  const auto tris = triangulatePolygon(corners);
  ASSERT_EQ(tris.size(), poly.size() - 2);
  double sum = 0;
  for (const auto& t : tris) {
    for (uint32_t i : t) ASSERT_LT(i, poly.size());
    const std::vector<Eigen::Vector2d> tri = {poly[t[0]], poly[t[1]], poly[t[2]]};
    const double a = doubleArea2d(tri);
    EXPECT_GT(a, 0) << "a triangle wound against the polygon (or flat)";
    sum += a;
    const Eigen::Vector2d c = (tri[0] + tri[1] + tri[2]) / 3.0;
    EXPECT_TRUE(insidePolygon(c, poly)) << "triangle centroid (" << c.transpose() << ") outside";
  }
  EXPECT_NEAR(sum, doubleArea2d(poly), 1e-4 * std::abs(doubleArea2d(poly)));
}

TEST(MeshPolygon, ConcaveLShapedFace) {
  // Starts at the reflex corner's neighbour, where a fan from corner 0 crosses outside.
  expectTriangulates({{2, 1}, {1, 1}, {1, 3}, {0, 3}, {0, 0}, {2, 0}});
  expectTriangulates({{1, 1}, {1, 3}, {0, 3}, {0, 0}, {2, 0}, {2, 1}});
}

TEST(MeshPolygon, ConcaveUShapedFace) {
  expectTriangulates({{3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}});
  // The same U clockwise: reversed input, still inside and area preserved (checked reversed).
  std::vector<Eigen::Vector2d> cw = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 2}, {3, 2}, {3, 0}};
  const std::vector<Vec3f> corners = [&] {
    std::vector<Vec3f> c;
    c.reserve(cw.size());
    for (const auto& q : cw) c.emplace_back(float(q.x()), 0.f, float(q.y()));  // on the floor
    return c;
  }();
  const auto tris = triangulatePolygon(corners);
  ASSERT_EQ(tris.size(), 6u);
  double sum = 0;
  for (const auto& t : tris) {
    const double a = -doubleArea2d({cw[t[0]], cw[t[1]], cw[t[2]]});  // clockwise: negative
    EXPECT_GT(a, 0);
    sum += a;
    EXPECT_TRUE(insidePolygon((cw[t[0]] + cw[t[1]] + cw[t[2]]) / 3.0, cw));
  }
  EXPECT_NEAR(sum, 2 * 5.0, 1e-6);  // twice the U's area (3 x 2 less the 1 x 1 notch)
}

TEST(MeshPolygon, StarAndCombFaces) {
  // A 10-corner star and a comb with many reflex corners: a chair's back, a shelf's side.
  std::vector<Eigen::Vector2d> star;
  for (int i = 0; i < 10; ++i) {
    const double r = i % 2 ? 0.4 : 1.0, a = 2 * M_PI * i / 10;
    star.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  expectTriangulates(star);
  // Five teeth of width 1 standing on a bar 1 high, gaps between them down to the bar.
  std::vector<Eigen::Vector2d> comb = {{0, 0}, {9, 0}};
  for (int k = 4; k >= 0; --k) {
    comb.emplace_back(2 * k + 1, 3);
    comb.emplace_back(2 * k, 3);
    if (k > 0) {
      comb.emplace_back(2 * k, 1);
      comb.emplace_back(2 * k - 1, 1);
    }
  }
  expectTriangulates(comb);
}

TEST(MeshPolygon, DegenerateFacesGiveTheirTrianglesWithoutCrashing) {
  // Collinear corners: no area, still n - 2 triangles with valid indices.
  const std::vector<Vec3f> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  auto tris = triangulatePolygon(line);
  ASSERT_EQ(tris.size(), 3u);
  for (const auto& t : tris)
    for (uint32_t i : t) EXPECT_LT(i, line.size());
  // Repeated corners and a self-intersecting bow tie.
  EXPECT_EQ(triangulatePolygon({{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}}).size(), 2u);
  EXPECT_EQ(triangulatePolygon({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}).size(), 2u);
  EXPECT_EQ(triangulatePolygon({{0, 0, 0}, {1, 0, 0}}).size(), 0u);

  // In an OBJ file: the collinear face loads beside a real one; the file as a whole is fine.
  const auto dir = test::tempDir("obj_degenerate");
  const auto p = writeFile(dir, "flat.obj",
                           "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nv 0 1 0\n"
                           "f 1 2 3 4\nf 1 2 5\n");
  auto m = loadMesh(p.string());
  ASSERT_TRUE(m.ok()) << m.error().message();
  EXPECT_EQ(m->triangles.size(), 3u);
}

TEST(MeshPolygon, ObjConcaveFaceStaysInsideItsOutline) {
  // An L-shaped table top as one OBJ face (vertical normal, y up): its triangles cover exactly
  // the L; the old fan from corner 1 covered the notch.
  const auto dir = test::tempDir("obj_concave");
  const auto p = writeFile(dir, "l.obj",
                           "v 2 0 1\nv 1 0 1\nv 1 0 3\nv 0 0 3\nv 0 0 0\nv 2 0 0\n"
                           "vt 0 0\nvn 0 1 0\nf 1/1/1 2/1/1 3/1/1 4/1/1 5/1/1 6/1/1\n");
  auto m = loadMesh(p.string());
  ASSERT_TRUE(m.ok()) << m.error().message();
  ASSERT_EQ(m->triangles.size(), 4u);
  double area = 0;
  for (const auto& t : m->triangles) {
    const Vec3f a = m->positions[t[0]], b = m->positions[t[1]], c = m->positions[t[2]];
    area += 0.5 * double((b - a).cross(c - a).norm());
    const Vec3f centre = (a + b + c) / 3.f;
    EXPECT_FALSE(centre.x() > 1 && centre.z() > 1) << "a triangle in the notch of the L";
  }
  EXPECT_NEAR(area, 4.0, 1e-5);
}

// --- FBX, COLLADA and 3DS through Assimp --------------------------------------------------------

TEST(MeshAssimp, FbxColladaAnd3dsLoadWithTheirUnits) {
  // A box 0.4 x 1.8 x 0.6 (y up) written as OBJ, converted by Assimp's own exporters.
  const auto dir = test::tempDir("mesh_assimp");
  std::string obj;
  for (int i = 0; i < 8; ++i)
    obj += "v " + std::to_string(i & 1 ? 0.4 : 0.0) + " " + std::to_string(i & 2 ? 1.8 : 0.0) + " " +
           std::to_string(i & 4 ? 0.6 : 0.0) + "\n";
  obj += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  const auto src = writeFile(dir, "box.obj", obj);
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(src.string(), 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  Assimp::Exporter exporter;
  struct Case {
    const char* formatId;
    const char* file;
    double metresPerUnit;  // what loadMesh must report (0: unknown)
  };
  for (const Case& c : {Case{"collada", "box.dae", 1.0}, Case{"3ds", "box.3ds", 0.0}}) {
    const fs::path out = dir / c.file;
    if (exporter.Export(scene, c.formatId, out.string()) != AI_SUCCESS) {
      ADD_FAILURE() << c.formatId << ": Assimp cannot write it here: " << exporter.GetErrorString();
      continue;
    }
    MeshFileInfo info;
    auto m = loadMesh(out.string(), {}, &info);
    ASSERT_TRUE(m.ok()) << c.file << ": " << m.error().message();
    EXPECT_EQ(m->triangles.size(), 12u) << c.file;
    // The height is up in y, 1.8 units (metres for COLLADA, which states its unit).
    EXPECT_NEAR(m->bounds().sizes().y(), 1.8f, 1e-4f)
        << c.file << " " << m->bounds().sizes().transpose();
    EXPECT_EQ(info.metresPerUnit, c.metresPerUnit) << c.file;
    EXPECT_EQ(info.format, std::string(c.file).substr(4));
  }
  // FBX (ASCII: Assimp 5.2 cannot read back the binary FBX it writes). Its global settings say
  // the unit (UnitScaleFactor: centimetres per unit) and the up axis; set them as a file from
  // another tool would.
  ASSERT_EQ(exporter.Export(scene, "fbxa", (dir / "box.fbx").string()), AI_SUCCESS)
      << exporter.GetErrorString();
  const std::string fbx = readBytes(dir / "box.fbx");
  auto withSetting = [](std::string text, const std::string& name, const std::string& value) {
    const std::string key = "P: \"" + name + "\",";
    const size_t at = text.find(key);
    if (at == std::string::npos) return std::string();
    const size_t end = text.find('\n', at);
    const size_t comma = text.rfind(',', end);
    return text.replace(comma + 1, end - comma - 1, " " + value);
  };
  struct FbxCase {
    const char* unitScale;  // centimetres per unit
    const char* upAxis;
    double metresPerUnit;
    Eigen::Vector3f size;  // after loading, in file units, y up
  };
  for (const FbxCase& c :
       {FbxCase{"1", "1", 0.01, {0.4f, 1.8f, 0.6f}}, FbxCase{"100", "1", 1.0, {0.4f, 1.8f, 0.6f}},
        FbxCase{"2.54", "2", 0.0254, {0.4f, 0.6f, 1.8f}}}) {
    std::string text = withSetting(withSetting(fbx, "UnitScaleFactor", c.unitScale), "UpAxis", c.upAxis);
    ASSERT_FALSE(text.empty()) << "the exported FBX has no UnitScaleFactor or UpAxis setting";
    const fs::path p = writeFile(dir, std::string("box_") + c.upAxis + ".fbx", text);
    MeshFileInfo info;
    auto m = loadMesh(p.string(), {}, &info);
    ASSERT_TRUE(m.ok()) << m.error().message();
    EXPECT_EQ(m->triangles.size(), 12u);
    EXPECT_NEAR(info.metresPerUnit, c.metresPerUnit, 1e-7) << c.unitScale;  // a float in the file
    EXPECT_LT((m->bounds().sizes() - c.size).norm(), 1e-4f)
        << c.unitScale << " up " << c.upAxis << ": " << m->bounds().sizes().transpose();
    EXPECT_EQ(info.format, "fbx");
  }
  // Refusals name the file and the reason.
  const auto junk = writeFile(dir, "junk.fbx", "this is not an FBX file at all\n");
  auto bad = loadMesh(junk.string());
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message().find("junk.fbx"), std::string::npos) << bad.error().message();
  const auto empty = writeFile(dir, "empty.dae", "");
  bad = loadMesh(empty.string());
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message().find("empty"), std::string::npos) << bad.error().message();
}

TEST(MeshAssimp, GltfIsInMetres) {
  INLAY_REQUIRE_SHARED();
  const fs::path p = fs::path(test::sharedDir()) / "models" / "spot_red_plastic.glb";
  if (!fs::exists(p)) GTEST_SKIP() << p << " is missing";
  MeshFileInfo info;
  auto m = loadMesh(p.string(), {}, &info);
  ASSERT_TRUE(m.ok()) << m.error().message();
  EXPECT_EQ(info.metresPerUnit, 1.0);
  EXPECT_EQ(info.format, "gltf");
  MeshFileInfo objInfo;
  ASSERT_TRUE(loadMesh((p.parent_path() / "spot.obj").string(), {}, &objInfo).ok());
  EXPECT_EQ(objInfo.metresPerUnit, 0.0);  // OBJ does not say
}

}  // namespace
}  // namespace inlay
