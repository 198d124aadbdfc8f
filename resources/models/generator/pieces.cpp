// The library's pieces (see pieces.h). Each function below is one piece: its parts as closed
// shapes, placed in metres, each part with its material.
#include "pieces.h"

#include "shapes.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <cmath>
#include <map>
#include <stdexcept>

namespace inlay::library {

namespace {

using V2 = Eigen::Vector2f;
constexpr float kDeg = 3.14159265358979f / 180.f;

// A material in glTF metallic-roughness terms (base colour linear; emission = colour x strength).
AssetMaterial material(const std::string& name, const Vec3& linearRgb, double roughness,
                       double metallic = 0, const Vec3& emission = Vec3::Zero()) {
  AssetMaterial m;
  m.name = name;
  m.baseColor = linearRgb;
  m.roughness = roughness;
  m.metallic = metallic;
  m.emission = emission;
  return m;
}

// The shared palette.
AssetMaterial oak() { return material("oak", {0.42, 0.26, 0.13}, 0.55); }
AssetMaterial walnut() { return material("walnut", {0.16, 0.085, 0.045}, 0.45); }
AssetMaterial blackMetal() { return material("black_metal", {0.04, 0.04, 0.04}, 0.35, 1.0); }
AssetMaterial brass() { return material("brass", {0.91, 0.72, 0.40}, 0.3, 1.0); }
// A warm shade lit from inside: radiance 1.5 in red (what shows as white at exposure 0 is 1),
// so the shade reads warm rather than clipped white, and lights the room around it.
AssetMaterial glowingShade() {
  return material("lamp_shade", {0.9, 0.85, 0.75}, 0.9, 0, Vec3(1.5, 1.15, 0.75));
}

Affine at(float x, float y, float z) { return Affine(Eigen::Translation3f(x, y, z)); }
Affine rotX(float deg) { return Affine(Eigen::AngleAxisf(deg * kDeg, Vec3f::UnitX())); }

// Collects a piece's parts: each is checked to be closed and outward-wound before it joins.
class PieceBuilder {
 public:
  PieceBuilder(std::string name, std::string title, std::string category, std::string note,
               const Vec3f& nominal) {
    piece_.name = std::move(name), piece_.title = std::move(title),
    piece_.category = std::move(category);
    piece_.materialNote = std::move(note), piece_.nominalSizeM = nominal;
  }
  // The material's index (added on first use, by name).
  uint32_t use(const AssetMaterial& m) {
    for (size_t i = 0; i < piece_.mesh.materials.size(); ++i)
      if (piece_.mesh.materials[i].name == m.name) return uint32_t(i);
    piece_.mesh.materials.push_back(m);
    return uint32_t(piece_.mesh.materials.size() - 1);
  }
  void add(const TriangleMesh& part, const AssetMaterial& m, const char* partName) {
    if (const std::string why = closedOutwardProblem(part); !why.empty())
      throw std::runtime_error(piece_.name + ": part '" + partName + "': " + why);
    const uint32_t mat = use(m);
    TriangleMesh& mesh = piece_.mesh;  // appended by hand: TriangleMesh::append adds "default" materials
    const uint32_t offset = uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
    mesh.normals.insert(mesh.normals.end(), part.normals.begin(), part.normals.end());
    mesh.uvs.insert(mesh.uvs.end(), part.uvs.begin(), part.uvs.end());
    for (const auto& t : part.triangles)
      mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    mesh.triangleMaterial.resize(mesh.triangles.size(), mat);
  }
  Piece finish(float thumbnailYawDeg = 30) {
    piece_.thumbnailYawDeg = thumbnailYawDeg;
    const Eigen::AlignedBox3f b = piece_.mesh.bounds();
    const Vec3f size(b.sizes().x(), b.sizes().z(), b.sizes().y());
    if ((size - piece_.nominalSizeM).cwiseAbs().maxCoeff() > 0.01f || std::abs(b.min().y()) > 1e-4f)
      throw std::runtime_error(piece_.name + ": built " + std::to_string(size.x()) + " x " +
                               std::to_string(size.y()) + " x " + std::to_string(size.z()) +
                               " m (min y " + std::to_string(b.min().y()) + "), not the nominal size");
    return std::move(piece_);
  }

 private:
  Piece piece_;
};

// A round leg from `bottom` up to `top` whose ends stay level (a sheared, not a rotated, rod):
// a leaning leg stands flat on the floor.
TriangleMesh leaningRod(const Vec3f& bottom, const Vec3f& top, float rBottom, float rTop,
                        int sides = 12) {
  const float height = top.y() - bottom.y();
  Affine shear = Affine::Identity();
  shear.linear().col(1) = Vec3f((top.x() - bottom.x()) / height, 1.f, (top.z() - bottom.z()) / height);
  return transformed(rod(Vec3f::Zero(), Vec3f(0, height, 0), rBottom, rTop, sides),
                     at(bottom.x(), bottom.y(), bottom.z()) * shear);
}

TriangleMesh box(float w, float h, float d, float radius, const Affine& where, int segments = 2) {
  return transformed(roundedBox(Vec3f(w, h, d), radius, segments), where);
}

Piece chair() {
  PieceBuilder b("chair", "Chair", "seating", "oak frame, blue-grey fabric seat pad",
                 {0.46f, 0.49f, 0.88f});
  const AssetMaterial fabric = material("fabric_blue_grey", {0.16, 0.20, 0.27}, 0.9);
  b.add(box(0.46f, 0.035f, 0.44f, 0.01f, at(0, 0.4325f, 0.02f)), oak(), "seat");
  b.add(box(0.42f, 0.05f, 0.40f, 0.02f, at(0, 0.47f, 0.03f), 3), fabric, "seat pad");
  for (float x : {-0.195f, 0.195f}) {
    b.add(rod({x, 0, 0.19f}, {x, 0.42f, 0.19f}, 0.016f, 0.02f), oak(), "front leg");
    // The back legs lean back 2.6 degrees and carry the back rails.
    b.add(leaningRod({x, 0, -0.19f}, {x, 0.88f, -0.23f}, 0.016f, 0.02f), oak(), "back leg");
    b.add(rod({x, 0.15f, 0.19f}, {x, 0.15f, -0.197f}, 0.01f, 0.01f), oak(), "stretcher");
  }
  auto legZ = [](float y) { return -0.19f - 0.04f * y / 0.88f; };
  b.add(box(0.40f, 0.10f, 0.025f, 0.008f, at(0, 0.80f, legZ(0.80f)) * rotX(-2.6f)), oak(), "top rail");
  b.add(box(0.40f, 0.045f, 0.022f, 0.007f, at(0, 0.58f, legZ(0.58f)) * rotX(-2.6f)), oak(),
        "lower rail");
  for (float x : {-0.1f, 0.f, 0.1f})
    b.add(rod({x, 0.59f, legZ(0.59f)}, {x, 0.77f, legZ(0.77f)}, 0.009f, 0.009f, 10), oak(), "spindle");
  return b.finish();
}

// An armchair and a sofa share their build: legs, a base, arms, a back, seat and back cushions.
struct UpholsteredLayout {
  float width, depth, height, legHeight, armWidth;
  int seats;
};

void upholstered(PieceBuilder& b, const UpholsteredLayout& l, const AssetMaterial& fabric) {
  const float baseTop = l.legHeight + 0.20f;
  for (float x : {-1.f, 1.f})
    for (float z : {-1.f, 1.f})
      b.add(rod({x * (0.5f * l.width - 0.06f), 0, z * (0.5f * l.depth - 0.06f)},
                {x * (0.5f * l.width - 0.06f), l.legHeight + 0.02f, z * (0.5f * l.depth - 0.06f)},
                0.018f, 0.024f),
            walnut(), "leg");
  b.add(box(l.width, 0.20f, l.depth, 0.03f, at(0, l.legHeight + 0.10f, 0), 3), fabric, "base");
  const float armTop = l.legHeight + 0.52f;
  for (float x : {-1.f, 1.f})
    b.add(box(l.armWidth, armTop - l.legHeight, l.depth, 0.05f,
              at(x * 0.5f * (l.width - l.armWidth), 0.5f * (armTop + l.legHeight), 0), 3),
          fabric, "arm");
  const float backDepth = 0.18f;
  b.add(box(l.width - 2 * l.armWidth + 0.02f, l.height - l.legHeight, backDepth, 0.06f,
            at(0, 0.5f * (l.height + l.legHeight), -0.5f * (l.depth - backDepth)), 3),
        fabric, "back");
  const float inner = l.width - 2 * l.armWidth;
  const float cushionW = inner / float(l.seats) - 0.01f;
  const float seatDepth = l.depth - backDepth - 0.03f;
  for (int i = 0; i < l.seats; ++i) {
    const float x = -0.5f * inner + (float(i) + 0.5f) * inner / float(l.seats);
    b.add(box(cushionW, 0.15f, seatDepth, 0.05f,
              at(x, baseTop + 0.07f, 0.5f * l.depth - 0.5f * seatDepth - 0.005f), 3),
          fabric, "seat cushion");
    b.add(box(cushionW, 0.40f, 0.14f, 0.05f,
              at(x, baseTop + 0.14f + 0.19f, -0.5f * l.depth + backDepth + 0.05f) * rotX(-10.f), 3),
          fabric, "back cushion");
  }
}

Piece armchair() {
  PieceBuilder b("armchair", "Armchair", "seating", "mustard wool upholstery, walnut legs",
                 {0.80f, 0.82f, 0.85f});
  upholstered(b, {0.80f, 0.82f, 0.85f, 0.12f, 0.14f, 1},
              material("wool_mustard", {0.50, 0.30, 0.06}, 0.95));
  return b.finish(25);
}

Piece sofa() {
  PieceBuilder b("sofa", "Sofa", "seating", "grey linen upholstery, walnut legs", {2.00f, 0.90f, 0.84f});
  upholstered(b, {2.00f, 0.90f, 0.84f, 0.10f, 0.18f, 3},
              material("linen_grey", {0.30, 0.30, 0.29}, 0.95));
  return b.finish(20);
}

Piece coffeeTable() {
  PieceBuilder b("coffee_table", "Coffee table", "tables", "walnut top and shelf, black metal legs",
                 {1.10f, 0.60f, 0.42f});
  b.add(box(1.10f, 0.035f, 0.60f, 0.012f, at(0, 0.4025f, 0)), walnut(), "top");
  b.add(box(0.98f, 0.02f, 0.48f, 0.006f, at(0, 0.13f, 0)), walnut(), "shelf");
  for (float x : {-0.49f, 0.49f})
    for (float z : {-0.24f, 0.24f})
      b.add(rod({x, 0, z}, {x, 0.386f, z}, 0.014f, 0.016f), blackMetal(), "leg");
  return b.finish();
}

Piece diningTable() {
  PieceBuilder b("dining_table", "Dining table", "tables", "oiled oak", {1.60f, 0.90f, 0.75f});
  b.add(box(1.60f, 0.035f, 0.90f, 0.01f, at(0, 0.7325f, 0)), oak(), "top");
  for (float z : {-0.36f, 0.36f})
    b.add(box(1.38f, 0.08f, 0.022f, 0.004f, at(0, 0.675f, z)), oak(), "apron");
  for (float x : {-0.71f, 0.71f})
    b.add(box(0.022f, 0.08f, 0.66f, 0.004f, at(x, 0.675f, 0)), oak(), "apron");
  for (float x : {-0.72f, 0.72f})
    for (float z : {-0.37f, 0.37f})
      b.add(box(0.065f, 0.716f, 0.065f, 0.006f, at(x, 0.358f, z)), oak(), "leg");
  return b.finish();
}

Piece stool() {
  PieceBuilder b("stool", "Stool", "seating", "oak, brass foot ring", {0.36f, 0.36f, 0.65f});
  b.add(lathe({{0, 0.612f},
               {0.165f, 0.612f},
               {0.178f, 0.618f},
               {0.18f, 0.632f},
               {0.175f, 0.645f},
               {0.16f, 0.65f},
               {0, 0.65f}},
              48),
        oak(), "seat");
  const float bottomR = 0.165f, topR = 0.11f, ringY = 0.22f;
  for (int i = 0; i < 4; ++i) {
    const float a = (45.f + 90.f * float(i)) * kDeg;
    const Vec3f dir(std::cos(a), 0, std::sin(a));
    b.add(leaningRod(bottomR * dir, topR * dir + Vec3f(0, 0.615f, 0), 0.015f, 0.018f), oak(), "leg");
  }
  const float ringR = bottomR + (topR - bottomR) * ringY / 0.615f;
  b.add(transformed(torus(ringR, 0.009f, 48, 10), at(0, ringY, 0)), brass(), "foot ring");
  return b.finish(0);
}

// A lamp shade: a thin-walled frustum, open at both ends (so the bulb's light gets out).
TriangleMesh shade(float bottomR, float topR, float y0, float y1, float wall) {
  return lathe({{bottomR, y0}, {topR, y1}, {topR - wall, y1}, {bottomR - wall, y0}, {bottomR, y0}}, 48);
}

Piece floorLamp() {
  PieceBuilder b("floor_lamp", "Floor lamp", "lighting", "brass stand, glowing linen shade (emissive)",
                 {0.40f, 0.40f, 1.60f});
  b.add(lathe({{0, 0}, {0.14f, 0}, {0.145f, 0.008f}, {0.14f, 0.02f}, {0.05f, 0.03f}, {0, 0.03f}}, 48),
        brass(), "base");
  b.add(rod({0, 0.02f, 0}, {0, 1.32f, 0}, 0.011f, 0.011f), brass(), "pole");
  b.add(shade(0.20f, 0.16f, 1.25f, 1.60f, 0.004f), glowingShade(), "shade");
  return b.finish(0);
}

Piece tableLamp() {
  PieceBuilder b("table_lamp", "Table lamp", "lighting", "teal glazed ceramic, glowing shade (emissive)",
                 {0.30f, 0.30f, 0.50f});
  const AssetMaterial ceramic = material("ceramic_teal", {0.04, 0.22, 0.24}, 0.2);
  b.add(lathe({{0, 0},
               {0.06f, 0},
               {0.066f, 0.008f},
               {0.088f, 0.07f},
               {0.095f, 0.13f},
               {0.085f, 0.19f},
               {0.05f, 0.245f},
               {0.022f, 0.27f},
               {0.02f, 0.28f},
               {0, 0.28f}},
              40),
        ceramic, "base");
  b.add(rod({0, 0.275f, 0}, {0, 0.36f, 0}, 0.008f, 0.008f), brass(), "neck");
  b.add(shade(0.15f, 0.11f, 0.30f, 0.50f, 0.003f), glowingShade(), "shade");
  return b.finish(0);
}

Piece vase() {
  PieceBuilder b("vase", "Vase", "decor", "deep blue glazed ceramic", {0.18f, 0.18f, 0.36f});
  const std::vector<V2> outside = {{0, 0},          {0.05f, 0},      {0.056f, 0.006f}, {0.075f, 0.05f},
                                   {0.087f, 0.11f}, {0.09f, 0.16f},  {0.082f, 0.22f},  {0.065f, 0.27f},
                                   {0.046f, 0.31f}, {0.047f, 0.34f}, {0.055f, 0.36f}};
  std::vector<V2> profile = outside;
  // The inside: the outside walked back down, 6 mm in, to a floor 12 mm up.
  for (auto it = outside.rbegin(); it != outside.rend(); ++it)
    if (it->y() > 0.012f) profile.push_back({std::max(0.f, it->x() - 0.006f), it->y()});
  profile.push_back({0.f, 0.012f});
  b.add(lathe(profile, 48, 50.f), material("ceramic_blue", {0.02, 0.05, 0.20}, 0.15), "body");
  return b.finish(0);
}

// Deterministic pseudo-random numbers in [0, 1) (a fixed LCG: the same library on every
// platform, which std::uniform_real_distribution does not promise).
class Lcg {
 public:
  explicit Lcg(uint32_t seed) : s_(seed) {}
  float next() {
    s_ = s_ * 1664525u + 1013904223u;
    return float(s_ >> 8) / float(1u << 24);
  }

 private:
  uint32_t s_;
};

// A leaf from its stem's tip: an arching blade, pointed at both ends.
TriangleMesh leaf(const Vec3f& base, float yawDeg, float riseDeg, float length, float width) {
  std::vector<Vec3f> path, up;
  std::vector<float> halfWidth, halfThick;
  const int n = 10;
  const Vec3f out(std::cos(yawDeg * kDeg), 0, std::sin(yawDeg * kDeg));
  for (int i = 0; i <= n; ++i) {
    const float s = float(i) / float(n);
    const float angle = (riseDeg - 75.f * s) * kDeg;  // droops toward the tip
    const float horizontal = length * s,
                vertical = length * (std::sin(riseDeg * kDeg) * s - 0.55f * s * s);
    path.push_back(base + horizontal * std::cos(angle * 0.3f) * out + Vec3f(0, vertical, 0));
    up.push_back(Vec3f::UnitY());
    const float w = 0.5f * width * std::pow(std::sin(3.14159265f * s), 0.7f);
    halfWidth.push_back(w);
    halfThick.push_back(i == 0 || i == n ? 0.f : 0.0025f);
  }
  return sweep(path, up, halfWidth, halfThick, 8);
}

Piece pottedPlant() {
  PieceBuilder b("potted_plant", "Potted plant", "decor", "terracotta pot, green leaves",
                 {0.74f, 0.73f, 0.86f});
  const AssetMaterial terracotta = material("terracotta", {0.45, 0.16, 0.08}, 0.85);
  b.add(lathe({{0, 0},
               {0.11f, 0},
               {0.15f, 0.27f},
               {0.165f, 0.28f},
               {0.165f, 0.31f},
               {0.15f, 0.31f},
               {0.142f, 0.28f},
               {0.104f, 0.012f},
               {0, 0.012f}},
              40, 30.f),
        terracotta, "pot");
  b.add(lathe({{0, 0.25f}, {0.142f, 0.25f}, {0.142f, 0.27f}, {0, 0.275f}}, 40),
        material("soil", {0.05, 0.035, 0.025}, 1.0), "soil");
  const AssetMaterial leafGreen = material("leaf", {0.05, 0.20, 0.04}, 0.5);
  const AssetMaterial stemGreen = material("stem", {0.10, 0.18, 0.05}, 0.7);
  Lcg rng(17);
  const int leaves = 14;
  for (int i = 0; i < leaves; ++i) {
    const float yaw = 360.f * (float(i) + 0.4f * rng.next()) / float(leaves);
    const float tipHeight = 0.50f + 0.30f * rng.next();
    const float lean = 0.03f + 0.05f * rng.next();
    const Vec3f foot(0.02f * std::cos(yaw * kDeg), 0.27f, 0.02f * std::sin(yaw * kDeg));
    const Vec3f tip(lean * std::cos(yaw * kDeg), tipHeight, lean * std::sin(yaw * kDeg));
    b.add(rod(foot, tip, 0.005f, 0.004f, 8), stemGreen, "stem");
    b.add(
        leaf(tip, yaw, 40.f + 25.f * rng.next(), 0.26f + 0.08f * rng.next(), 0.11f + 0.04f * rng.next()),
        leafGreen, "leaf");
  }
  return b.finish(0);
}

void shelfOfBooks(PieceBuilder& b, Lcg& rng, float y, float width,
                  const std::vector<AssetMaterial>& covers) {
  float x = -0.5f * width + 0.01f;
  while (true) {
    const float w = 0.022f + 0.025f * rng.next();
    if (x + w > 0.5f * width - 0.01f) break;
    if (rng.next() < 0.12f) {  // a gap
      x += 0.04f + 0.04f * rng.next();
      continue;
    }
    const float h = 0.18f + 0.10f * rng.next(), d = 0.16f + 0.06f * rng.next();
    const AssetMaterial& cover = covers[size_t(rng.next() * float(covers.size())) % covers.size()];
    b.add(box(w, h, d, 0.002f, at(x + 0.5f * w, y + 0.5f * h, 0.13f - 0.5f * d), 1), cover, "book");
    x += w + 0.002f;
  }
}

Piece bookshelf() {
  PieceBuilder b("bookshelf", "Bookshelf", "storage", "white painted wood, books in five colours",
                 {0.80f, 0.30f, 1.80f});
  const AssetMaterial paint = material("white_paint", {0.78, 0.77, 0.74}, 0.6);
  for (float x : {-0.39f, 0.39f})
    b.add(box(0.02f, 1.80f, 0.30f, 0.003f, at(x, 0.90f, 0)), paint, "side");
  b.add(box(0.76f, 0.02f, 0.30f, 0.003f, at(0, 1.79f, 0)), paint, "top");
  b.add(box(0.76f, 0.06f, 0.02f, 0.003f, at(0, 0.03f, 0.13f)), paint, "plinth");
  const std::vector<float> shelves = {0.07f, 0.42f, 0.77f, 1.12f, 1.45f};
  for (float y : shelves) b.add(box(0.76f, 0.02f, 0.28f, 0.003f, at(0, y, 0.005f)), paint, "shelf");
  b.add(box(0.76f, 1.76f, 0.008f, 0.002f, at(0, 0.90f, -0.146f)), paint, "back");
  const std::vector<AssetMaterial> covers = {
      material("book_red", {0.40, 0.05, 0.04}, 0.6), material("book_navy", {0.03, 0.05, 0.16}, 0.6),
      material("book_ochre", {0.55, 0.36, 0.08}, 0.6), material("book_green", {0.06, 0.18, 0.10}, 0.6),
      material("book_cream", {0.70, 0.64, 0.52}, 0.6)};
  Lcg rng(5);
  for (size_t i = 0; i + 1 < shelves.size(); ++i)
    if (i != 2) shelfOfBooks(b, rng, shelves[i] + 0.01f, 0.76f, covers);
  return b.finish();
}

Piece rug() {
  PieceBuilder b("rug", "Rug", "textiles", "terracotta wool field, cream border",
                 {2.00f, 1.40f, 0.012f});
  const AssetMaterial field = material("wool_field", {0.35, 0.09, 0.06}, 1.0);
  const AssetMaterial border = material("wool_border", {0.62, 0.56, 0.45}, 1.0);
  b.add(box(1.80f, 0.012f, 1.20f, 0.003f, at(0, 0.006f, 0), 1), field, "field");
  for (float z : {-0.65f, 0.65f})
    b.add(box(2.00f, 0.012f, 0.10f, 0.004f, at(0, 0.006f, z), 1), border, "border");
  for (float x : {-0.95f, 0.95f})
    b.add(box(0.10f, 0.012f, 1.20f, 0.004f, at(x, 0.006f, 0), 1), border, "border");
  return b.finish(0);
}

}  // namespace

std::string closedOutwardProblem(const TriangleMesh& part) {
  using Mesh = OpenMesh::TriMesh_ArrayKernelT<>;
  Mesh mesh;
  std::map<std::array<long, 3>, Mesh::VertexHandle> welded;
  std::vector<Mesh::VertexHandle> handle(part.positions.size());
  for (size_t i = 0; i < part.positions.size(); ++i) {
    const Vec3f& p = part.positions[i];
    if (!p.allFinite()) return "vertex " + std::to_string(i) + " is not finite";
    const std::array<long, 3> key = {std::lround(p.x() * 1e6f), std::lround(p.y() * 1e6f),
                                     std::lround(p.z() * 1e6f)};
    auto it = welded.find(key);
    if (it == welded.end())
      it = welded.emplace(key, mesh.add_vertex(Mesh::Point(p.x(), p.y(), p.z()))).first;
    handle[i] = it->second;
  }
  // add_face explains a refusal on stderr; the refusal is reported below instead.
  struct Quiet {
    Quiet() { omerr().disable(); }
    ~Quiet() { omerr().enable(); }
  } quiet;
  double volume = 0;
  for (size_t t = 0; t < part.triangles.size(); ++t) {
    const auto& tri = part.triangles[t];
    const Mesh::VertexHandle a = handle[tri[0]], b = handle[tri[1]], c = handle[tri[2]];
    if (a == b || b == c || a == c) return "triangle " + std::to_string(t) + " collapses when welded";
    if (!mesh.add_face(a, b, c).is_valid())
      return "triangle " + std::to_string(t) + " makes a non-manifold or inconsistently wound edge";
    const Vec3f p0 = part.positions[tri[0]], p1 = part.positions[tri[1]], p2 = part.positions[tri[2]];
    volume += double(p0.dot(p1.cross(p2))) / 6.0;
  }
  for (const auto he : mesh.halfedges())
    if (mesh.is_boundary(he)) return "not closed (an edge has one triangle)";
  if (!(volume > 0)) return "wound inward (signed volume " + std::to_string(volume) + " m^3)";
  return "";
}

std::vector<Piece> buildLibrary() {
  return {chair(),     armchair(),  sofa(), coffeeTable(), diningTable(), stool(),
          floorLamp(), tableLamp(), vase(), pottedPlant(), bookshelf(),   rug()};
}

}  // namespace inlay::library
