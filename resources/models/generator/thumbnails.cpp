// Thumbnails through Inlay's renderer (see thumbnails.h).
#include "thumbnails.h"

#include "inlay/modeling/parallel.h"
#include "inlay/render/composite.h"
#include "inlay/render/path_tracer.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <tbb/blocked_range.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

namespace inlay::library {

namespace {

// A square of photo pixels [x0, x0 + side) x [y0, y0 + side).
struct Square {
  double x0 = 0, y0 = 0, side = 0;
};

// The photo-pixel box of the placed mesh's bounding box corners; false when a corner is behind
// the camera.
bool projectedBox(const Camera& camera, const TriangleMesh& mesh, const Mat4& worldFromObject,
                  Eigen::AlignedBox2d* box) {
  const Eigen::AlignedBox3f b = mesh.bounds();
  box->setEmpty();
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner = b.corner(Eigen::AlignedBox3f::CornerType(c)).cast<double>();
    const Vec4 w = worldFromObject * Vec4(corner.x(), corner.y(), corner.z(), 1.0);
    const auto px = camera.project(w.head<3>());
    if (!px) return false;
    box->extend(*px);
  }
  return true;
}

// The nearest floor point on the photo's middle column where the whole piece is in the photo
// (4 px margin); the farthest valid one when none fits.
Expected<Placement> nearestFittingPlacement(const PreparedScene& room, const TriangleMesh& mesh,
                                            double heightM, double yawDeg, Eigen::AlignedBox2d* box,
                                            Vec2* basePx) {
  const Camera& cam = room.camera;
  const double margin = 4;
  std::optional<Placement> last;
  Eigen::AlignedBox2d lastBox;
  Vec2 lastBase(0, 0);
  for (double y = cam.heightPx - 2; y > 0.5 * cam.heightPx; y -= 3) {
    const Vec2 base(0.5 * cam.widthPx, y);
    auto placed = placeObject(mesh, room.geometry, cam, base, heightM, yawDeg, "thumbnail");
    if (!placed) continue;
    Eigen::AlignedBox2d b;
    if (!projectedBox(cam, mesh, placed->worldFromObject, &b)) continue;
    last = *placed, lastBox = b, lastBase = base;
    if (b.min().x() >= margin && b.min().y() >= margin && b.max().x() <= cam.widthPx - margin &&
        b.max().y() <= cam.heightPx - margin)
      break;
  }
  if (!last) return Error{"", "thumbnail", "no floor point of the example photo holds the piece"};
  *box = lastBox, *basePx = lastBase;
  return *last;
}

Square squareAround(const Eigen::AlignedBox2d& box, int widthPx, int heightPx) {
  Square s;
  s.side = std::min<double>(
      {std::max(24.0, 1.15 * box.sizes().maxCoeff()), double(widthPx), double(heightPx)});
  const Vec2 c = box.center();
  s.x0 = std::clamp(c.x() - 0.5 * s.side, 0.0, widthPx - s.side);
  s.y0 = std::clamp(c.y() - 0.5 * s.side, 0.0, heightPx - s.side);
  return s;
}

// Bilinear sample of `image` at photo pixel position (x, y) (pixel centres at +0.5).
Vec3 bilinear(const ImageF& image, double x, double y) {
  x = std::clamp(x - 0.5, 0.0, image.width - 1.0), y = std::clamp(y - 0.5, 0.0, image.height - 1.0);
  const int x0 = int(x), y0 = int(y), x1 = std::min(x0 + 1, image.width - 1),
            y1 = std::min(y0 + 1, image.height - 1);
  const double fx = x - x0, fy = y - y0;
  return (1 - fy) * ((1 - fx) * image.rgb(x0, y0) + fx * image.rgb(x1, y0)) +
         fy * ((1 - fx) * image.rgb(x0, y1) + fx * image.rgb(x1, y1));
}

ImageF cropOf(const ImageF& image, int x0, int y0, int side) {
  ImageF out(side, side, image.channels);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      for (int c = 0; c < image.channels; ++c) out.at(x, y, c) = image.at(x0 + x, y0 + y, c);
  return out;
}

// Area-averaged resampling of a square image to `size` x `size`.
ImageF resampled(const ImageF& image, int size) {
  ImageF out(size, size, 3);
  const double scale = double(image.width) / size;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const int xa = int(x * scale), xb = std::max(xa + 1, int(std::ceil((x + 1) * scale)));
      const int ya = int(y * scale), yb = std::max(ya + 1, int(std::ceil((y + 1) * scale)));
      Vec3 sum = Vec3::Zero();
      int n = 0;
      for (int v = ya; v < std::min(yb, image.height); ++v)
        for (int u = xa; u < std::min(xb, image.width); ++u) sum += image.rgb(u, v), ++n;
      out.setRgb(x, y, sum / std::max(1, n));
    }
  return out;
}

}  // namespace

Expected<PreparedScene> prepareExampleRoom(std::vector<std::string>* warnings) {
  const std::string path = exampleScenePath();
  if (path.empty())
    return Error{"resources/example/scene.json", "", "the bundled example scene was not found"};
  auto loaded = loadSceneFile(path);
  if (!loaded) return loaded.error();
  loaded->doc.objects.clear();
  auto prepared = prepareScene(loaded->doc);
  if (!prepared) return prepared.error().inFile(path);
  if (warnings) {
    warnings->insert(warnings->end(), loaded->warnings.begin(), loaded->warnings.end());
    warnings->insert(warnings->end(), prepared->warnings.begin(), prepared->warnings.end());
  }
  return prepared;
}

Expected<ImageF> renderThumbnail(const PreparedScene& room, const TriangleMesh& mesh, double heightM,
                                 double yawDeg, const ThumbnailOptions& options, ThumbnailStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  Eigen::AlignedBox2d box;
  Vec2 basePx;
  auto placement = nearestFittingPlacement(room, mesh, heightM, yawDeg, &box, &basePx);
  if (!placement) return placement.error();
  const Camera& cam = room.camera;
  const Square sq = squareAround(box, cam.widthPx, cam.heightPx);
  const int k = std::clamp(int(std::ceil(options.sizePx / sq.side)), 1, std::max(1, options.maxUpscale));

  RenderScene scene = room.renderScene;
  InsertedObject piece;  // as the pipeline inserts a file with preset "asset"
  piece.meshObject = std::make_shared<const TriangleMesh>(mesh);
  piece.worldFromObject = placement->worldFromObject;
  MaterialKeys asset;
  asset.preset = "asset";
  setObjectMaterial(piece, asset);
  scene.objects = {piece};
  PathTracer tracer(scene);
  DifferentialBuffers buffers(cam.widthPx * k, cam.heightPx * k);
  const int x0 = int(std::floor(sq.x0 * k)), y0 = int(std::floor(sq.y0 * k));
  const int side = std::min({int(std::ceil(sq.side * k)), buffers.width - x0, buffers.height - y0});
  parallelFor(tbb::blocked_range<int>(y0, y0 + side, 4), [&](const tbb::blocked_range<int>& rows) {
    tracer.renderRect(buffers, x0, rows.begin(), x0 + side, rows.end(), 0, options.spp, options.seed);
  });

  ImageF photo(side, side, 3);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      photo.setRgb(x, y, bilinear(room.photo.linearRgb, (x0 + x + 0.5) / k, (y0 + y + 0.5) / k));
  ImageF composite = differentialComposite(photo, cropOf(buffers.meanWith(), x0, y0, side),
                                           cropOf(buffers.meanWithout(), x0, y0, side),
                                           cropOf(buffers.meanMask(), x0, y0, side));
  applyExposure(composite, room.doc.render.exposure);
  if (stats) {
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats->nonFiniteSamples = tracer.stats().nonFiniteSamples;
    stats->basePx = basePx;
  }
  return resampled(composite, options.sizePx);
}

ImageF contactSheet(const std::vector<ImageF>& thumbnails, const std::vector<std::string>& titles,
                    int columns, std::vector<std::string>* warnings) {
  INLAY_CHECK(!thumbnails.empty() && thumbnails.size() == titles.size() && columns > 0);
  const int tile = thumbnails.front().width, pad = 8, label = 22;
  const int rows = int((thumbnails.size() + size_t(columns) - 1) / size_t(columns));
  const int width = columns * (tile + pad) + pad, height = rows * (tile + label + pad) + pad;
  OIIO::ImageBuf sheet(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  const float background[3] = {0.9f, 0.9f, 0.9f};
  OIIO::ImageBufAlgo::fill(sheet, background);
  const std::string font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  const bool haveFont = std::filesystem::exists(font);
  if (!haveFont && warnings)
    warnings->push_back("contact sheet: " + font + " not found; titles left out");
  const float ink[3] = {0.02f, 0.02f, 0.02f};
  for (size_t i = 0; i < thumbnails.size(); ++i) {
    const int x = pad + int(i % size_t(columns)) * (tile + pad),
              y = pad + int(i / size_t(columns)) * (tile + label + pad);
    const ImageF& t = thumbnails[i];
    for (int v = 0; v < std::min(tile, t.height); ++v)
      for (int u = 0; u < std::min(tile, t.width); ++u) sheet.setpixel(x + u, y + v, t.pixel(u, v), 3);
    if (haveFont)
      OIIO::ImageBufAlgo::render_text(sheet, x + tile / 2, y + tile + 16, titles[i], 14, font, ink,
                                      OIIO::ImageBufAlgo::TextAlignX::Center);
  }
  ImageF out(width, height, 3);
  sheet.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, out.data.data());
  return out;
}

}  // namespace inlay::library
