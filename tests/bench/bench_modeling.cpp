// Extra geometry of a scene file, timed: every surface (extrusion, box, stairs) built `repeat`
// times (best time), every occluder matted once (grabCut and matting seconds, the alpha written
// as an 8-bit PGM) and asked whether it shows each top drawn without a thickness open below
// (slabFromMatte: the slab's thickness). Needs the scene's camera keys (focal_px and vanishing_points_px, as the
// harness's assisted mode writes them). One JSON object per line on stdout; bench_modeling.py
// turns them into CSV against the ground truth.
//
// usage: bench_modeling SCENE.json OUT_DIR [repeat]
#include "inlay/modeling/camera.h"
#include "inlay/modeling/geometry.h"
#include "inlay/modeling/image_io.h"
#include "inlay/modeling/occluder.h"
#include "inlay/modeling/scene_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <utility>
#include <vector>

using namespace inlay;
using json = nlohmann::json;

namespace {
double msSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}
// The process's CPU time (all threads), ms: with the machine shared by other jobs the wall time
// of one run swings several times over; the CPU time much less.
double cpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * double(ts.tv_sec) + 1e-6 * double(ts.tv_nsec);
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_modeling SCENE.json OUT_DIR [repeat]\n");
    return 2;
  }
  const std::string outDir = argv[2];
  const int repeat = argc > 3 ? std::max(1, std::atoi(argv[3])) : 20;
  auto loaded = loadSceneFile(argv[1]);
  if (!loaded) {
    std::fprintf(stderr, "%s\n", loaded.error().message().c_str());
    return 1;
  }
  const SceneDoc& doc = loaded->doc;
  auto photo = loadImage(doc.photoResolved);
  if (!photo) {
    std::fprintf(stderr, "%s\n", photo.error().message().c_str());
    return 1;
  }
  if (!doc.camera.vanishingPointsPx) {
    std::fprintf(stderr, "the scene needs camera.vanishing_points_px\n");
    return 1;
  }
  VanishingInput in;
  in.vanishingPointsPx = *doc.camera.vanishingPointsPx;
  in.focalPx = doc.camera.focalPx;
  in.principalPx = doc.camera.principalPx;
  in.widthPx = photo->linearRgb.width;
  in.heightPx = photo->linearRgb.height;
  in.heightM = doc.camera.heightM.value_or(1.6);
  auto camera = cameraFromVanishingPoints(in);
  if (!camera) {
    std::fprintf(stderr, "%s\n", camera.error().message().c_str());
    return 1;
  }
  std::optional<RoomBox> room;
  if (doc.layout.backWallPx) {
    auto box = roomFromBackWall(*camera, *doc.layout.backWallPx);
    if (box) room = *box;
  }
  // Extrusions built to the floor (no thickness_m), for the matte's slab evidence below.
  std::vector<std::pair<size_t, Extrusion>> solids;
  for (size_t i = 0; i < doc.surfaces.size(); ++i) {
    const SurfaceKeys& s = doc.surfaces[i];
    const std::string key = "surfaces[" + std::to_string(i) + "]";
    ExtrusionOptions eo;
    eo.thicknessM = s.thicknessM.value_or(0.0);
    double best = 1e300;
    Expected<Extrusion> ex = Error{"", key, "not built"};
    for (int r = 0; r < repeat; ++r) {
      const auto t = std::chrono::steady_clock::now();
      if (s.kind == "box") {
        ex = boxFromOutline(*camera, s.outlinePx, s.heightClickPx, key, eo);
      } else if (s.kind == "stairs" && !s.profilePx.empty()) {
        StairsProfileSpec sp;
        sp.profilePx = s.profilePx;
        sp.widthM = s.widthM;
        if (s.wall == "left") sp.wall = SurfaceKind::WallLeft;
        if (s.wall == "right") sp.wall = SurfaceKind::WallRight;
        if (s.wall == "back") sp.wall = SurfaceKind::WallBack;
        if (!room) {
          ex = Error{"", key, "stairs from a profile need layout.back_wall_px"};
        } else {
          ex = stairsFromProfile(*camera, *room, sp, key);
        }
      } else if (s.kind == "stairs") {
        StairsSpec st;
        st.basePx = s.basePx, st.steps = s.steps, st.riseM = s.riseM, st.runM = s.runM,
        st.widthM = s.widthM;
        const double sign = s.climbAxis[0] == '-' ? -1.0 : 1.0;
        st.climbWorld = s.climbAxis[1] == 'x' ? Vec3(sign, 0, 0) : Vec3(0, 0, sign);
        ex = stairsFromSpec(*camera, st, key);
      } else {
        ex = extrusionFromOutline(*camera, s.outlinePx, s.heightClickPx, key, eo);
      }
      best = std::min(best, msSince(t));
    }
    json line{{"what", "surface"}, {"index", i}, {"kind", s.kind}, {"ms", best}};
    if (!ex) {
      line["error"] = ex.error().message();
    } else {
      line["height_m"] = ex->heightM;
      json top = json::array(), floorPx = json::array();
      for (const Vec3& p : ex->topOutlineWorld) {
        top.push_back({p.x(), p.y(), p.z()});
        const auto px = camera->project(Vec3(p.x(), 0, p.z()));
        floorPx.push_back(px ? json{px->x(), px->y()} : json(nullptr));
      }
      line["top_world"] = top;  // Inlay's world: camera at (0, h, 0)
      line["floor_corners_px"] = floorPx;
      line["up_triangles"] = ex->upWorld.triangles.size();
      if (!s.thicknessM && s.kind != "stairs") solids.emplace_back(i, *ex);
    }
    std::cout << line.dump() << std::endl;
  }
  {
    // A round table top of 256 outline points 3 m in front of the camera: the extrusion's cost
    // with a long outline (CGAL validity, triangulation, closed-solid checks).
    const Vec3 fwd = camera->worldFromCamera * Vec3(0, 0, -1);
    const Vec3 centre = Vec3(0, 0.75, 0) + 3.0 * Vec3(fwd.x(), 0, fwd.z()).normalized();
    std::vector<Vec2> outline;
    for (int k = 0; k < 256; ++k) {
      const double a = 2 * M_PI * k / 256;
      const auto px = camera->project(centre + 0.5 * Vec3(std::cos(a), 0, std::sin(a)));
      if (px) outline.push_back(*px);
    }
    // On the floor below outline point 0 (angle 0).
    const auto click = camera->project(centre + Vec3(0.5, -0.75, 0));
    double best = 1e300;
    Expected<Extrusion> ex = Error{"", "round", "not built"};
    for (int r = 0; r < repeat && click; ++r) {
      const auto t = std::chrono::steady_clock::now();
      ex = extrusionFromOutline(*camera, outline, *click, "round");
      best = std::min(best, msSince(t));
    }
    json line{{"what", "surface"}, {"index", -1}, {"kind", "round_256"}, {"ms", best}};
    if (ex) line["height_m"] = ex->heightM, line["up_triangles"] = ex->upWorld.triangles.size();
    else line["error"] = ex.error().message();
    std::cout << line.dump() << std::endl;
  }
  for (size_t i = 0; i < doc.occluders.size(); ++i) {
    const std::string key = "occluders[" + std::to_string(i) + "]";
    const auto t = std::chrono::steady_clock::now();
    const double cpu0 = cpuMs();
    auto m = matteFromScribbles(photo->linearRgb, doc.occluders[i].foregroundScribblesPx,
                                doc.occluders[i].backgroundScribblesPx, key);
    const double ms = msSince(t);
    json line{{"what", "occluder"}, {"index", i}, {"ms", ms}, {"cpu_ms", cpuMs() - cpu0}};
    if (!m) {
      line["error"] = m.error().message();
      std::cout << line.dump() << std::endl;
      continue;
    }
    line["segment_ms"] = 1e3 * m->segmentSeconds;
    line["matte_ms"] = 1e3 * m->matteSeconds;
    line["lowest_px"] = {m->lowestPx.x(), m->lowestPx.y()};
    line["box_px"] = m->boxPx;
    auto card = occluderCard(*camera, *m, int(i), key);
    if (card) {
      json corners = json::array();
      for (const auto& p : card->meshWorld.positions) corners.push_back({p.x(), p.y(), p.z()});
      line["card_world"] = corners;
    } else {
      line["card_error"] = card.error().message();
    }
    const std::string pgm = outDir + "/occluder_" + std::to_string(i) + "_alpha.pgm";
    std::ofstream f(pgm, std::ios::binary);
    f << "P5\n" << m->alphaPx.width << " " << m->alphaPx.height << "\n255\n";
    for (float a : m->alphaPx.data) f.put(char(uint8_t(std::lround(255.f * std::clamp(a, 0.f, 1.f)))));
    line["alpha_pgm"] = pgm;
    std::cout << line.dump() << std::endl;
    for (const auto& [index, solid] : solids) {
      // What this matte says about each top drawn without a thickness (slabFromMatte).
      const auto t0 = std::chrono::steady_clock::now();
      const SlabEvidence e = slabFromMatte(*camera, solid, m->alphaPx);
      std::cout << json{{"what", "slab"},
                        {"index", index},
                        {"occluder", i},
                        {"ms", msSince(t0)},
                        {"covered", e.coveredSamples},
                        {"open_points", e.openSamples},
                        {"open", e.open},
                        {"thickness_m", e.thicknessM}}
                       .dump()
                << std::endl;
    }
  }
  return 0;
}
