// Meshes: builtins, helpers, the importers on ../shared/models and on malformed files made here.
#include "inlay/modeling/mesh.h"

#include "test_support.h"

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
  const fs::path p = dir / name;
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
  return (m.positions[tri[1]] - m.positions[tri[0]])
      .cross(m.positions[tri[2]] - m.positions[tri[0]]);
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
                            c.positions[c.triangles[t][2]]) / 3.f;
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
  EXPECT_EQ(m->triangles.size(), 4u);  // 3 from the fan + 1
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
  if (!c.element.empty()) EXPECT_EQ(m.error().key, c.element) << m.error().message();
  EXPECT_NE(m.error().reason.find(c.reasonPart), std::string::npos) << m.error().message();
}

std::string plyHeader(const std::string& format, int vertices, int faces,
                      const std::string& indexType = "int") {
  return "ply\nformat " + format + " 1.0\ncomment test\nelement vertex " +
         std::to_string(vertices) + "\nproperty float x\nproperty float y\nproperty float z\n" +
         "element face " + std::to_string(faces) + "\nproperty list uchar " + indexType +
         " vertex_indices\nend_header\n";
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
        BadMesh{"nan_vertex", "n.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "line 2",
                "non-finite"},
        BadMesh{"inf_vertex", "i.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n", "line 3",
                "non-finite"},
        BadMesh{"overflow_vertex", "o.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n", "line 2",
                ""},
        BadMesh{"index_too_big", "b.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "line 4",
                "out of range"},
        BadMesh{"index_zero", "z.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "line 4",
                "index 0"},
        BadMesh{"negative_before_start", "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n",
                "line 4", "before the first"},
        BadMesh{"normal_index", "vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n",
                "line 5", "normal index 2 out of range"},
        BadMesh{"two_vertex_face", "t.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "line 3", "at least 3"},
        BadMesh{"garbage_index", "g.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", "line 4",
                "malformed"},
        BadMesh{"degenerate_only", "d.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", "",
                "zero area"},
        BadMesh{"empty_ply", "e.ply", "", "", "empty file"},
        BadMesh{"not_ply", "x.ply", "solid cube\nendsolid\n", "header", "not a PLY"},
        BadMesh{"ply_no_end", "h.ply", "ply\nformat ascii 1.0\nelement vertex 3\n", "header",
                "end_header"},
        BadMesh{"ply_ascii_short", "s.ply", plyHeader("ascii", 5, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                "", ""},
        BadMesh{"ply_binary_lies", "l.ply", plyHeader("binary_little_endian", 3, 2) + binaryTriangle(),
                "face 1", "unexpected end of data: the file ends here, but header line 8 claims 2 "
                          "'face' entries"},
        BadMesh{"ply_huge_count", "u.ply", plyHeader("binary_little_endian", 2000000000, 1) +
                                              binaryTriangle(),
                "header line 4",
                "more data than the file holds: 'vertex' claims 2000000000 entries, so the data "
                "after end_header needs at least 24000000000 bytes, but the file holds 49"},
        BadMesh{"ply_bad_index", "i.ply", plyHeader("ascii", 3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
                "face 0", "out of range"},
        BadMesh{"ply_negative_index", "n.ply",
                plyHeader("ascii", 3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "face 0",
                "out of range"},
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
    [](const ::testing::TestParamInfo<BadMesh>& info) { return std::string(info.param.name); });

TEST(Mesh, PlyAsciiAndBinaryAndTristrips) {
  const auto dir = test::tempDir("ply_ok");
  auto a = loadMesh(writeFile(dir, "a.ply", plyHeader("ascii", 4, 1) +
                                                "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
                        .string());
  ASSERT_TRUE(a.ok()) << a.error().message();
  EXPECT_EQ(a->triangles.size(), 2u);
  auto b = loadMesh(writeFile(dir, "b.ply", plyHeader("binary_little_endian", 3, 1) + binaryTriangle())
                        .string());
  ASSERT_TRUE(b.ok()) << b.error().message();
  EXPECT_EQ(b->triangles.size(), 1u);
  EXPECT_EQ(b->positions[1], Vec3f(1, 0, 0));
  // Big endian with normals and an extra element to skip.
  std::string be = "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\n"
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
  const SharedModel expected[] = {
      {"spot.obj", 5856, 5856},          {"teapot.obj", 6320, 6320},
      {"stanford-bunny.obj", 69451, 69451}, {"suzanne.obj", 968, 968},
      {"cow.obj", 5804, 5804},           {"igea.ply", 250000, 280000},
      {"spot_red_plastic.glb", 5856, 5856}, {"teapot_gold.glb", 6320, 6320},
      {"suzanne_glass.glb", 968, 968},   {"cow_glowing.glb", 5804, 5804}};
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
    if (!m->normals.empty()) EXPECT_EQ(m->normals.size(), m->positions.size()) << e.file;
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
    if (m.ok()) EXPECT_LT(m->triangles.size(), 5804u);
  }
}

}  // namespace
}  // namespace inlay
