// What the renderer renders: the room (surfaces with the photo's albedo projected onto them),
// its lights, and the inserted objects. Plain data, built by the host (the engine pipeline),
// copied into a PathTracer. Units: metres; radiance in the photo's linear units (1.0 = the
// radiance that shows as a pure white pixel at exposure 0).
#pragma once

#include "inlay/modeling/camera.h"
#include "inlay/modeling/geometry.h"
#include "inlay/modeling/image.h"
#include "inlay/modeling/mesh.h"

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace inlay {

// Glossy is a dielectric-coated base (plastic); Conductor a GGX metal; RoughGlass a GGX
// dielectric (frosted glass); Glass and Mirror are smooth.
struct Material {
  enum class Kind { Diffuse, Glossy, Mirror, Glass, Emissive, Conductor, RoughGlass };
  Kind kind = Kind::Diffuse;
  Vec3 albedo{0.8, 0.8, 0.8};  // Diffuse/Glossy: base colour; Mirror: reflectance;
                               // Conductor: reflectance at normal incidence (Schlick F0)
  double roughness = 0.3;      // Glossy, Conductor, RoughGlass (GGX alpha = roughness^2)
  double ior = 1.5;            // Glass, RoughGlass; Glossy's coat
  Vec3 emission{0, 0, 0};      // Emissive: radiance
};

// The room's reflectance as a projective texture: a world point on surface `s` that the camera
// sees (it projects into the photo onto a pixel whose first surface is `s`) takes that pixel's
// albedo; anything else (out of frame, behind the camera, hidden) takes the surface's mean.
struct ProjectedAlbedo {
  Camera camera;
  ImageF albedo;                          // W x H x 3, in [0,1], the photo's size
  std::vector<int> firstSurfacePerPixel;  // W*H surface ids (-1: none)
  std::vector<Vec3> surfaceMean;          // per surface id

  Vec3 lookup(int surfaceId, const Vec3& pointWorld) const;
  // The index (y * albedo.width + x) of the albedo pixel that shows `pointWorld` on surface
  // `surfaceId`; nullopt when the point is out of frame, behind the camera or hidden.
  std::optional<size_t> pixelShowing(int surfaceId, const Vec3& pointWorld) const;

  // The photo's own radiance (linear, W x H x 3, the photo's size) and where it may stand for a
  // room point's outgoing radiance (W x H, 1 = usable; light outlines are 0). Empty: every
  // bounce is path traced with the albedo instead.
  ImageF photoRadiance;
  std::vector<uint8_t> photoRadianceUsable;
  // The photo's radiance at a room point the camera sees on surface `surfaceId` (and where it
  // is usable); false otherwise.
  bool radianceAt(int surfaceId, const Vec3& pointWorld, Vec3* radiance) const;
  // lookup() and radianceAt() for a point whose pixelShowing() is already known (the tracer
  // projects each room hit once).
  Vec3 albedoAtPixel(int surfaceId, std::optional<size_t> pixel) const;
  bool radianceAtPixel(std::optional<size_t> pixel, Vec3* radiance) const;
  // Fills firstSurfacePerPixel by casting each pixel centre's ray into `geometry`.
  void computeFirstSurfaces(const SceneGeometry& geometry);
};

// A planar quad light, one-sided: it emits on the side of normal() = (c1 - c0) x (c3 - c0)
// normalised (corners in order around the quad).
struct AreaLight {
  std::array<Vec3, 4> cornersWorld;
  Vec3 radiance{1, 1, 1};
  Vec3 normal() const {
    return (cornersWorld[1] - cornersWorld[0]).cross(cornersWorld[3] - cornersWorld[0]).normalized();
  }
  double area() const {
    return 0.5 * ((cornersWorld[1] - cornersWorld[0]).cross(cornersWorld[2] - cornersWorld[0]).norm() +
                  (cornersWorld[2] - cornersWorld[0]).cross(cornersWorld[3] - cornersWorld[0]).norm());
  }
  Vec3 centre() const {
    return 0.25 * (cornersWorld[0] + cornersWorld[1] + cornersWorld[2] + cornersWorld[3]);
  }
};

// Sunlight through an opening: parallel light travelling along `travelDirection`, of strength
// `irradianceOverPi` (irradiance on a surface facing it, over pi, in the photo's units), present
// only in the beam that lands on the lit patch the photo shows. A point p is in the beam when
// p + t * travelDirection (t >= 0) meets `receiverPlane` where `litMask` (the photo's soft mask
// of the patch, read through `camera`) is > 0. An empty mask lights every point.
struct SunLight {
  Vec3 travelDirection{0, -1, 0};  // unit, the direction the light travels
  Vec3 irradianceOverPi{1, 1, 1};
  Vec4 receiverPlane{0, 1, 0, 0};  // (n, d): n . x + d = 0, the surface the patch lies on
  Camera camera;
  ImageF litMask;  // W x H x 1 in [0, 1]

  // In [0, 1]: how much of the beam reaches p (0 outside it).
  double beamAt(const Vec3& p) const;
};

struct InsertedObject {
  std::shared_ptr<const TriangleMesh> meshObject;  // object space, shared between copies
  Mat4 worldFromObject = Mat4::Identity();
  Material material;
  // A multi-material asset (a lamp's brass stand and its glowing shade): one material per
  // entry of meshObject->materials, chosen per triangle by meshObject->triangleMaterial; an
  // emissive part is a light. Empty (or the mesh has no per-triangle materials): `material`
  // everywhere.
  std::vector<Material> partMaterials;
};

struct RenderScene {
  Camera camera;
  SceneGeometry room;
  ProjectedAlbedo roomAlbedo;
  // Room surfaces the user marked as a real mirror or a glossy floor, by surface id (shorter
  // than room.surfaces or nullopt: Lambertian with the projected albedo). Glossy takes the
  // projected albedo as its base colour (its `albedo` is ignored); Mirror reflects `albedo`.
  // Only Glossy and Mirror are meant here; any other kind renders as the Lambertian default.
  std::vector<std::optional<Material>> roomMaterials;
  std::vector<AreaLight> lights;
  std::vector<SunLight> suns;
  std::vector<InsertedObject> objects;
};

}  // namespace inlay
