#include "inlay/engine/pipeline.h"

#include "inlay/engine/data_dirs.h"

#include "inlay/modeling/estimate_camera.h"
#include "inlay/modeling/image_resample.h"
#include "inlay/modeling/occluder.h"
#include "inlay/modeling/photo_codes.h"
#include "inlay/lighting/shaft.h"
#include "inlay/lighting/sun_ratio.h"
#include "inlay/render/composite.h"
#include "inlay/render/gltf_export.h"
#include "inlay/render/grain.h"
#include "inlay/render/path_tracer.h"
#include "inlay/render/scene.h"
#include "inlay/modeling/cpu_time.h"
#include "inlay/modeling/fingerprint.h"
#include "inlay/modeling/parallel.h"
#include "inlay/modeling/subdivide.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <span>

namespace inlay {

namespace {

// correctEstimate names its keys "correction.*"; the user lines come from the file's
// camera.vanishing_lines_px, so an error about them names that key.
Error inFileKeys(Error e) {
  const std::string lines = "correction.vanishing_lines_px";
  if (e.key.rfind(lines, 0) != 0) return e;
  std::string rest = e.key.substr(lines.size());  // "[z]": the file writes the axis as ".z"
  if (rest.size() >= 3 && rest[0] == '[' && rest[2] == ']')
    rest = "." + rest.substr(1, 1) + rest.substr(3);
  e.key = "camera.vanishing_lines_px" + rest;
  return e;
}

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Marks the pixels inside each outlined light (dilated by `growPx`): they show the emitter, not
// a reflecting surface, and are left out of gathering and fitting.
ImageF rasterizeLights(int W, int H, const std::vector<std::vector<Vec2>>& polygons, int growPx) {
  ImageF mask(W, H, 1, 0.f);
  for (const auto& poly : polygons) {
    if (poly.size() < 3) continue;
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const Vec2& p : poly) {
      x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
      x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
    }
    const int ix0 = std::max(0, int(std::floor(x0)) - growPx),
              iy0 = std::max(0, int(std::floor(y0)) - growPx);
    const int ix1 = std::min(W - 1, int(std::ceil(x1)) + growPx),
              iy1 = std::min(H - 1, int(std::ceil(y1)) + growPx);
    for (int y = iy0; y <= iy1; ++y)
      for (int x = ix0; x <= ix1; ++x) {
        // Inside test (even-odd) at the pixel centre, or within growPx of an edge.
        const Vec2 c(x + 0.5, y + 0.5);
        bool inside = false;
        double nearest = 1e300;
        for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
          const Vec2 &a = poly[i], &b = poly[j];
          if (((a.y() > c.y()) != (b.y() > c.y())) &&
              (c.x() < (b.x() - a.x()) * (c.y() - a.y()) / (b.y() - a.y()) + a.x()))
            inside = !inside;
          const Vec2 ab = b - a;
          const double t = std::clamp((c - a).dot(ab) / std::max(1e-12, ab.squaredNorm()), 0.0, 1.0);
          nearest = std::min(nearest, (a + t * ab - c).norm());
        }
        if (inside || nearest <= growPx) mask.at(x, y) = 1.f;
      }
  }
  return mask;
}

// One scene-file surface built with the camera and room: an extrusion or box (`thicknessM`:
// 0 down to the floor, > 0 a slab), or stairs by steps or from a drawn profile.
Expected<Extrusion> surfaceOf(const Camera& camera, const RoomBox& box, const SurfaceKeys& sk,
                              double thicknessM, const std::string& key) {
  ExtrusionOptions eo;
  eo.thicknessM = thicknessM;
  if (sk.kind == "extrusion")
    return extrusionFromOutline(camera, sk.outlinePx, sk.heightClickPx, key, eo);
  if (sk.kind == "box") return boxFromOutline(camera, sk.outlinePx, sk.heightClickPx, key, eo);
  if (sk.kind == "stairs" && !sk.profilePx.empty()) {
    StairsProfileSpec sp;
    sp.profilePx = sk.profilePx;
    if (sk.wall == "left") sp.wall = SurfaceKind::WallLeft;
    if (sk.wall == "right") sp.wall = SurfaceKind::WallRight;
    if (sk.wall == "back") sp.wall = SurfaceKind::WallBack;
    sp.widthM = sk.widthM;
    return stairsFromProfile(camera, box, sp, key);
  }
  if (sk.kind == "stairs") {
    StairsSpec st;
    st.basePx = sk.basePx;
    st.steps = sk.steps;
    st.riseM = sk.riseM;
    st.runM = sk.runM;
    st.widthM = sk.widthM;
    const double sign = sk.climbAxis.size() == 2 && sk.climbAxis[0] == '-' ? -1.0 : 1.0;
    st.climbWorld = sk.climbAxis.size() == 2 && sk.climbAxis[1] == 'x' ? Vec3(sign, 0, 0)
                                                                       : Vec3(0, 0, sign);
    return stairsFromSpec(camera, st, key);
  }
  return Error{"", key + ".kind", "unknown surface kind '" + sk.kind + "'"};
}

// A surface; an extrusion or box drawn without "thickness_m" becomes a slab when an occluder's
// matte (the user's segmentation of the same object) shows the floor or wall under its top
// (slabFromMatte), with a warning saying so.
Expected<Extrusion> extrusionOf(PreparedScene& ps, const SurfaceKeys& sk,
                                const std::vector<OccluderMatte>& mattes, const std::string& key) {
  auto ex = surfaceOf(ps.camera, ps.box, sk, sk.thicknessM.value_or(0.0), key);
  if (!ex || sk.thicknessM || (sk.kind != "extrusion" && sk.kind != "box")) return ex;
  for (size_t m = 0; m < mattes.size(); ++m) {
    const SlabEvidence e = slabFromMatte(ps.camera, *ex, mattes[m].alphaPx);
    if (!e.open) continue;
    auto slab = surfaceOf(ps.camera, ps.box, sk, e.thicknessM, key);
    if (!slab) return ex;  // the solid stands
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  ": occluders[%zu]'s matte shows the floor under the top at %d of %d points, so "
                  "it is a slab %.3f m thick (give thickness_m to choose; 0: solid)",
                  m, e.openSamples, e.coveredSamples, e.thicknessM);
    ps.warnings.push_back(key + buf);
    return slab;
  }
  return ex;
}
// Where the decomposition's direct light is data: its own mask when it ran, else every pixel on
// the room outside the light outlines.
std::vector<uint8_t> usableDirect(const LightingEstimate& l, const ImageF& lightMask) {
  const size_t n = size_t(l.direct.width) * l.direct.height;
  if (l.decomposeValid.size() == n) return l.decomposeValid;
  std::vector<uint8_t> u(n, 0);
  for (size_t i = 0; i < n && i < l.firstSurfacePerPixel.size(); ++i)
    u[i] = l.firstSurfacePerPixel[i] >= 0 && (lightMask.empty() || lightMask.data[i] <= 0.5f);
  return u;
}

// Sun k's strength from its clipped patch's bounce (sun_ratio.h, sunStrengthFromBounce), when
// the ratio could not tell it (`ratioWhy`); nothing when the sun has no bounce image (no clipped
// patch) or the fit fails: the warnings say why.
std::optional<Vec3> sunFromBounce(PreparedScene& ps, const ImageF& photo, const Camera& camera, size_t k,
                                  const std::string& ratioWhy) {
  const LightingEstimate& L = ps.lighting;
  const std::string kept = "sun " + std::to_string(k) + ": strength kept as estimated: " + ratioWhy;
  if (k >= L.sunBounce.size()) {
    ps.warnings.push_back(kept);
    return std::nullopt;
  }
  SunBounceImages images{L.sunBounce[k], ImageF(), Vec3::Zero()};
  if (k < L.sunBounceUnseen.size() && k < L.sunBounceUnseenAt.size())
    images.unseen = L.sunBounceUnseen[k], images.unseenAt = L.sunBounceUnseenAt[k];
  auto r = sunStrengthFromBounce(photo, camera, ps.geometry, L.gathered, images, L.lights, L.suns[k]);
  if (!r) {
    ps.warnings.push_back(kept + "; its bounce does not tell it either: " + r.error().reason);
    return std::nullopt;
  }
  char buf[320];
  if (r->determined)
    std::snprintf(buf, sizeof buf,
                  "sun %zu: %s; its strength from the light its patch bounces: %.3g %.3g %.3g "
                  "(estimated %.3g %.3g %.3g, the clipped patch's lower bound %.3g %.3g %.3g)",
                  k, ratioWhy.c_str(), r->strength[0], r->strength[1], r->strength[2],
                  L.suns[k].irradianceOverPi[0], L.suns[k].irradianceOverPi[1],
                  L.suns[k].irradianceOverPi[2], r->lowerBound[0], r->lowerBound[1], r->lowerBound[2]);
  else
    std::snprintf(buf, sizeof buf,
                  "sun %zu: %s; its patch's bounce does not tell it either (%s): kept as estimated, "
                  "at least the clipped patch's lower bound: %.3g %.3g %.3g",
                  k, ratioWhy.c_str(), r->warning.c_str(), r->strength[0], r->strength[1],
                  r->strength[2]);
  ps.warnings.push_back(buf);
  return r->strength;
}

// Each sun's strength from the ratio of its lit patch to the same surface's shadow (sun_ratio.h),
// or, when the patch clips, from the light it bounces (PrepareOptions::sunsFromBounce); the
// gathered light keeps the patch's bounce at the new strength. Light outlines are no data.
// `photoLinear`, `camera` and `lightMask` are the working copy's (the lighting's pixel frame).
void sunsFromShadowRatio(PreparedScene& ps, const ImageF& photoLinear, const Camera& camera,
                         const ImageF& lightMask, bool fromBounce) {
  LightingEstimate& L = ps.lighting;
  ImageF photo = photoLinear;
  for (int y = 0; y < photo.height && !lightMask.empty(); ++y)
    for (int x = 0; x < photo.width; ++x)
      if (lightMask.at(x, y) > 0.5f) photo.setRgb(x, y, Vec3::Constant(1e9));
  for (size_t k = 0; k < L.suns.size(); ++k) {
    auto r = sunStrengthFromShadowRatio(photo, camera, ps.geometry, L.gathered, L.lights, L.suns[k]);
    std::optional<Vec3> strength;
    if (r) strength = r->strength;
    else if (fromBounce && r.error().reason.find("clipped") != std::string::npos)
      strength = sunFromBounce(ps, photo, camera, k, r.error().reason);
    else
      ps.warnings.push_back("sun " + std::to_string(k) +
                            ": strength kept as estimated: " + r.error().reason);
    if (!strength) continue;
    // The bounce fit scales the light by way of the unseen surfaces too (held at sunBounceUnseenAt).
    if (!r && k < L.sunBounceUnseen.size() && k < L.sunBounceUnseenAt.size() &&
        L.sunBounceUnseen[k].data.size() == L.gathered.data.size()) {
      const Vec3 unseenChange = *strength - L.sunBounceUnseenAt[k];
      for (size_t i = 0; i < L.gathered.data.size(); ++i)
        L.gathered.data[i] += float(unseenChange[int(i % 3)]) * L.sunBounceUnseen[k].data[i];
      L.sunBounceUnseenAt[k] = *strength;
    }
    const Vec3 change = *strength - L.suns[k].irradianceOverPi;
    L.suns[k].irradianceOverPi = *strength;
    if (k < L.sunBounce.size() && L.sunBounce[k].width == L.gathered.width &&
        L.sunBounce[k].height == L.gathered.height)
      for (size_t i = 0; i < L.gathered.data.size(); ++i)
        L.gathered.data[i] += float(change[int(i % 3)]) * L.sunBounce[k].data[i];
  }
}

// Whether the refinement moved a light's corners by more than a millimetre.
// The farthest any corner of a light moved (metres); infinity when a corner is not finite.
double cornerMoveM(const AreaLight& before, const AreaLight& after) {
  double moved = 0;
  for (size_t k = 0; k < 4; ++k) {
    const double d = (before.cornersWorld[k] - after.cornersWorld[k]).norm();
    if (!std::isfinite(d)) return std::numeric_limits<double>::infinity();
    moved = std::max(moved, d);
  }
  return moved;
}

bool lightsMoved(const std::vector<AreaLight>& before, const std::vector<AreaLight>& after) {
  if (before.size() != after.size()) return true;
  for (size_t j = 0; j < before.size(); ++j)
    if (cornerMoveM(before[j], after[j]) > 1e-3) return true;
  return false;
}

}  // namespace

const char* versionString() { return INLAY_VERSION; }

Expected<TriangleMesh> loadObjectMesh(const ObjectKeys& object) {
  auto mesh = loadMesh(object.meshResolved.empty() ? object.mesh : object.meshResolved);
  if (!mesh) return mesh.error().underKey("mesh");
  if (object.subdivideLevels <= 0) return mesh;
  auto smooth = subdivide(*mesh, object.subdivideLevels);
  if (!smooth) return smooth.error();
  // One material per object in the renderer: keep the file's for preset "asset".
  smooth->mesh.materials = mesh->materials;
  return std::move(smooth->mesh);
}

Status exportSceneGltf(const PreparedScene& scene, const std::string& path,
                       std::vector<std::string>* warnings) {
  RenderScene shown = scene.renderScene;  // hidden objects are not exported
  for (size_t i = shown.objects.size(); i-- > 0;)
    if (i < scene.doc.objects.size() && scene.doc.objects[i].hidden)
      shown.objects.erase(shown.objects.begin() + std::ptrdiff_t(i));
  return exportGltf(shown, path, {}, warnings);
}

Expected<std::vector<std::optional<Material>>> roomMaterialsOf(const RoomKeys& keys,
                                                               const SceneGeometry& room) {
  std::vector<std::optional<Material>> out(room.surfaces.size());
  for (const auto& [name, k] : keys.materials) {
    const auto it = std::find_if(room.surfaces.begin(), room.surfaces.end(),
                                 [&wanted = name](const Surface& s) { return s.name == wanted; });
    if (it == room.surfaces.end())
      return Error{"", "room.materials." + name, "this room has no surface '" + name + "'"};
    if (k.preset == "diffuse") continue;
    Material m;
    m.kind = k.preset == "mirror" ? Material::Kind::Mirror : Material::Kind::Glossy;
    m.albedo = k.reflectance;  // the mirror's; a glossy surface keeps the projected albedo
    m.roughness = k.roughness;
    m.ior = k.ior;
    out[size_t(it - room.surfaces.begin())] = m;
  }
  return out;
}

Material materialFromAsset(const AssetMaterial& a) {
  Material m;
  m.albedo = a.baseColor;
  m.roughness = a.roughness;
  m.ior = a.ior;
  if (a.emission.maxCoeff() > 0) {
    m.kind = Material::Kind::Emissive;
    m.emission = a.emission;
  } else if (a.transmission > 0.5) {
    m.kind = a.roughness < 0.05 ? Material::Kind::Glass : Material::Kind::RoughGlass;
  } else if (a.metallic > 0.5) {
    m.kind = a.roughness < 0.05 ? Material::Kind::Mirror : Material::Kind::Conductor;
  } else {
    m.kind = a.roughness < 0.6 ? Material::Kind::Glossy : Material::Kind::Diffuse;
  }
  return m;
}

void setObjectMaterial(InsertedObject& object, const MaterialKeys& keys) {
  const TriangleMesh* mesh = object.meshObject.get();
  object.material = materialFromKeys(keys, mesh);
  object.partMaterials.clear();
  if (keys.preset != "asset" || !mesh || mesh->materials.size() < 2 ||
      mesh->triangleMaterial.size() != mesh->triangles.size())
    return;
  for (const AssetMaterial& a : mesh->materials) object.partMaterials.push_back(materialFromAsset(a));
}

Material materialFromKeys(const MaterialKeys& keys, const TriangleMesh* meshObject) {
  Material m;
  m.albedo = keys.albedo;
  m.roughness = keys.roughness;
  m.ior = keys.ior;
  if (keys.preset == "glossy") {
    m.kind = Material::Kind::Glossy;
  } else if (keys.preset == "mirror") {
    m.kind = Material::Kind::Mirror;
  } else if (keys.preset == "glass") {
    m.kind = Material::Kind::Glass;
  } else if (keys.preset == "metal") {
    m.kind = Material::Kind::Conductor;
  } else if (keys.preset == "rough_glass") {
    m.kind = Material::Kind::RoughGlass;
  } else if (keys.preset == "emissive") {
    m.kind = Material::Kind::Emissive;
    m.emission = keys.rgb;
    m.albedo = Vec3::Zero();
  } else if (keys.preset == "asset" && meshObject && !meshObject->materials.empty()) {
    // The file's first material, mapped onto the nearest of the renderer's models (a
    // multi-material file's other parts: setObjectMaterial).
    m = materialFromAsset(meshObject->materials.front());
  } else {
    m.kind = Material::Kind::Diffuse;
  }
  return m;
}

ImageF compositeOf(const ImageF& photoLinear, double exposureStops, const RenderFrame& frame,
                   const PhotoNoise* grain, uint32_t grainSeed, const ImageF* grainField,
                   const ImageF* unclipped, double vignetting) {
  ImageF c =
      differentialComposite(photoLinear, frame.withObjects, frame.withoutObjects, frame.mask, unclipped);
  if (grain) addGrain(c, photoLinear, frame, *grain, grainSeed, grainField);
  divideByVignetting(c, vignetting, /*undo=*/true);
  applyExposure(c, exposureStops);
  return c;
}

double vignettingFalloff(double v, int x, int y, int w, int h) {
  const double cx = w / 2.0, cy = h / 2.0, corner2 = cx * cx + cy * cy;
  const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
  const double r2 = corner2 > 0 ? std::min(1.0, (dx * dx + dy * dy) / corner2) : 0.0;
  const double strength = std::isfinite(v) ? std::clamp(v, 0.0, VignettingKeys::kMax) : 0.0;
  return 1 - strength * r2;
}

void divideByVignetting(ImageF& image, double v, bool undo) {
  if (!(std::isfinite(v) && v > 0)) return;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double V = vignettingFalloff(v, x, y, image.width, image.height);
      float* px = image.pixel(x, y);
      for (int c = 0; c < std::min(image.channels, 3); ++c)  // further channels (alpha) kept
        if (std::isfinite(px[c])) px[c] = float(undo ? px[c] * V : px[c] / V);
    }
}

double vignettingToApply(const VignettingKeys& keys, double estimatedV) {
  switch (keys.mode) {
    case VignettingKeys::Mode::None: return 0;
    case VignettingKeys::Mode::Given: return std::clamp(keys.v, 0.0, VignettingKeys::kMax);
    case VignettingKeys::Mode::Auto: break;
  }
  const bool confident = std::isfinite(estimatedV) && estimatedV >= kMinAutoVignetting &&
                         estimatedV < kMaxAutoVignetting;
  return confident ? estimatedV : 0;
}

std::string exampleScenePath() {
  namespace fs = std::filesystem;
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("INLAY_EXAMPLE_DIR")) candidates.emplace_back(env);
  for (const std::string& dir : dataDirCandidates("example")) candidates.emplace_back(dir);
  for (const auto& c : candidates)
    if (fs::exists(c / "scene.json")) return fs::weakly_canonical(c / "scene.json").string();
  return {};
}

Expected<CameraAndLayout> cameraAndLayoutOf(const CameraKeys& camera, const LayoutKeys& layout,
                                            const LoadedImage& photo, bool alwaysEstimate,
                                            const CancelToken* cancel) {
  const int W = photo.linearRgb.width, H = photo.linearRgb.height;
  const double heightM = camera.heightM.value_or(1.6);
  if (!(heightM > 0 && std::isfinite(heightM)))
    return Error{"", "camera.height_m", "must be a positive number of metres"};
  CameraAndLayout out;
  std::optional<Camera> given;
  if (camera.vanishingPointsPx) {
    VanishingInput in;
    in.vanishingPointsPx = *camera.vanishingPointsPx;
    in.focalPx = camera.focalPx;
    in.principalPx = camera.principalPx;
    in.widthPx = W;
    in.heightPx = H;
    in.heightM = heightM;
    auto cam = cameraFromVanishingPoints(in);
    if (!cam) return cam.error();
    given = *cam;
  }
  if (given && layout.backWallPx && !alwaysEstimate) {
    out.camera = *given;
    out.backWallPx = *layout.backWallPx;
    return out;
  }
  EstimateOptions eo;
  eo.priorFocalPx = camera.focalPx ? camera.focalPx : photo.exif.focalPx(W, H);
  eo.cameraHeightM = heightM;
  eo.principalPx = camera.principalPx;  // the rotation is fitted about the given point
  eo.cancel = cancel;
  auto e = estimateCamera(photo.linearRgb, eo);
  if (!e) return e.error();
  // What the user gave is kept and the rest estimated around it: a given camera keeps the
  // layout search on that camera; given corners pull the camera to the user's box.
  EstimateCorrection fix;
  bool anyFix = false;
  if (given) {
    fix.fixedCamera = *given;
    anyFix = true;
  } else if (camera.focalPx) {
    fix.lockedFocalPx = camera.focalPx;
    anyFix = true;
  }
  if (layout.backWallPx) {
    for (size_t i = 0; i < 4; ++i) fix.backWallCornersPx[i] = (*layout.backWallPx)[i];
    anyFix = true;
  }
  for (size_t k = 0; k < 3; ++k)
    if (camera.vanishingLinesPx[k]) {
      fix.vanishingLinesPx[k] = camera.vanishingLinesPx[k];
      anyFix = true;
    }
  if (anyFix) {
    auto fixed = correctEstimate(*e, fix, eo);
    if (!fixed) return inFileKeys(fixed.error());
    e = std::move(fixed);
  }
  for (const auto& w : e->warnings) out.warnings.push_back("estimate: " + w);
  if (!e->manhattan)
    out.warnings.push_back(
        "estimate: the photo shows no clear room structure; the camera is a "
        "fallback (" +
        std::string(e->focalFromPrior ? "prior" : "default") +
        " focal length, upright): give camera.vanishing_points_px for a reliable result");
  if (given) {
    out.camera = *given;
  } else {
    out.camera = e->camera;
    out.camera.heightM = heightM;
    if (camera.principalPx) out.camera.principalPx = *camera.principalPx;
  }
  out.backWallPx = layout.backWallPx ? *layout.backWallPx : e->backWallPx;
  out.estimate = std::move(*e);
  return out;
}

namespace {

// responseOf with the photo's 8-bit codes (srgbCodesOf) when they are already found, else null.
ChosenResponse responseOfCodes(const ResponseKeys& keys, const LoadedImage& photo,
                               const ResponseEstimateOptions& options,
                               const std::vector<unsigned char>* codes) {
  ChosenResponse out;
  if (!photo.wasSrgbEncoded) {
    out.response = CameraResponse::linear();
    if (keys.mode != ResponseKeys::Mode::Auto && keys.mode != ResponseKeys::Mode::Linear)
      out.warnings.push_back("camera.response: ignored, the photo is already linear (EXR/HDR)");
    return out;
  }
  switch (keys.mode) {
    case ResponseKeys::Mode::Srgb: out.response = CameraResponse::srgb(); break;
    case ResponseKeys::Mode::Linear: out.response = CameraResponse::linear(); break;
    case ResponseKeys::Mode::ToeShoulder:
      out.response = CameraResponse::toeShoulder({keys.power, keys.toe, keys.shoulder});
      break;
    case ResponseKeys::Mode::Auto: {
      ResponseEstimate e = codes ? estimateResponseFromCodes(photo.linearRgb, *codes, options)
                                 : estimateResponse(photo.linearRgb, options);
      out.response = e.response;
      out.warnings = e.warnings;
      out.estimate = std::move(e);
      break;
    }
  }
  return out;
}

}  // namespace

ChosenResponse responseOf(const ResponseKeys& keys, const LoadedImage& photo,
                          const ResponseEstimateOptions& options) {
  return responseOfCodes(keys, photo, options, nullptr);
}

Expected<Placement> placeObjectAt(const PreparedScene& scene, size_t index) {
  INLAY_CHECK(index < scene.doc.objects.size() && index < scene.renderScene.objects.size());
  const ObjectKeys& o = scene.doc.objects[index];
  const auto& mesh = scene.renderScene.objects[index].meshObject;
  return placeObject(*mesh, scene.geometry, scene.camera, o.basePx, o.heightM, o.yawDeg,
                     "objects[" + std::to_string(index) + "]");
}

Expected<PlacedObjects> placeObjects(const std::vector<ObjectKeys>& objects,
                                     const SceneGeometry& geometry, const Camera& camera,
                                     MeshCache* cache) {
  MeshCache local;
  MeshCache& meshes = cache ? *cache : local;
  PlacedObjects out;
  for (size_t i = 0; i < objects.size(); ++i) {
    const ObjectKeys& o = objects[i];
    const std::string key = "objects[" + std::to_string(i) + "]";
    auto& cached = meshes[(o.meshResolved.empty() ? o.mesh : o.meshResolved) + "#" +
                          std::to_string(o.subdivideLevels)];
    if (!cached) {
      auto mesh = loadObjectMesh(o);
      if (!mesh) return mesh.error().underKey(key);
      cached = std::make_shared<const TriangleMesh>(std::move(*mesh));
    }
    auto place = placeObject(*cached, geometry, camera, o.basePx, o.heightM, o.yawDeg, key);
    if (!place) return place.error();
    InsertedObject obj;
    obj.meshObject = cached;
    obj.worldFromObject = place->worldFromObject;
    setObjectMaterial(obj, o.material);
    out.objects.push_back(obj);
    out.placements.push_back(*place);
  }
  return out;
}

RenderScene shownRenderScene(const PreparedScene& scene) {
  RenderScene shown = scene.renderScene;
  for (size_t i = 0; i < shown.objects.size() && i < scene.doc.objects.size(); ++i)
    if (scene.doc.objects[i].hidden) shown.objects[i].meshObject.reset();
  return shown;
}

std::string describeStage(const StageRecord& stage) {
  if (!stage.ran) return stage.name + ": skipped, " + stage.reason;
  char seconds[48];
  std::snprintf(seconds, sizeof seconds, "%.3f s, CPU %.3f s", stage.seconds, stage.cpuSeconds);
  std::string line = stage.name + ": " + seconds +
                     (stage.detail.empty() ? "" : " (" + stage.detail + ")");
  if (stage.reducedImage)
    line += " at " + std::to_string(stage.workingWidth) + " x " + std::to_string(stage.workingHeight) +
            " px";
  for (size_t i = 0; i < stage.steps.size(); ++i) {
    std::snprintf(seconds, sizeof seconds, " %.2f", stage.steps[i].cpuSeconds);
    line += (i == 0 ? "; CPU s: " : ", ") + stage.steps[i].name + seconds;
  }
  return line;
}

namespace {

// The photo the image stages (occluder mattes, the lights' mask, shafts, lighting, sun ratio,
// refine, refit) work on: the photo area-averaged to PrepareOptions::workingMaxPixels, with the
// camera and every pixel coordinate scaled to it; or, when the photo has no more pixels, the
// photo itself (then every stage gets exactly what it got before there was a working copy).
struct WorkingCopy {
  bool reduced = false;
  double sx = 1, sy = 1;  // working pixels per photo pixel, per axis
  ImageF photo;           // the reduced photo (empty when not reduced)
  ImageF photoLightMask;  // the lights' mask at the photo's size (when reduced)
};

// The camera stage's result (cameraAndLayoutOf) and the fingerprint of the photo it was found on
// (photoFingerprint; the scene file's camera and layout keys are the same for both responses).
struct FoundCamera {
  std::shared_ptr<const CameraAndLayout> found;
  uint64_t photoKey = 0;
};

// What the stages of prepareScene() hand on to each other besides the PreparedScene they fill.
struct Preparation {
  Preparation(const SceneDoc& d, const PrepareOptions& o) : doc(d), opt(o) { ps.doc = d; }
  const SceneDoc& doc;
  const PrepareOptions& opt;
  PreparedScene ps;
  std::array<Vec2, 4> layoutCorners{};  // the back wall the camera stage was given or found
  std::vector<OccluderMatte> mattes;    // per occluder
  std::vector<Surface> occluderCards;   // per occluder; join the room after its surfaces
  std::vector<std::optional<Material>> roomMaterials;  // per room surface ("room.materials")
  std::vector<bool> nonMatte;                          // per room surface: marked glossy or mirror
  std::vector<AreaLight> lights;                       // per scene-file light, as marked
  // Per light: estimated (its intensity fitted, its position refined) rather than given with its
  // rgb and "refine": false.
  std::vector<bool> estimated;
  std::vector<std::vector<Vec2>> outlines;  // of the outlined lights
  ImageF lightMask;                         // the pixels showing an outlined light
  std::vector<SunLight> suns;               // from the shafts
  LightingOptions lightingOptions;          // the lighting stage's, again for its refit
  bool refined = false;                     // the refinement ran
  // The refinement's largest light move (largestLightMove); below PrepareOptions::
  // refitMinLightMove the first estimate's lights are kept and the refit is skipped.
  double refinedMove = 0;
  WorkingCopy work;
  // The image size a stage worked at when it is neither the photo's nor the working copy's
  // (the camera estimate reduces the photo itself); set by the stage, read by runStage.
  std::array<int, 2> stagePx{};
  std::vector<StageStep> stageSteps;  // the steps a stage timed (StageRecord::steps), set by it
  // The photo as loaded, decoded as sRGB (srgbDecoded) before the response decoded it with the
  // curve: kept when the response check will prepare it again with sRGB
  // (PrepareOptions::checkResponseByLightFit).
  std::optional<LoadedImage> photoAsLoaded;
  MeshCache* meshes = nullptr;  // the objects' meshes, shared by the response check's candidates
  // The response check's full comparison: the last lighting estimate's decomposition waits for
  // the verdict (LightingOptions::deferDecomposition), made only for the response kept.
  // `pendingStage`: the stage whose estimate waits, and the prefix of its notes as warnings.
  bool deferLastDecomposition = false;
  std::string pendingStage, pendingNotes;
  // The camera the camera stage found (FoundCamera): kept when `handsCameraOn` (the response
  // check's copies hand theirs to the preparation of the same response after them); when set
  // before the stage, taken instead of estimating it again if the photo is the same.
  FoundCamera camera;
  bool handsCameraOn = false;

  // The image the image stages read, and the camera in its pixels.
  const ImageF& workPhoto() const { return work.reduced ? work.photo : ps.photo.linearRgb; }
  Camera workCamera() const {
    if (!work.reduced) return ps.camera;
    Camera c = ps.camera;
    c.widthPx = work.photo.width;
    c.heightPx = work.photo.height;
    c.focalPx *= work.sx;
    c.principalPx = toWork(ps.camera.principalPx);
    return c;
  }
  Vec2 toWork(const Vec2& px) const {
    return work.reduced ? Vec2(px.x() * work.sx, px.y() * work.sy) : px;
  }
  std::vector<Vec2> toWork(std::vector<Vec2> pts) const {
    for (Vec2& q : pts) q = toWork(q);
    return pts;
  }
  ShaftKeys toWork(ShaftKeys shaft) const {
    for (auto* box : {&shaft.shaftBoxPx, &shaft.sourceBoxPx})
      if (*box && work.reduced) {
        auto& b = **box;
        b = {b[0] * work.sx, b[1] * work.sy, b[2] * work.sx, b[3] * work.sy};
      }
    return shaft;
  }
  // The pixels showing an outlined light, at the photo's own size.
  const ImageF& photoLightMask() const { return work.reduced ? work.photoLightMask : lightMask; }

  bool cancelled() const { return opt.cancel && opt.cancel->shouldStop(); }
  // The refinement holds light i where the estimate put it.
  // The lights the shafts' unseen windows add (after the scene file's) are held where the beam
  // put them.
  bool locked(size_t i) const { return i >= doc.lights.size() || doc.lights[i].lock || !estimated[i]; }
};

Error cancelledError() { return Error{"", "", "cancelled"}; }

// "1 light", "2 lights".
// A lighting estimate's step times (LightingEstimate::steps) as a stage's (StageRecord::steps).
std::vector<StageStep> stepsOf(const LightingEstimate& e) {
  std::vector<StageStep> out;
  for (const LightingStepTime& s : e.steps) out.push_back({s.name, s.seconds, s.cpuSeconds});
  return out;
}

// "5 passes, 11834 points x 36 rays": the gather-and-fit passes and each pass's gather ("3
// passes, the first estimate's rays replayed, ...": LightingEstimate::raysReused).
std::string gatherText(const LightingEstimate& e) {
  return std::to_string(e.passes) + (e.passes == 1 ? " pass, " : " passes, ") +
         (e.raysReused ? "the first estimate's rays replayed, " : "") +
         (e.warmStarted ? "going on from its passes, " : "") + std::to_string(e.gatherPoints) +
         " points x " + std::to_string(e.gatherSamples) + " rays, " + std::to_string(e.fitIterations) +
         " light fit iterations";
}

std::string countOf(size_t n, const std::string& thing) {
  return std::to_string(n) + " " + thing + (n == 1 ? "" : "s");
}

// --- Why a scene does not need a stage (empty: it does) ---

std::string noOccluders(const Preparation& p) { return p.doc.occluders.empty() ? "none marked" : ""; }
std::string noSurfaces(const Preparation& p) { return p.doc.surfaces.empty() ? "none marked" : ""; }
std::string noShafts(const Preparation& p) { return p.doc.shafts.empty() ? "no sun marked" : ""; }
std::string noObjects(const Preparation& p) { return p.doc.objects.empty() ? "none inserted" : ""; }

const char* kInitialLights = "the lights are kept as estimated (initial lights asked for)";

std::string sunRatioNotNeeded(const Preparation& p) {
  if (!p.opt.refineLights) return kInitialLights;
  if (!p.opt.sunsFromShadowRatio) return "turned off";
  return p.ps.lighting.suns.empty() ? "no sun marked" : "";
}

std::string refineNotNeeded(const Preparation& p) {
  if (!p.opt.refineLights) return kInitialLights;
  // With LightRefineOptions::refineSuns the suns' strengths are fitted even when no light moves.
  if (p.opt.refine.refineSuns && !p.ps.lighting.suns.empty()) return "";
  if (p.ps.lighting.lights.empty()) return "no light marked";
  bool allLocked = true, anyGiven = false;
  for (size_t i = 0; i < p.doc.lights.size(); ++i) {
    allLocked = allLocked && p.locked(i);
    anyGiven = anyGiven || !p.estimated[i];
  }
  if (!allLocked) return "";
  return anyGiven ? "every light locked or given (\"refine\": false)" : "every light locked";
}

std::string photoSizeNotNeeded(const Preparation& p) {
  return p.work.reduced ? "" : "the working copy is the photo";
}

// Whether the refinement moved the lights too little to fit the lighting again: then the first
// estimate's lights are kept (refineTheLights).
bool movedTooLittleToRefit(const Preparation& p) {
  return p.refined && p.refinedMove < p.opt.refitMinLightMove;  // NaN: refit
}

std::string refitNotNeeded(const Preparation& p) {
  if (!p.refined) return "the lights were not refined";
  if (!movedTooLittleToRefit(p))
    return lightsMoved(p.ps.initialLights, p.ps.lighting.lights) ? "" : "no light moved";
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "lights moved by at most %.1f %% of their size (under %.1f %%): the first "
                "estimate's lights are kept",
                100 * p.refinedMove, 100 * p.opt.refitMinLightMove);
  return buf;
}

// --- The stages' work ---

Status loadPhoto(Preparation& p, std::string& detail) {
  auto photo =
      loadImage(p.doc.photoResolved.empty() ? p.doc.photo : p.doc.photoResolved, ImageLimits::photo());
  if (!photo) return photo.error().underKey("photo");
  p.ps.photo = std::move(*photo);
  detail = std::to_string(p.ps.photo.linearRgb.width) + " x " +
           std::to_string(p.ps.photo.linearRgb.height) + " px";
  return {};
}

// `photo` decoded as the response stage decodes it with sRGB (from its 8-bit `codes` when
// found, else its values): what the response check's sRGB candidates read, its copy's included,
// so that the copy's camera serves the full-size preparation (Preparation::camera). The loader's
// sRGB values differ from it in some values (their fingerprints differed on the example and on
// York); decoding it again with sRGB changes nothing.
LoadedImage srgbDecoded(const LoadedImage& photo, const std::vector<unsigned char>* codes) {
  LoadedImage out = photo;
  if (codes) redecodePhotoFromCodes(out.linearRgb, *codes, CameraResponse::srgb());
  else if (out.wasSrgbEncoded)
    redecodePhoto(out.linearRgb, out.sourceBitsPerChannel, CameraResponse::srgb());
  return out;
}

// The camera response; from here on everything works in the linearised radiance.
Status chooseResponse(Preparation& p, std::string& detail) {
  ResponseEstimateOptions ro = p.opt.responseEstimate;
  ro.cancel = p.opt.cancel;
  PreparedScene& ps = p.ps;
  // An estimated response of an 8-bit photo: its codes found once for the estimate and the
  // re-decode (the same values as finding them in each).
  const bool shareCodes = ps.photo.wasSrgbEncoded && ps.photo.sourceBitsPerChannel <= 8 &&
                          p.doc.camera.response.mode == ResponseKeys::Mode::Auto &&
                          !ps.photo.linearRgb.empty() && ps.photo.linearRgb.channels == 3;
  const std::vector<unsigned char> codes = shareCodes ? srgbCodesOf(ps.photo.linearRgb)
                                                      : std::vector<unsigned char>{};
  ChosenResponse chosen =
      responseOfCodes(p.doc.camera.response, ps.photo, ro, shareCodes ? &codes : nullptr);
  if (p.cancelled()) return cancelledError();
  ps.response = chosen.response;
  detail = !ps.photo.wasSrgbEncoded ? "linear photo" : chosen.estimate ? "estimated" : "camera.response";
  ps.responseEstimate = std::move(chosen.estimate);
  for (const auto& w : chosen.warnings) ps.warnings.push_back(w);
  if (p.opt.checkResponseByLightFit && ps.responseEstimate &&
      ps.response.family() == ResponseFamily::ToeShoulder)
    p.photoAsLoaded = srgbDecoded(ps.photo, shareCodes ? &codes : nullptr);
  if (shareCodes) redecodePhotoFromCodes(ps.photo.linearRgb, codes, ps.response);
  else if (ps.photo.wasSrgbEncoded)
    redecodePhoto(ps.photo.linearRgb, ps.photo.sourceBitsPerChannel, ps.response);
  return {};
}

// The working copy (WorkingCopy), made once the response has linearised the photo.
Status makeWorkingCopy(Preparation& p, std::string& detail) {
  const ImageF& photo = p.ps.photo.linearRgb;
  const auto [w, h] = workingSizeFor(photo.width, photo.height, p.opt.workingMaxPixels);
  WorkingCopy& wc = p.work;
  wc.reduced = w != photo.width || h != photo.height;
  if (wc.reduced) {
    wc.sx = double(w) / photo.width;
    wc.sy = double(h) / photo.height;
    wc.photo = resizeImage(photo, w, h);
  }
  p.ps.workingPx = {w, h};
  detail = wc.reduced ? "the photo area-averaged" : "the photo's own size";
  return {};
}

// The photo's size and values: what the camera estimate reads of it.
uint64_t photoFingerprint(const ImageF& photo) {
  Fingerprint f;
  for (const int v : {photo.width, photo.height, photo.channels}) f.value(v);
  f.bytes(photo.data.data(), photo.data.size() * sizeof(float));
  return f.get();
}

// The camera stage's detail when it took the camera the response check's copy found on the same
// photo (Preparation::camera).
const char* const kCameraOfTheCopy = "estimated from the photo once, for the response check's copy";

// The camera and the back wall: the file's, or estimated from the photo, or the estimate that
// an earlier preparation made on the same photo with the same keys (Preparation::camera).
Status findCamera(Preparation& p, std::string& detail) {
  const bool keyed = p.camera.found || p.handsCameraOn;  // the fingerprint only when it serves
  const uint64_t key = keyed ? photoFingerprint(p.ps.photo.linearRgb) : 0;
  const bool reused = p.camera.found && p.camera.photoKey == key;
  if (!reused) {
    auto found = cameraAndLayoutOf(p.doc.camera, p.doc.layout, p.ps.photo, false, p.opt.cancel);
    if (!found) return found.error();
    p.camera = {std::make_shared<const CameraAndLayout>(std::move(*found)), key};
  }
  const CameraAndLayout& cl = *p.camera.found;
  p.ps.camera = cl.camera;
  p.layoutCorners = cl.backWallPx;
  detail = !cl.estimate ? "the file's vanishing points and back wall"
           : reused     ? kCameraOfTheCopy
                        : "estimated from the photo";
  if (cl.estimate) {  // the estimate reduces the photo itself (EstimateOptions::maxWorkingSidePx)
    const ImageF& photo = p.ps.photo.linearRgb;
    const double s = cl.estimate->workingScale;
    p.stagePx = {int(std::lround(photo.width * s)), int(std::lround(photo.height * s))};
  }
  p.ps.cameraEstimate = cl.estimate;
  for (const auto& w : cl.warnings) p.ps.warnings.push_back(w);
  return {};
}

// The room box from the back wall; an estimated back wall that does not fit this camera gives a
// room of ordinary proportions (a given one is an error).
Status boxFromBackWall(Preparation& p, std::string& detail) {
  PreparedScene& ps = p.ps;
  std::vector<Vec3> placed;  // the corners of the lights placed in 3D stay inside the box
  for (const LightKeys& l : p.doc.lights)
    if (l.kind == LightKeys::Kind::RectM)
      placed.insert(placed.end(), l.cornersM.begin(), l.cornersM.end());
  RoomOptions options;
  options.rearMarginM = rearWallDistanceM(p.doc.layout.rearM, options.rearMarginM, placed);
  auto box = roomFromBackWall(ps.camera, p.layoutCorners, options);
  if (!box && p.doc.layout.backWallPx) return box.error();
  if (box) {
    ps.box = *box;
    ps.backWallPx = p.layoutCorners;
  } else {
    ps.box = RoomBox{-2.5, 2.5, -5.0, options.rearMarginM,
                     std::max(2.6, p.doc.camera.heightM.value_or(1.6) + 0.5)};
    ps.warnings.push_back("layout: the estimated back wall is unusable (" + box.error().reason +
                          "); using a 5 x 5.5 m room: give layout.back_wall_px");
  }
  char buf[80];
  std::snprintf(buf, sizeof buf, "%.2f x %.2f m, %.2f m high", ps.box.xRightM - ps.box.xLeftM,
                ps.box.zRearM - ps.box.zBackM, ps.box.ceilingM);
  detail = buf;
  return {};
}

// Each occluder's matte from its scribbles, and the card it stands as in the room. The mattes
// come before the surfaces: one may show that a top drawn without a thickness is open below.
Status occluderMattes(Preparation& p, std::string& detail) {
  for (size_t i = 0; i < p.doc.occluders.size(); ++i) {
    const std::string key = "occluders[" + std::to_string(i) + "]";
    const OccluderKeys& o = p.doc.occluders[i];
    // At the scale of a 640-pixel photo whatever the photo's size (MatteOptions): a bigger
    // photo's matte on its scribbles' region, reduced, and brought back to its pixels.
    auto matte =
        matteFromScribbles(p.ps.photo.linearRgb, o.foregroundScribblesPx, o.backgroundScribblesPx, key);
    if (!matte) return matte.error();
    p.mattes.push_back(std::move(*matte));
    if (p.cancelled()) return cancelledError();
  }
  for (size_t i = 0; i < p.mattes.size(); ++i) {
    auto card = occluderCard(p.ps.camera, p.mattes[i], int(i), "occluders[" + std::to_string(i) + "]");
    if (!card) return card.error();
    p.occluderCards.push_back(std::move(*card));
  }
  detail = countOf(p.mattes.size(), "matte");
  return {};
}

Status buildSurfaces(Preparation& p, std::string& detail) {
  for (size_t i = 0; i < p.doc.surfaces.size(); ++i) {
    auto ex = extrusionOf(p.ps, p.doc.surfaces[i], p.mattes, "surfaces[" + std::to_string(i) + "]");
    if (!ex) return ex.error();
    p.ps.extrusions.push_back(*ex);
  }
  detail = countOf(p.ps.extrusions.size(), "surface") + " built";
  return {};
}

// The room's geometry: box, surfaces and occluder cards. Its marked materials are checked now,
// before the costly lighting stage.
Status assembleRoom(Preparation& p, std::string& detail) {
  PreparedScene& ps = p.ps;
  ps.geometry = buildSceneGeometry(ps.box, ps.extrusions);
  for (Surface& card : p.occluderCards) ps.geometry.surfaces.push_back(std::move(card));
  p.occluderCards.clear();
  auto roomMaterials = roomMaterialsOf(p.doc.room, ps.geometry);
  if (!roomMaterials) return roomMaterials.error();
  p.roomMaterials = std::move(*roomMaterials);
  // Marked glossy or mirror surfaces show reflections: the light fits leave them out.
  p.nonMatte.assign(p.roomMaterials.size(), false);
  for (size_t i = 0; i < p.nonMatte.size(); ++i) p.nonMatte[i] = p.roomMaterials[i].has_value();
  const auto marked = std::count(p.nonMatte.begin(), p.nonMatte.end(), true);
  detail = countOf(ps.geometry.surfaces.size(), "surface") +
           (marked ? ", " + std::to_string(marked) + " reflective" : "");
  return {};
}

// The lights as marked: outlines on the photo become area lights on the room's surfaces,
// rectangles placed in 3D face the room. The pixels inside the outlines are no data.
Status lightsFromMarks(Preparation& p, std::string& detail) {
  const PreparedScene& ps = p.ps;
  const Vec3 roomCentre(0.5 * (ps.box.xLeftM + ps.box.xRightM), 0.5 * ps.box.ceilingM,
                        0.5 * (ps.box.zBackM + ps.box.zRearM));
  for (size_t i = 0; i < p.doc.lights.size(); ++i) {
    const LightKeys& l = p.doc.lights[i];
    const std::string key = "lights[" + std::to_string(i) + "]";
    if (l.kind == LightKeys::Kind::PolygonPx) {
      auto a = lightFromOutline(ps.camera, ps.geometry, l.pointsPx, key + ".points");
      if (!a) return a.error();
      p.lights.push_back(*a);
      p.outlines.push_back(l.pointsPx);
    } else {
      AreaLight a;
      a.cornersWorld = l.cornersM;
      if (!(a.area() > 1e-8)) return Error{"", key + ".corners", "the rectangle has no area"};
      if (a.normal().dot(roomCentre - a.centre()) < 0) std::swap(a.cornersWorld[1], a.cornersWorld[3]);
      a.radiance = l.rgb.value_or(Vec3(1, 1, 1));
      p.lights.push_back(a);
    }
    p.estimated.push_back(l.refine || !(l.kind == LightKeys::Kind::RectM && l.rgb));
  }
  if (p.lights.empty())
    p.ps.warnings.push_back("lights: none given; the objects are lit by the room's gathered light only");
  std::vector<std::vector<Vec2>> workOutlines;
  for (const auto& o : p.outlines) workOutlines.push_back(p.toWork(o));
  p.lightMask = rasterizeLights(p.workPhoto().width, p.workPhoto().height, workOutlines, 2);
  if (p.work.reduced)  // the same margin at the photo's size, for the render's bounces
    p.work.photoLightMask = rasterizeLights(ps.photo.linearRgb.width, ps.photo.linearRgb.height,
                                            p.outlines, int(std::lround(2 / p.work.sx)));
  detail = std::to_string(p.outlines.size()) + " outlined, " +
           std::to_string(p.lights.size() - p.outlines.size()) + " placed in 3D";
  return {};
}

// The sky through a shaft's window when the photo does not show it: the opening the beam came
// through, as an area light whose intensity the lighting fit finds (PrepareOptions::
// skyThroughUnseenWindows). Returns whether it was added.
bool addSkyOfUnseenWindow(Preparation& p, size_t i, const SunLight& sun) {
  if (!p.opt.skyThroughUnseenWindows || p.doc.shafts[i].sourceBoxPx) return false;
  const auto opening =
      openingOfBeam(sun, p.ps.camera, p.ps.geometry, kMinBeamPixels, p.opt.windowRevealDepthM);
  if (!opening || opening->visibleShare >= 0.5) return false;
  p.lights.push_back(opening->light);
  p.estimated.push_back(true);
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "shafts[%zu]: the window the sun comes through is out of view; its sky is a light "
                "of %.2f x %.2f m on the %s (where the beam came from), its intensity fitted "
                "(give source_box_px, or outline the window as a light, to choose)",
                i, opening->widthM, opening->heightM,
                p.ps.geometry.surfaces[size_t(opening->surface)].name.c_str());
  p.ps.warnings.push_back(buf);
  return true;
}

Status sunsFromShafts(Preparation& p, std::string& detail) {
  size_t skies = 0;
  for (size_t i = 0; i < p.doc.shafts.size(); ++i) {
    auto shaft = sunFromShaft(p.toWork(p.doc.shafts[i]), p.workPhoto(), p.workCamera(), p.ps.geometry,
                              "shafts[" + std::to_string(i) + "]");
    if (!shaft) return shaft.error();
    p.suns.push_back(shaft->sun);
    skies += addSkyOfUnseenWindow(p, i, shaft->sun);
  }
  detail = countOf(p.suns.size(), "sun");
  if (skies == 1) detail += ", 1 sky through an unseen window";
  if (skies > 1) detail += ", " + std::to_string(skies) + " skies through unseen windows";
  return {};
}

// LightingOptions::blackBelow for the photo's camera response: `srgbLevel` (sRGB's, below its
// code 1) times the response's code 1 over sRGB's, so that the same codes are black whatever the
// curve (a long shoulder decodes code 64 to 5e-5). sRGB, linear and EXR photos keep `srgbLevel`.
double blackLevelOf(const PreparedScene& ps, double srgbLevel) {
  if (!ps.photo.wasSrgbEncoded || ps.response.family() != ResponseFamily::ToeShoulder) return srgbLevel;
  const double code1 = ps.response.table8()[1], srgb1 = CameraResponse::srgb().table8()[1];
  return code1 > 0 && std::isfinite(code1) ? srgbLevel * code1 / srgb1 : srgbLevel;
}

std::string vignettingNotNeeded(const Preparation& p);

// The decomposition the lighting estimate left (LightingOptions::deferDecomposition), its notes
// added to the warnings after `prefix` as the stage that made the estimate adds them.
Status finishTheDecomposition(Preparation& p, const std::string& prefix) {
  LightingEstimate& lighting = p.ps.lighting;
  const size_t notes = lighting.notes.size();
  if (auto error = finishDecomposition(lighting, p.ps.geometry))
    return p.cancelled() ? cancelledError() : *error;
  for (size_t i = notes; i < lighting.notes.size(); ++i)
    p.ps.warnings.push_back(prefix + lighting.notes[i]);
  return {};
}

// Leaves the estimate's decomposition for the response check's verdict when `p` defers it
// (Preparation::deferLastDecomposition), otherwise runs it now. `stage` and `prefix`: its stage
// and its notes' prefix.
Status decomposeUnlessDeferred(Preparation& p, bool defer, const char* stage, const char* prefix) {
  if (defer && p.ps.lighting.pendingDecomposition) {
    p.pendingStage = stage;
    p.pendingNotes = prefix;
    return {};
  }
  return finishTheDecomposition(p, prefix);
}

// Whether the lighting stage's decomposition may wait for the response check's verdict: no
// stage before the verdict reads its albedo (the vignetting fits the lighting again, the
// refinement reads it; without a refinement there is no refit). The sun ratio changes the
// gathered light, not the albedo: the decomposition keeps the gathered light it was made with.
bool decompositionCanWait(const Preparation& p) {
  return p.deferLastDecomposition && !vignettingNotNeeded(p).empty() && !refineNotNeeded(p).empty();
}

// The gathered light, the albedo and the lights' radiances (lighting/estimate.h).
Status fitTheLighting(Preparation& p, std::string& detail) {
  PreparedScene& ps = p.ps;
  LightingOptions lo = p.lightingOptions;
  lo.deferDecomposition = p.deferLastDecomposition;  // made below, or after the check's verdict
  auto lighting = estimateLighting(p.workPhoto(), p.workCamera(), ps.geometry, p.lights, p.estimated,
                                   p.lightMask, p.suns, lo);
  if (!lighting) return lighting.error();
  ps.lighting = std::move(*lighting);
  for (const auto& n : ps.lighting.notes) ps.warnings.push_back("lighting: " + n);
  if (Status st = decomposeUnlessDeferred(p, decompositionCanWait(p), "lighting", "lighting: "); !st)
    return st;
  p.stageSteps = stepsOf(ps.lighting);
  ps.initialLights = ps.lighting.lights;
  ps.initialSuns = ps.lighting.suns;
  detail = countOf(ps.lighting.lights.size(), "light") + ", " + countOf(ps.lighting.suns.size(), "sun") +
           ", " + gatherText(ps.lighting);
  return {};
}

Status estimateTheLighting(Preparation& p, std::string& detail) {
  LightingOptions& lo = p.lightingOptions;
  lo.nonMatteSurfaces = p.nonMatte;
  lo.cancel = p.opt.cancel;
  lo.threads = p.opt.threads;
  lo.seed += p.opt.seed;
  lo.fitUnseenCeilingAlbedo = p.opt.fitUnseenCeilingAlbedo;
  lo.fitUnseenCeiling = p.opt.fitUnseenCeiling;
  lo.renderFittedCeiling = p.opt.renderFittedCeiling;
  lo.gatherSunBounceUnseen = p.opt.sunsFromShadowRatio && p.opt.sunsFromBounce;
  lo.blackBelow = blackLevelOf(p.ps, lo.blackBelow);
  return fitTheLighting(p, detail);
}

// camera.vignetting: the strength to apply (given, or the light fit's estimate when confident);
// when it is not 0 the photo and its working copy are devignetted and the light fit runs again
// on them, so every later stage (and the render's bounces) sees the devignetted radiance.
Status devignetteThePhoto(Preparation& p, std::string& detail) {
  PreparedScene& ps = p.ps;
  const double estimated = ps.lighting.vignetting;
  const double v = vignettingToApply(p.doc.camera.vignetting, estimated);
  char text[96];
  std::snprintf(text, sizeof text, "v %.2f applied, the light fit's residual shows %.2f", v, estimated);
  detail = text;
  ps.vignettingEstimated = estimated;
  if (v == 0) return {};
  ps.vignetting = v;
  divideByVignetting(ps.photo.linearRgb, v);
  if (p.work.reduced) divideByVignetting(p.work.photo, v);
  // The first fit's notes are the last warnings (its stage ran just before): the refit's replace them.
  const size_t notes = std::min(ps.lighting.notes.size(), ps.warnings.size());
  ps.warnings.resize(ps.warnings.size() - notes);
  std::string again;  // the first fit's detail stands in the lighting stage's line
  if (Status st = fitTheLighting(p, again); !st) return st;
  detail += ", the light fit run again";
  return {};
}

std::string vignettingNotNeeded(const Preparation& p) {
  return p.doc.camera.vignetting.mode == VignettingKeys::Mode::None
             ? "camera.vignetting is \"none\" (the default)"
             : "";
}

Status sunsFromRatio(Preparation& p, std::string& detail) {
  sunsFromShadowRatio(p.ps, p.workPhoto(), p.workCamera(), p.lightMask, p.opt.sunsFromBounce);
  detail = countOf(p.ps.lighting.suns.size(), "sun");
  return {};
}

// The lights' positions and intensities against the photo's direct light (lighting/refine.h).
Status refineTheLights(Preparation& p, std::string& detail) {
  PreparedScene& ps = p.ps;
  LightRefineOptions ro = p.opt.refine;
  std::vector<LightRefineSpec> specs(p.lights.size());
  for (size_t i = p.doc.lights.size(); i < specs.size(); ++i) specs[i].lock = true;
  for (size_t i = 0, outline = 0; i < p.doc.lights.size(); ++i) {
    const LightKeys& l = p.doc.lights[i];
    specs[i].lock = p.locked(i);
    specs[i].positionWeight = l.positionWeight;
    specs[i].intensityWeight = l.intensityWeight;
    specs[i].refineSize = l.refineSize;
    specs[i].sizeWeight = l.sizeWeight;
    // An outlined light stays within its outline's uncertainty (working copy's pixels).
    if (l.kind == LightKeys::Kind::PolygonPx && outline < p.outlines.size() && ro.holdOutlinedLights)
      specs[i].maxDisplacementM =
          outlineDisplacementBoundM(p.workCamera(), p.lights[i], p.toWork(p.outlines[outline]), ro);
    outline += l.kind == LightKeys::Kind::PolygonPx ? 1 : 0;
  }
  ro.seed += p.opt.seed;
  if (!ro.cancel) ro.cancel = p.opt.cancel;
  ro.nonMatteSurfaces = p.nonMatte;
  ro.sunBounce = ps.lighting.sunBounce;
  auto refined = refineLights(p.workCamera(), ps.geometry, ps.lighting.albedo, ps.lighting.direct,
                              usableDirect(ps.lighting, p.lightMask), ps.lighting.lights, specs,
                              ps.lighting.suns, ro);
  if (!refined) return p.cancelled() ? cancelledError() : refined.error();
  ps.refinement = std::move(*refined);
  ps.lighting.lights = ps.refinement.lights;
  ps.lighting.suns = ps.refinement.suns;
  for (const auto& n : ps.refinement.notes) ps.warnings.push_back("light refinement: " + n);
  p.refined = true;
  p.refinedMove = largestLightMove(ps.initialLights, ps.lighting.lights);
  // The refinement fits the intensities to the direct light alone; the refit fits them again
  // with the room's albedo and indirect light. A refinement that hardly moved the lights is
  // not refitted (PrepareOptions::refitMinLightMove), so its intensities are not kept either.
  if (movedTooLittleToRefit(p)) ps.lighting.lights = ps.initialLights;
  const auto locked =
      std::count_if(specs.begin(), specs.end(), [](const LightRefineSpec& s) { return s.lock; });
  detail = std::to_string(specs.size() - size_t(locked)) + " of " + countOf(specs.size(), "light") +
           " refined, " + countOf(size_t(ps.refinement.evaluations), "evaluation") +
           (ps.refinement.stoppedByGuard    ? ", stopped by the time guard"
            : ps.refinement.stoppedByBudget ? ", stopped at the budget"
                                            : "");
  return {};
}

// The albedo-intensity split rests on the shape of each light's irradiance over the room
// (B = rho (L E + Gamma) is flat along rho / k, L k where E and Gamma look alike): with the
// refined positions, the radiances, Gamma and the albedo are estimated again.
Status refitTheLighting(Preparation& p, std::string& detail) {
  PreparedScene& ps = p.ps;
  const double move = p.refinedMove;
  // A locked light keeps its intensity too.
  std::vector<bool> fitAgain(p.estimated);
  for (size_t i = 0; i < fitAgain.size() && i < p.doc.lights.size(); ++i)
    fitAgain[i] = p.estimated[i] && !p.doc.lights[i].lock;
  // The same photo, camera, room and mask as the first estimate: its rays' hits are replayed
  // (they do not depend on the lights), and only the radiances along them computed again.
  LightingOptions lo = p.lightingOptions;
  lo.reuseRays = ps.lighting.rays;
  lo.deferDecomposition = true;  // made only when the refit is kept
  auto again = estimateLighting(p.workPhoto(), p.workCamera(), ps.geometry, ps.lighting.lights, fitAgain,
                                p.lightMask, ps.lighting.suns, lo);
  if (!again) return p.cancelled() ? cancelledError() : again.error();
  p.stageSteps = stepsOf(*again);  // the refit's work, whichever fit is kept
  // ps.lighting is still the first estimate's fit (the refinement changed only its lights).
  const double first = ps.lighting.fitRmsLog;
  if (p.opt.keepBetterFit && refitFitsWorse(first, again->fitRmsLog, p.opt.keepBetterFitTolerance)) {
    // A routine self-check, not something the user must act on: the stage's detail (the
    // report, --verbose, the studio's log) says it, the warnings do not.
    char buf[240];
    std::snprintf(buf, sizeof buf,
                  "lights moved by at most %.1f %% of their size; the first estimate fits the photo "
                  "better (log residual %.5f against %.5f) and is kept; the refit took ",
                  100 * move, ps.lighting.fitRmsLog, again->fitRmsLog);
    ps.lighting.lights = ps.initialLights;
    ps.lighting.suns = ps.initialSuns;
    detail = buf + gatherText(*again);
    return {};
  }
  ps.lighting = std::move(*again);
  for (const auto& n : ps.lighting.notes) ps.warnings.push_back("lighting (refit): " + n);
  const char* prefix = "lighting (refit): ";
  if (Status st = decomposeUnlessDeferred(p, p.deferLastDecomposition, "lighting refit", prefix); !st)
    return st;
  p.stageSteps = stepsOf(ps.lighting);
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "lights moved by at most %.1f %% of their size; the refit is kept (log residual "
                "%.5f against the first estimate's %.5f), ",
                100 * move, ps.lighting.fitRmsLog, first);
  detail = buf + gatherText(ps.lighting);
  return {};
}

// The surface each photo pixel's centre shows, from the working copy's (`working`): where the
// working pixel and its eight neighbours show one surface, that surface; elsewhere (edges
// between surfaces) the pixel's own ray is cast. A surface narrower than a working pixel that
// no working pixel centre hits is not seen.
// Per working pixel: whether it and its eight neighbours (clamped at the borders) show one surface.
std::vector<unsigned char> uniformNeighbourhoods(const std::vector<int>& ids, int w, int h) {
  std::vector<unsigned char> uniform(ids.size(), 1);
  parallelFor(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < w; ++x) {
        const int id = ids[size_t(y) * w + x];
        bool same = true;
        for (int dy = -1; dy <= 1 && same; ++dy)
          for (int dx = -1; dx <= 1 && same; ++dx) {
            const int qx = std::clamp(x + dx, 0, w - 1), qy = std::clamp(y + dy, 0, h - 1);
            same = ids[size_t(qy) * w + qx] == id;
          }
        uniform[size_t(y) * w + x] = same;
      }
  });
  return uniform;
}

std::vector<int> firstSurfacesAtPhotoSize(const Preparation& p, const std::vector<int>& working) {
  const int W = p.ps.photo.linearRgb.width, H = p.ps.photo.linearRgb.height;
  const int w = p.work.photo.width, h = p.work.photo.height;
  std::vector<int> ids(size_t(W) * H, -1);
  if (working.size() != size_t(w) * h) return ids;
  const RoomTracer tracer(p.ps.geometry);
  const Camera& camera = p.ps.camera;
  const std::vector<unsigned char> uniform = uniformNeighbourhoods(working, w, h);
  parallelFor(tbb::blocked_range<int>(0, H), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      const int ly = std::min(h - 1, int((y + 0.5) * p.work.sy));
      for (int x = 0; x < W; ++x) {
        const int lx = std::min(w - 1, int((x + 0.5) * p.work.sx));
        if (uniform[size_t(ly) * w + lx]) {
          ids[size_t(y) * W + x] = working[size_t(ly) * w + lx];
          continue;
        }
        const auto hit = tracer.intersect(camera.rayThroughPixel(Vec2(x + 0.5, y + 0.5)), 1e-6);
        if (hit) ids[size_t(y) * W + x] = hit->surfaceId;
      }
    }
  });
  return ids;
}

Status lightingAtPhotoSize(Preparation& p, std::string& detail) {
  LightingEstimate& L = p.ps.lighting;
  const ImageF& photo = p.ps.photo.linearRgb;
  const ImageF& low = p.work.photo;
  const auto t = Clock::now();
  // The maps share the upsampling's weights (they depend on the photo only).
  std::vector<ImageF*> maps{&L.albedo};
  if (!L.suns.empty()) maps.push_back(&L.physicalAlbedo);
  maps.erase(
      std::remove_if(maps.begin(), maps.end(),
                     [&](const ImageF* m) { return m->width != low.width || m->height != low.height; }),
      maps.end());
  JointBilateralOptions ratio;
  ratio.ratio = true;
  std::vector<ImageF> up =
      jointBilateralUpsample(std::vector<const ImageF*>(maps.begin(), maps.end()), low, photo, ratio);
  for (size_t k = 0; k < maps.size(); ++k) {
    // Albedos in [0, 1]; the direct light and the fit's albedo >= 0 (NaN to 0).
    const float highest = maps[k] == &L.albedo ? 1.f : std::numeric_limits<float>::max();
    for (float& v : up[k].data) v = v > 0 ? std::min(v, highest) : 0.f;
    *maps[k] = std::move(up[k]);
  }
  if (!L.suns.empty() && !L.gathered.empty())
    L.gathered = resizeImage(L.gathered, photo.width, photo.height);
  if (p.cancelled()) return cancelledError();
  const double mapsSeconds = secondsSince(t);
  L.firstSurfacePerPixel = firstSurfacesAtPhotoSize(p, L.firstSurfacePerPixel);
  char buf[120];
  std::snprintf(buf, sizeof buf, "from %d x %d px: maps %.2f s, surfaces cast %.2f s", low.width,
                low.height, mapsSeconds, secondsSince(t) - mapsSeconds);
  detail = buf;
  return {};
}

// The render scene: the room with its projected albedo and the photo's radiance for bounces,
// the lights and suns.
Status buildRenderScene(Preparation& p, std::string&) {
  const PreparedScene& ps = p.ps;
  RenderScene& rs = p.ps.renderScene;
  const int W = ps.photo.linearRgb.width, H = ps.photo.linearRgb.height;
  rs.camera = ps.camera;
  rs.room = ps.geometry;
  rs.roomMaterials = std::move(p.roomMaterials);
  rs.lights = ps.lighting.lights;
  rs.suns = ps.lighting.suns;
  rs.roomAlbedo.camera = ps.camera;
  rs.roomAlbedo.albedo = ps.lighting.albedo;
  rs.roomAlbedo.surfaceMean = ps.lighting.surfaceMeanAlbedo;
  // The surface each pixel shows: the lighting stage cast those rays already.
  rs.roomAlbedo.firstSurfacePerPixel = ps.lighting.firstSurfacePerPixel;
  // Bounces that reach a room point the photo shows take the photo's radiance there (not the
  // light outlines: their light is the lights' own; a clipped sunlit patch takes the model's).
  rs.roomAlbedo.photoRadiance =
      radianceForBounces(ps.photo.linearRgb, ps.camera, ps.geometry, ps.lighting);
  rs.roomAlbedo.photoRadianceUsable.assign(size_t(W) * H, 1);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (p.photoLightMask().at(x, y) > 0.5f) rs.roomAlbedo.photoRadianceUsable[size_t(y) * W + x] = 0;
  return {};
}

Status placeTheObjects(Preparation& p, std::string& detail) {
  auto placed = placeObjects(p.doc.objects, p.ps.geometry, p.ps.camera, p.meshes);
  if (!placed) return placed.error();
  p.ps.renderScene.objects = std::move(placed->objects);
  p.ps.placements = std::move(placed->placements);
  detail = countOf(p.ps.placements.size(), "object");
  return {};
}

// The photo's grain, last: in the units ps.photo.linearRgb ended in. A linear photo (EXR, HDR)
// is taken as noise-free: its pixels are radiances, not a camera's encoded output.
Status measureGrain(Preparation& p, std::string& detail) {
  p.ps.photoNoise = photoNoiseOf(p.ps.photo);
  detail = p.ps.photoNoise.empty() ? "none" : "";
  return {};
}

// One stage of prepareScene(): its name (StageRecord::name), the progress label it starts
// (PrepareOptions::progress; null: none), why a scene would not need it (null: every scene does)
// and its work, which may describe itself in `detail`.
struct Stage {
  const char* name;
  const char* progress;
  std::string (*notNeeded)(const Preparation&);
  Status (*run)(Preparation&, std::string& detail);
  // The image it works at (StageRecord::workingWidth): none, the photo's size, the working copy.
  enum class At { None, Photo, Working } at = At::None;
};

// Wall and CPU seconds since it was made, for a stage's record.
struct StageClock {
  Clock::time_point start = Clock::now();
  double cpuStart = processCpuSeconds();
  void stamp(StageRecord& record) const {
    record.seconds = secondsSince(start);
    record.cpuSeconds = processCpuSeconds() - cpuStart;
  }
};

// Runs `stage` when the scene needs it and records its seconds, or records why it was skipped.
Status runStage(const Stage& stage, Preparation& p) {
  StageRecord record;
  record.name = stage.name;
  if (stage.notNeeded) record.reason = stage.notNeeded(p);
  if (record.reason.empty()) {
    if (stage.progress && p.opt.progress) p.opt.progress(stage.progress, 0);
    const StageClock clock;
    p.stagePx = {0, 0};
    p.stageSteps.clear();
    if (Status st = stage.run(p, record.detail); !st) return st;
    record.steps = std::move(p.stageSteps);
    record.ran = true;
    clock.stamp(record);
    const ImageF& photo = p.ps.photo.linearRgb;
    std::array<int, 2> px = p.stagePx;
    if (px[0] == 0 && stage.at == Stage::At::Photo) px = {photo.width, photo.height};
    if (px[0] == 0 && stage.at == Stage::At::Working) px = {p.workPhoto().width, p.workPhoto().height};
    record.workingWidth = px[0];
    record.workingHeight = px[1];
    record.reducedImage = px[0] > 0 && (px[0] != photo.width || px[1] != photo.height);
  }
  p.ps.stages.push_back(std::move(record));
  return p.cancelled() ? Status(cancelledError()) : Status();
}

using At = Stage::At;

// The stages of prepareScene(), in three runs. The photo, loaded once:
const Stage kLoadStages[] = {{"photo", "photo", nullptr, loadPhoto, At::Photo}};

// Those whose work depends on the camera response (from the linearised photo on; the camera
// estimate finds its edges in it too): the response check runs them a second time, with sRGB.
const Stage kResponseStages[] = {
    {"response", nullptr, nullptr, chooseResponse, At::Photo},
    {"working copy", nullptr, nullptr, makeWorkingCopy, At::Working},
    {"camera", "camera", nullptr, findCamera, At::Photo},
    {"layout", "room", nullptr, boxFromBackWall},
    {"occluders", nullptr, noOccluders, occluderMattes, At::Photo},
    {"surfaces", nullptr, noSurfaces, buildSurfaces},
    {"room", nullptr, nullptr, assembleRoom},
    {"lights", "lighting", nullptr, lightsFromMarks, At::Working},
    {"shafts", nullptr, noShafts, sunsFromShafts, At::Working},
    {"lighting", nullptr, nullptr, estimateTheLighting, At::Working},
    {"vignetting", nullptr, vignettingNotNeeded, devignetteThePhoto, At::Working},
    {"sun ratio", nullptr, sunRatioNotNeeded, sunsFromRatio, At::Working},
    {"refine", "refine", refineNotNeeded, refineTheLights, At::Working},
    {"lighting refit", "lighting", refitNotNeeded, refitTheLighting, At::Working},
};

// After the response check, once, for the response it kept:
const Stage kSceneStages[] = {
    {"photo size", "objects", photoSizeNotNeeded, lightingAtPhotoSize, At::Photo},
    {"render scene", "objects", nullptr, buildRenderScene, At::Photo},
    {"objects", nullptr, noObjects, placeTheObjects},
    {"grain", nullptr, nullptr, measureGrain, At::Photo},
};

// `stages` in turn, each recorded.
Status runStages(std::span<const Stage> stages, Preparation& p) {
  for (const Stage& stage : stages) {
    if (Status st = runStage(stage, p); !st) return st;
    // The lighting's rays (tens of MB) serve only its refit: dropped before the photo-size maps.
    if (stage.run == refitTheLighting) p.ps.lighting.rays.reset();
  }
  return {};
}

// The stages after the response check, then the last progress report.
Expected<PreparedScene> finishScene(Preparation& p) {
  if (Status st = runStages(kSceneStages, p); !st) return st.error();
  if (p.opt.progress) p.opt.progress("objects", 1);
  return std::move(p.ps);
}

bool isCancelled(const Error& e) { return e.reason == cancelledError().reason; }

// The decision's start when the light fit's check takes the estimate's curve away (`why` below
// starts so).
const std::string kRefusedByTheLightFit = "kept sRGB: ";
const std::string kTheLightFitsResidual = "the light fit's residual";

// The check's reason: both light fits' residuals (sRGB's NaN when its preparation failed).
std::string checkWhy(const CameraResponse& curve, double withCurve, double withSrgb) {
  char buf[320];
  std::snprintf(buf, sizeof buf, "%s with the fitted %s is %.4f, with sRGB %.4f",
                kTheLightFitsResidual.c_str(), curve.describe().c_str(), withCurve, withSrgb);
  return buf;
}
std::string checkWhy(const Preparation& curved, double withSrgb) {
  return checkWhy(curved.ps.response, curved.ps.lighting.fitResidualRelative, withSrgb);
}

// Whether the curve explains the photo at least as well as sRGB (a residual that is not
// finite never wins; sRGB's is NaN when its preparation failed).
bool keepsTheCurve(const Preparation& curved, double withSrgb) {
  return !refitFitsWorse(withSrgb, curved.ps.lighting.fitResidualRelative,
                         curved.opt.responseFitTolerance);
}

// --- The quick comparison on small copies (ResponseQuickCheck) ---

// The log of the curve's residual over sRGB's widened by the tolerance (NaN: not told).
double quickLogRatio(double withCurve, double withSrgb, double tolerance) {
  const double tol = std::isnan(tolerance) ? 0.0 : std::max(0.0, tolerance);
  const double r = std::log(withCurve) - std::log(withSrgb) - std::log1p(tol);
  const bool told = withCurve > 0 && withSrgb > 0 && std::isfinite(withCurve) && std::isfinite(withSrgb);
  return told && std::isfinite(r) ? r : std::nan("");
}

// Its result: both copies' light fit residuals, the copies' size and the stages it ran as steps.
struct QuickCheck {
  double withCurve = std::nan(""), withSrgb = std::nan("");
  std::array<int, 2> copyPx{};
  std::vector<StageStep> steps;
  double seconds = 0, cpuSeconds = 0;
  FoundCamera curveCamera, srgbCamera;  // each copy's camera, for its response's full size
  double logRatio(double tolerance) const { return quickLogRatio(withCurve, withSrgb, tolerance); }
  int verdict(const PrepareOptions& opt) const {
    return quickResponseVerdict(withCurve, withSrgb, opt.responseFitTolerance, opt.responseQuick.margin);
  }
  bool decides(const PrepareOptions& opt) const { return verdict(opt) != 0; }
  bool keepsTheCurve(const PrepareOptions& opt) const { return verdict(opt) > 0; }
};

// The "response check" record: the response it kept and why (`kept`, `why`), the stages it ran
// (the copies', then those run again with sRGB: `again`) as its steps, and its own seconds since
// `clock` plus the copies'.
StageRecord checkRecord(bool kept, const std::string& why, const QuickCheck& quick,
                        const std::vector<StageStep>& again, const StageClock& clock,
                        const PrepareOptions& opt) {
  StageRecord record;
  record.name = "response check";
  record.ran = true;
  record.detail = std::string(kept ? "the curve kept: " : "sRGB kept: ") + why;
  char buf[200];
  const double r = quick.logRatio(opt.responseFitTolerance);
  if (quick.copyPx[0] > 0)
    std::snprintf(buf, sizeof buf, "; on %d x %d copies %.4f against %.4f, log ratio %.3f %s %.3f",
                  quick.copyPx[0], quick.copyPx[1], quick.withCurve, quick.withSrgb, r,
                  quick.decides(opt) ? "beyond" : "within", opt.responseQuick.margin);
  else std::snprintf(buf, sizeof buf, "; no quick comparison");
  record.detail += buf;
  record.steps = quick.steps;
  record.steps.insert(record.steps.end(), again.begin(), again.end());
  clock.stamp(record);
  record.seconds += quick.seconds;
  record.cpuSeconds += quick.cpuSeconds;
  return record;
}
StageRecord checkRecord(const Preparation& curved, double withSrgb, const QuickCheck& quick,
                        const std::vector<StageStep>& again, const StageClock& clock) {
  return checkRecord(keepsTheCurve(curved, withSrgb), checkWhy(curved, withSrgb), quick, again, clock,
                     curved.opt);
}

// The stages a preparation ran, as steps (each name after `prefix`).
std::vector<StageStep> stepsOf(const std::vector<StageRecord>& stages, const std::string& prefix = "") {
  std::vector<StageStep> out;
  for (const StageRecord& r : stages)
    if (r.ran) out.push_back({prefix + r.name, r.seconds, r.cpuSeconds});
  return out;
}

// The response stage alone, and the response stages after it.
std::span<const Stage> theResponseStage() { return std::span<const Stage>(kResponseStages).first(1); }
std::span<const Stage> afterTheResponse() { return std::span<const Stage>(kResponseStages).subspan(1); }

SceneDoc withSrgb(const SceneDoc& doc) {
  SceneDoc srgbDoc = doc;
  srgbDoc.camera.response = {ResponseKeys::Mode::Srgb};
  return srgbDoc;
}

// The options of the copies' preparations: the working copy at ResponseQuickCheck::maxPixels,
// the lights as marked, no progress reports and no check of their own.
PrepareOptions quickOptionsOf(const PrepareOptions& opt) {
  PrepareOptions q = opt;
  q.progress = nullptr;
  q.workingMaxPixels = opt.responseQuick.maxPixels;
  q.refineLights = opt.responseQuick.refineLights;
  q.checkResponseByLightFit = false;
  return q;
}

// One response's copy, prepared: whether its stages ran, its light fit's residual (NaN when a
// stage failed), its stages as the check's steps, its size and the camera its camera stage found.
struct CopyFit {
  Status ran;
  double residual = std::nan("");
  std::vector<StageStep> steps;
  std::array<int, 2> copyPx{};
  FoundCamera camera;
};

// One response's copy prepared through `stages` (from the photo `q` holds), its stages named
// after `label`.
CopyFit quickFit(Preparation& q, std::span<const Stage> stages, const std::string& label) {
  q.lightingOptions.objective = false;
  q.lightingOptions.fitPixels = q.opt.responseQuick.fitPixels;
  q.lightingOptions.maxPasses = q.opt.responseQuick.maxPasses;
  q.lightingOptions.fitFunctionTolerance = q.opt.responseQuick.fitTolerance;
  q.handsCameraOn = true;
  CopyFit out;
  out.ran = runStages(stages, q);
  out.steps = stepsOf(q.ps.stages, label);
  if (out.ran) {
    out.residual = q.ps.lighting.fitResidualRelative;
    out.copyPx = q.ps.workingPx;
  }
  out.camera = q.camera;
  return out;
}

// One copy prepared from `photo` (quickFit), lent to it and given back: no stage of a copy
// changes the photo but the vignetting, which divides it in place (then the copy gets its own).
// At 12 MP a copy of the photo is 144 MB written and freed per response.
CopyFit quickFitOn(LoadedImage& photo, Preparation& q, const std::string& label) {
  const bool lend = !vignettingNotNeeded(q).empty();
  if (lend) q.ps.photo = std::move(photo);
  else q.ps.photo = photo;
  CopyFit fit = quickFit(q, afterTheResponse(), label);
  if (lend) photo = std::move(q.ps.photo);
  return fit;
}

// The names of the step that times both copies together (quickCheck).
const char* const kCopiesSideBySide = "both copies, side by side";
const char* const kCopiesOneAfterTheOther = "both copies, one after the other";

// Whether the check may prepare its two candidates (the copies, or the full check's) side by
// side: not when the preparation is held to one thread (PrepareOptions::threads 1), which
// prepares them one after the other.
bool candidatesSideBySide(const PrepareOptions& opt) { return opt.threads != 1; }

// The quick comparison of `curved`, whose response stage fitted a curve: its decoded photo with
// the curve, and the photo as loaded with sRGB, each lent to a copy's preparation, the two side
// by side (runAlongside: they share nothing they write, as the full check's candidates) or,
// held to one thread, one after the other. Each copy's camera is kept for the full-size
// preparation of its response. Fails only when cancelled.
Expected<QuickCheck> quickCheck(Preparation& curved) {
  QuickCheck quick;
  if (!(curved.opt.responseQuick.maxPixels > 0)) return quick;
  const StageClock clock;
  const PrepareOptions qopt = quickOptionsOf(curved.opt);
  Preparation curve(curved.doc, qopt);
  curve.ps.response = curved.ps.response;
  const SceneDoc srgbDoc = withSrgb(curved.doc);
  Preparation srgb(srgbDoc, qopt);
  srgb.ps.response = CameraResponse::srgb();  // the photo as loaded: decoded as sRGB
  CopyFit a, b;
  const auto curveCopy = [&] { a = quickFitOn(curved.ps.photo, curve, "copy, curve: "); };
  const auto srgbCopy = [&] { b = quickFitOn(*curved.photoAsLoaded, srgb, "copy, sRGB: "); };
  const bool sideBySide = candidatesSideBySide(curved.opt);
  if (sideBySide) runAlongside(curveCopy, srgbCopy);
  else {
    curveCopy();
    if (a.ran || !isCancelled(a.ran.error())) srgbCopy();
  }
  for (const CopyFit* fit : {&a, &b})
    if (!fit->ran && isCancelled(fit->ran.error())) return fit->ran.error();
  quick.withCurve = a.residual, quick.withSrgb = b.residual;
  quick.copyPx = b.ran ? b.copyPx : a.copyPx;
  quick.steps = a.steps;
  quick.steps.insert(quick.steps.end(), b.steps.begin(), b.steps.end());
  quick.curveCamera = a.camera, quick.srgbCamera = b.camera;
  StageRecord timing;
  clock.stamp(timing);
  quick.steps.push_back(
      {sideBySide ? kCopiesSideBySide : kCopiesOneAfterTheOther, timing.seconds, timing.cpuSeconds});
  quick.seconds = timing.seconds;
  quick.cpuSeconds = timing.cpuSeconds;
  return quick;
}

// After the response check's verdict: the decomposition the kept response's preparation left
// (Preparation::deferLastDecomposition), its time and step added to the stage that made it.
Status decomposeTheKept(Preparation& p) {
  if (!p.ps.lighting.pendingDecomposition) return {};
  const StageClock clock;
  if (Status st = finishTheDecomposition(p, p.pendingNotes); !st) return st;
  StageRecord spent;
  clock.stamp(spent);
  for (auto it = p.ps.stages.rbegin(); it != p.ps.stages.rend(); ++it)
    if (it->name == p.pendingStage && it->ran) {
      it->seconds += spent.seconds;
      it->cpuSeconds += spent.cpuSeconds;
      it->steps = stepsOf(p.ps.lighting);
      break;
    }
  return {};
}

// The copies kept the curve: it is prepared alone.
Expected<PreparedScene> finishWithTheCurve(Preparation& curved, const QuickCheck& quick) {
  curved.photoAsLoaded.reset();
  curved.camera = quick.curveCamera;
  if (Status st = runStages(afterTheResponse(), curved); !st) return st.error();
  const StageClock now;  // the record's seconds: the copies'
  curved.ps.stages.push_back(checkRecord(
      true, checkWhy(curved.ps.response, quick.withCurve, quick.withSrgb), quick, {}, now, curved.opt));
  return finishScene(curved);
}

// The scene prepared with sRGB in place of the estimated curve `curved` used: the estimate and
// the scene file's "auto" kept, the decision and a warning saying why.
PreparedScene srgbInsteadOfTheCurve(PreparedScene&& srgb, PreparedScene&& curved,
                                    const std::string& why) {
  srgb.doc = std::move(curved.doc);
  srgb.responseEstimate = std::move(curved.responseEstimate);
  srgb.responseEstimate->decision = kRefusedByTheLightFit + why;
  srgb.responseEstimate->response = CameraResponse::srgb();
  srgb.warnings.push_back("camera response: the estimated curve was not used (" + why + "); using sRGB");
  return std::move(srgb);
}

// sRGB kept: the stages after the refit run on its preparation, after the curve's records (the
// stages that ran first) and the check's.
Expected<PreparedScene> finishWithSrgb(Preparation& curved, Preparation& srgb, const QuickCheck& quick,
                                       const StageClock& clock, const StageStep& both) {
  const double withSrgb = srgb.ps.lighting.fitResidualRelative;
  if (Status st = decomposeTheKept(srgb); !st) return st.error();
  std::vector<StageStep> again = stepsOf(srgb.ps.stages);
  again.push_back(both);
  srgb.ps.stages = curved.ps.stages;
  srgb.ps.stages.push_back(checkRecord(curved, withSrgb, quick, again, clock));
  Expected<PreparedScene> done = finishScene(srgb);
  if (!done) return done;
  return srgbInsteadOfTheCurve(std::move(*done), std::move(curved.ps), checkWhy(curved, withSrgb));
}

// The names of blockStep's step.
const char* const kCandidatesSideBySide = "both candidates, side by side";
const char* const kCandidatesOneAfterTheOther = "both candidates, one after the other";

// The options of the sRGB candidate the full check prepares beside the curve: no progress
// reports (they belong to the calling thread, where the curve's stages run).
PrepareOptions alongsideOptionsOf(const PrepareOptions& opt) {
  PrepareOptions q = opt;
  q.progress = nullptr;
  return q;
}

// The full check's two candidates, independent of each other: the curve's stages after the
// response (on the calling thread, with its progress reports) and sRGB's from the response on
// (`ranSrgb`), side by side (runAlongside) or, held to one thread, one after the other as
// before. Each writes only its own Preparation: they share the scene file and the options
// (read only; the cancel token is atomic) and nothing else. The curve's failure is the
// preparation's (then, one after the other, sRGB is not prepared at all).
Status prepareBothCandidates(Preparation& curved, Preparation& srgb, Status& ranSrgb) {
  Status ranCurve;
  const auto curve = [&] { ranCurve = runStages(afterTheResponse(), curved); };
  const auto other = [&] { ranSrgb = runStages(kResponseStages, srgb); };
  if (candidatesSideBySide(curved.opt)) {
    runAlongside(curve, other);
  } else {
    curve();
    if (ranCurve) other();
  }
  return ranCurve;
}

// The seconds the stage records from `first` on took, summed (wall and CPU).
StageStep secondsOf(const std::vector<StageRecord>& stages, size_t first) {
  StageStep sum;
  for (size_t i = first; i < stages.size(); ++i)
    sum.seconds += stages[i].seconds, sum.cpuSeconds += stages[i].cpuSeconds;
  return sum;
}

// The check's own clock when the curve's stages ran inside it (`curveStages`): started that
// much later, so the curve's records and the check's add up to the preparation's seconds. Side
// by side the curve's records hold the process's CPU while they ran, sRGB's beside them too.
StageClock withoutTheCurve(StageClock clock, const StageStep& curveStages) {
  clock.start +=
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(curveStages.seconds));
  clock.cpuStart += curveStages.cpuSeconds;
  return clock;
}

// The check's step that times both candidates together, from `block` (started before them) to
// now: side by side, each candidate's stage records count the process's CPU while they ran, the
// other candidate's included, so this is the one figure that covers the two without overlap.
StageStep blockStep(const StageClock& block, bool sideBySide) {
  StageRecord spent;
  block.stamp(spent);
  return {sideBySide ? kCandidatesSideBySide : kCandidatesOneAfterTheOther, spent.seconds,
          spent.cpuSeconds};
}

// PrepareOptions::checkResponseByLightFit: `curved` (its response stage fitted a curve) prepared
// up to the refit with the curve, and the photo as loaded prepared up to the refit with sRGB,
// side by side (prepareBothCandidates); the stages after the refit run once, for the one whose
// light fit explains the photo better. When sRGB's preparation fails the curve stands. The
// objects are placed only in the kept response's room: the rejected one's camera and box never
// refuse them. Both last lighting estimates wait for the verdict to be decomposed.
Expected<PreparedScene> checkTheCurveByTheLightFit(Preparation& curved, const QuickCheck& quick) {
  const StageClock block;
  const SceneDoc srgbDoc = withSrgb(curved.doc);
  const PrepareOptions srgbOpt = alongsideOptionsOf(curved.opt);
  Preparation srgb(srgbDoc, srgbOpt);
  MeshCache meshes;
  curved.meshes = srgb.meshes = &meshes;
  srgb.ps.photo = std::move(*curved.photoAsLoaded);
  curved.photoAsLoaded.reset();
  curved.camera = quick.curveCamera, srgb.camera = quick.srgbCamera;
  curved.deferLastDecomposition = srgb.deferLastDecomposition = true;
  const size_t curveFirst = curved.ps.stages.size();
  Status ran;
  if (Status st = prepareBothCandidates(curved, srgb, ran); !st) return st.error();
  if (!ran && isCancelled(ran.error())) return ran.error();
  const StageClock clock = withoutTheCurve(block, secondsOf(curved.ps.stages, curveFirst));
  const StageStep both = blockStep(block, candidatesSideBySide(curved.opt));
  std::vector<StageStep> again = stepsOf(srgb.ps.stages);
  again.push_back(both);
  const double residual = srgb.ps.lighting.fitResidualRelative;
  const bool srgbFitsBetter = ran && !keepsTheCurve(curved, residual);
  if (srgbFitsBetter) {
    Expected<PreparedScene> kept = finishWithSrgb(curved, srgb, quick, clock, both);
    if (kept || isCancelled(kept.error())) return kept;
  }
  // sRGB's preparation failed (before the refit, or after it with sRGB kept): NaN.
  const double withSrgb = ran && !srgbFitsBetter ? residual : std::nan("");
  curved.ps.stages.push_back(checkRecord(curved, withSrgb, quick, again, clock));
  if (Status st = decomposeTheKept(curved); !st) return st.error();
  return finishScene(curved);
}

// The copies kept sRGB: the photo as loaded is prepared with sRGB alone (its response stage
// counted in the check), after the curve's photo and response records. When that preparation
// fails the curve is prepared after all, as the full check does.
Expected<PreparedScene> prepareSrgbInstead(Preparation& curved, QuickCheck quick) {
  const SceneDoc srgbDoc = withSrgb(curved.doc);
  Preparation srgb(srgbDoc, curved.opt);
  srgb.ps.photo = std::move(*curved.photoAsLoaded);
  curved.photoAsLoaded.reset();
  srgb.camera = quick.srgbCamera;
  Status ran = runStages(theResponseStage(), srgb);
  const std::vector<StageStep> decode = stepsOf(srgb.ps.stages, "sRGB: ");
  quick.steps.insert(quick.steps.end(), decode.begin(), decode.end());
  for (const StageStep& step : decode)
    quick.seconds += step.seconds, quick.cpuSeconds += step.cpuSeconds;
  srgb.ps.stages = curved.ps.stages;
  if (ran) ran = runStages(afterTheResponse(), srgb);
  const std::string why = checkWhy(curved.ps.response, quick.withCurve, quick.withSrgb);
  if (ran) {
    const StageClock now;  // the record's seconds: the copies' and the sRGB decode
    srgb.ps.stages.push_back(checkRecord(false, why, quick, {}, now, curved.opt));
    Expected<PreparedScene> done = finishScene(srgb);
    if (done) return srgbInsteadOfTheCurve(std::move(*done), std::move(curved.ps), why);
    ran = done.error();
  }
  if (isCancelled(ran.error())) return ran.error();
  quick.withSrgb = std::nan("");
  return finishWithTheCurve(curved, quick);
}

// After the curve's response stage, when PrepareOptions::checkResponseByLightFit checks it: the
// copies first (ResponseQuickCheck), then the response they keep alone, or both up to the refit.
Expected<PreparedScene> prepareCheckingTheCurve(Preparation& curved) {
  Expected<QuickCheck> quick = quickCheck(curved);
  if (!quick) return quick.error();
  if (quick->decides(curved.opt))
    return quick->keepsTheCurve(curved.opt) ? finishWithTheCurve(curved, *quick)
                                            : prepareSrgbInstead(curved, *quick);
  return checkTheCurveByTheLightFit(curved, *quick);
}

}  // namespace

bool curveRefusedByTheLightFit(const ResponseEstimate& estimate) {
  return estimate.decision.rfind(kRefusedByTheLightFit + kTheLightFitsResidual, 0) == 0;
}

Expected<PreparedScene> prepareScene(const SceneDoc& doc, const PrepareOptions& opt) {
  Preparation p(doc, opt);
  if (Status st = runStages(kLoadStages, p); !st) return st.error();
  if (Status st = runStages(theResponseStage(), p); !st) return st.error();
  if (p.photoAsLoaded) return prepareCheckingTheCurve(p);
  if (Status st = runStages(afterTheResponse(), p); !st) return st.error();
  return finishScene(p);
}

PhotoNoise photoNoiseOf(const LoadedImage& photo) {
  if (!photo.wasSrgbEncoded)
    return PhotoNoise{{}, 0, 0, {}, {"a linear photo (EXR, HDR) gets no grain"}};
  NoiseMeasureOptions o;
  o.maxPatches = kGrainMaxPatches;
  return measurePhotoNoise(photo.linearRgb, o);
}

ImageF compositeOf(const PreparedScene& scene, const RenderFrame& frame, bool withGrain) {
  const bool grain = withGrain && scene.doc.render.grain;
  return compositeOf(scene.photo.linearRgb, scene.doc.render.exposure, frame,
                     grain ? &scene.photoNoise : nullptr, scene.doc.render.seed, nullptr,
                     &scene.renderScene.roomAlbedo.photoRadiance, scene.vignetting);
}

const CameraResponse* outputResponseOf(const PreparedScene& scene) {
  // A linear (EXR/HDR) photo's composite is written as sRGB to 8-bit files, as it always was.
  const bool linearPhoto = scene.response.family() == ResponseFamily::Linear &&
                           !scene.photo.wasSrgbEncoded;
  return linearPhoto ? nullptr : &scene.response;
}

int quickResponseVerdict(double withCurve, double withSrgb, double tolerance, double margin) {
  const double r = quickLogRatio(withCurve, withSrgb, tolerance);
  if (std::isnan(margin) || !(std::abs(r) > std::max(0.0, margin))) return 0;  // a tie never decides
  return r < 0 ? 1 : -1;
}

bool refitFitsWorse(double before, double after, double tolerance) {
  // before * (1 + tol) is infinite for an infinite tolerance: every finite refit is kept.
  if (!std::isfinite(after)) return std::isfinite(before);
  const double tol = std::isnan(tolerance) ? 0.0 : std::max(0.0, tolerance);
  return std::isfinite(before) && after > before * (1 + tol);
}

double largestLightMove(const std::vector<AreaLight>& before, const std::vector<AreaLight>& after) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (before.size() != after.size()) return inf;
  double largest = 0;
  for (size_t j = 0; j < before.size(); ++j) {
    const double moved = cornerMoveM(before[j], after[j]);
    if (!std::isfinite(moved)) return inf;
    const double size = std::sqrt(before[j].area());
    if (moved > 0) largest = std::max(largest, size > 0 && std::isfinite(size) ? moved / size : inf);
  }
  return largest;
}

}  // namespace inlay
