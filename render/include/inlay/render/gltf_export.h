// glTF 2.0 export of a render scene, so a user can go on in Blender or any glTF tool.
//
// What is written (world metres, y up, as glTF wants):
// - each room surface (occluder cards excepted: they are mattes, not geometry) as a mesh whose
//   albedo is baked from the projected photo albedo into a PNG base-colour texture (planar per
//   group of parallel triangles; hidden parts take the surface mean, as the renderer does);
// - each area light as a one-quad mesh with an emissive material (KHR_materials_emissive_strength:
//   emissive colour x strength = the light's radiance in the photo's units);
// - the camera (perspective; its principal point and pixel size in the camera's `extras`, since
//   glTF cannot say them);
// - each inserted object as a node (its worldFromObject matrix) over its object-space mesh, with
//   a metallic-roughness material: diffuse, glossy (KHR_materials_ior), metal/mirror (metallic 1),
//   glass and rough glass (KHR_materials_transmission + KHR_materials_ior), emissive; an object
//   with part materials (a multi-material asset) as one primitive per part.
// Suns (masked directional light) have no glTF equivalent and are left out with a warning.
//
// Radiance units carry over: an emissive strength of 1 shows as a pure white pixel at exposure
// 0, as in the photo. Files are written atomically; a .gltf gets its .bin and PNGs beside it
// (named after it), a .glb holds everything.
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/render/scene.h"

#include <string>
#include <vector>

namespace inlay {

struct GltfExportOptions {
  double texelsPerMetre = 128;  // baked albedo texture density
  int maxTextureSize = 1024;    // per surface group, each side
};

// Writes `scene` to `path` (.gltf or .glb, by extension). Warnings (what was left out) are
// appended to `warnings` when given. Errors name the file and the reason.
Status exportGltf(const RenderScene& scene, const std::string& path,
                  const GltfExportOptions& options = {}, std::vector<std::string>* warnings = nullptr);

}  // namespace inlay
