// The engine pipeline shared by inlay-cli and the studio (Qt-free):
//   SceneDoc -> photo, camera, room and supporting surfaces -> lighting (albedo, lights)
//            -> RenderScene (room + lights + placed objects) -> frames -> composite.
// prepareScene() does the once-per-photo-and-geometry work; moving an object only needs
// placeObjectAt() plus RenderSession::setObjectTransform(), never a new prepareScene().
#pragma once

#include "inlay/lighting/estimate.h"
#include "inlay/lighting/refine.h"
#include "inlay/lighting/shaft.h"
#include "inlay/modeling/camera.h"
#include "inlay/modeling/estimate_camera.h"
#include "inlay/modeling/geometry.h"
#include "inlay/modeling/image_io.h"
#include "inlay/modeling/response.h"
#include "inlay/modeling/scene_file.h"
#include "inlay/render/grain.h"
#include "inlay/render/scene.h"
#include "inlay/render/session.h"

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace inlay {

// One stage of prepareScene() (photo, response, working copy, camera, layout, occluders,
// surfaces, room, lights, shafts, lighting, vignetting, sun ratio, refine, lighting refit,
// response check (when it checks a curve), photo size, render scene, objects, grain):
// what it took, or why the scene did not need it ("shafts": "no sun marked"). A skipped stage
// does none of its work.
// One step inside a stage (StageRecord::steps): the lighting's surfaces, direct light, gather,
// light fit, decomposition..., with its wall and CPU seconds summed over its calls.
struct StageStep {
  std::string name;
  double seconds = 0;
  double cpuSeconds = 0;
};

struct StageRecord {
  std::string name;
  bool ran = false;
  double seconds = 0;  // wall seconds, when it ran
  // CPU seconds of the whole process (all threads) while it ran: steadier than `seconds` on a
  // loaded machine; cpuSeconds / seconds is about the threads it kept busy.
  double cpuSeconds = 0;
  std::string reason;  // why it was skipped; empty when it ran
  std::string detail;  // what it did, when it ran (may be empty): "estimated from the photo"
  // The image size it worked at, when it ran and works on an image (0 x 0: it works on none,
  // as layout, room, objects): the photo's, the working copy's (PrepareOptions::
  // workingMaxPixels) or its own (the camera estimate reduces the photo itself).
  int workingWidth = 0, workingHeight = 0;
  bool reducedImage = false;     // that size is smaller than the photo's
  std::vector<StageStep> steps;  // where its seconds went, when it tells (the lighting does)
};
// One line for a log: "camera: 0.84 s, CPU 1.52 s (estimated from the photo)", "shafts:
// skipped, no sun marked"; a stage that worked on a reduced image says its size: "lighting:
// 20.1 s, CPU 38.9 s (1 light, 0 suns) at 816 x 612 px"; a stage with steps lists their CPU
// seconds after it: "; CPU s: surfaces 0.05, gather 3.10, ...".
std::string describeStage(const StageRecord& stage);

struct PreparedScene {
  SceneDoc doc;
  LoadedImage photo;  // linear RGB (decoded by `response`), oriented
  // The size of the working copy the image stages ran on (PrepareOptions::workingMaxPixels):
  // the photo's own size when it has no more pixels.
  std::array<int, 2> workingPx{};
  // How the photo's codes map to radiance (camera.response, estimated when "auto"); the
  // composite is encoded with it (SaveOptions::response), so untouched pixels keep their codes.
  // Linear for EXR/HDR photos.
  CameraResponse response;
  std::optional<ResponseEstimate> responseEstimate;  // when "auto" ran the estimate
  // The vignetting strength v applied (camera.vignetting; 0: none): from the stage "vignetting"
  // on, photo.linearRgb is the devignetted radiance f^-1(photo) / V (V = vignettingFalloff),
  // and compositeOf multiplies the composite by V again, so untouched pixels keep their codes.
  double vignetting = 0;
  double vignettingEstimated = 0;  // LightingEstimate::vignetting of the fit before devignetting
  Camera camera;
  RoomBox box;
  std::array<Vec2, 4> backWallPx{};  // the corners the box was made from
  // The automatic estimate, when one ran (the scene file did not give both the vanishing points
  // and the back wall): its line segments, vanishing points and confidences, for display.
  std::optional<CameraEstimate> cameraEstimate;
  std::vector<Extrusion> extrusions;
  SceneGeometry geometry;
  // Lights and suns refined when the refinement ran. Its images are at the photo's size (from
  // the working copy by the "photo size" stage), except the decomposition's inputs
  // (decomposeStart, decomposeValid, decomposeClipped), Retinex's albedo (retinexAlbedo) and,
  // in a room without a sun, the fit's albedo (physicalAlbedo): they stay at workingPx.
  LightingEstimate lighting;
  // The lights and suns before the refinement (the estimate's radiance fit at the outlined or
  // placed positions), and what the refinement did (empty history when it did not run).
  std::vector<AreaLight> initialLights;
  std::vector<SunLight> initialSuns;
  LightRefineResult refinement;
  RenderScene renderScene;            // lights and objects placed; roomAlbedo filled
  std::vector<Placement> placements;  // per object
  // The photo's noise against intensity and its grain's correlation (render/grain.h), measured
  // once from photo.linearRgb; empty for a linear (EXR, HDR) or noise-free photo. compositeOf
  // gives the pixels the objects change this grain (scene key render.grain).
  PhotoNoise photoNoise;
  std::vector<std::string> warnings;  // one line each, for stderr or a status bar
  // Every stage of the preparation in order: its seconds, or why this scene did not need it.
  // When PrepareOptions::checkResponseByLightFit checks a curve, the stages up to the lighting
  // refit are those of the response kept (the curve's when the full check ran), then "response
  // check": its own seconds, which response it kept and why, and as its steps the copies'
  // stages ("copy, curve: lighting", ...) and those it ran again with sRGB; the stages after it
  // ran once, for the response kept. The full check prepares the two candidates side by side
  // (PrepareOptions::checkResponseByLightFit): each of their stages counts the process's CPU
  // while it ran, the other candidate's included; the check's own record holds the rest of that
  // block, so the records add up to the process's seconds, and its last step ("both
  // candidates, side by side") times the two together.
  std::vector<StageRecord> stages;
};

// The working copy's default size: the image stages of a bigger photo run on it (about 816 x 612
// for a 4:3 photo); dev rooms (512 x 384) and York photos (632 x 474) are smaller, so run on
// the photo itself.
inline constexpr double kWorkingMaxPixels = 0.5e6;

// PrepareOptions::keepBetterFitTolerance's default: twice the fit residual's own noise. Both
// residuals come from Monte Carlo gathers; over the preparation's seeds (0, 1, 2) the relative
// difference refit / first - 1 spreads by 0.1-5.6 % per room of half A (scenes-train t01..t13),
// median 0.81 % (tests/bench/bench_refit_tolerance.py); a refit worse by less than two such
// spreads is a tie and is kept. Half A's rooms whose refit is worse by more (t05 4.9 %, t13 9.4 %
// at the product's seed) keep their first estimate as before (docs/generalization.md, "A
// tolerance for the refit").
inline constexpr double kKeepBetterFitTolerance = 0.016;

// PrepareOptions::refitMinLightMove's default, chosen on half A (docs/benchmarks.md, "Skipping
// the light refit when the lights hardly moved"): there the refinement moves the lights by 1.2 %
// (t09) or by 9 to 41 % of their size; t09 alone falls below, and its first estimate scores as
// its refit does (object RMSE 0.0226 against 0.0225).
inline constexpr double kRefitMinLightMove = 0.05;

// PrepareOptions::checkResponseByLightFit's first, quick comparison: the curve and sRGB each
// prepared up to the lighting on a copy of the photo area-averaged to at most `maxPixels`, with
// the lights as marked (no refinement, no refit), fitPixels pixels in the light fit and no
// decomposition (the residual is the light fit's, before it). When the log of the ratio of their
// relative residuals (the curve's over sRGB's times 1 + responseFitTolerance) is beyond
// `margin` either way, that verdict stands and only the response it keeps is prepared; inside
// it (or when a copy's fit fails) the full check runs as before, on the photo's working copy.
// The copies' light fit stops at a coarser solver tolerance (1e-3 against Ceres' 1e-6): a
// quarter less CPU, the same photos decided on half A.
// Chosen on half A's camera variants (docs/benchmarks.md, "The response check decides on a
// small copy first").
struct ResponseQuickCheck {
  double maxPixels = 160 * 120;  // <= 0: no quick comparison, the full check always
  int fitPixels = 1500;          // LightingOptions::fitPixels of the copies' fits
  int maxPasses = 5;             // LightingOptions::maxPasses of the copies' fits
  double fitTolerance = 1e-3;    // LightingOptions::fitFunctionTolerance of the copies' fits
  double margin = 0.1;           // |log ratio| beyond which the copies decide; infinite: never
  bool refineLights = false;     // the copies' lights refined and refitted as the full check's
};

struct PrepareOptions {
  const CancelToken* cancel = nullptr;
  // The image stages (the lights' mask, shafts, lighting, sun ratio, refine, refit) run on the
  // photo area-averaged to at most this many pixels (occluder mattes, whatever this is, at the
  // scale of a 640-pixel photo on their scribbles' region: MatteOptions), their maps brought back
  // to the photo's size by guided upsampling; the render and composite stay at the photo's
  // size. <= 0: every stage at the photo's own size.
  double workingMaxPixels = kWorkingMaxPixels;
  // stage name ("photo", "camera", "room", "lighting", "refine", "objects": coarser than
  // PreparedScene::stages) and fraction in [0,1]; called on the calling thread.
  std::function<void(const std::string& stage, double fraction)> progress;
  int threads = 0;
  // Refine the lights' positions and intensities against the photo (lighting/refine.h); false
  // renders with the initial lights.
  bool refineLights = true;
  LightRefineOptions refine;
  // After the refinement the lighting is fitted again at the refined places; when that fit
  // explains the photo worse than the first estimate (its robust log residual,
  // LightingEstimate::fitRmsLog, is larger by more than `keepBetterFitTolerance` of the first's),
  // the first estimate's lights are kept (the refit stage's detail says so). False: the refit is
  // always taken.
  bool keepBetterFit = true;
  // The relative excess of the refit's residual over the first estimate's that is still a tie
  // (the refit is kept): the fit residual's own spread over the gather's seeds
  // (kKeepBetterFitTolerance). 0: any larger residual keeps the first estimate.
  double keepBetterFitTolerance = kKeepBetterFitTolerance;
  // The refit runs only when the refinement moved some light's corner by at least this fraction
  // of that light's size (the square root of its area: largestLightMove). Below it the
  // refinement's lights are dropped and the first estimate's kept (their intensities were fitted
  // with the room's albedo and indirect light, the refinement's to the direct light alone; the
  // suns stay as the sun ratio and the refinement left them), and the refit stage is reported
  // skipped with the largest move. 0: every move over a millimetre refits.
  double refitMinLightMove = kRefitMinLightMove;
  // With refineLights: each sun's strength from its lit patch against the shadowed pixels of
  // the same surface beside it (lighting/sun_ratio.h), which cancels the albedo; the gathered
  // light follows (its clipped patch's bounce scales with the sun). Kept as estimated when the
  // ratio cannot be measured (a note says why).
  bool sunsFromShadowRatio = true;
  // With sunsFromShadowRatio: when the ratio cannot be measured because the patch clips, the
  // sun's strength from the light its patch bounces onto the room the photo shows unclipped
  // (lighting/sun_ratio.h, sunStrengthFromBounce), at least the clipped patch's lower bound; a
  // channel the bounce cannot tell keeps the estimate's strength (a warning says why). Off by
  // default: chosen on d4 it held, but on the held-out sun rooms it made t04's object 0.070 ->
  // 0.195 (docs/generalization.md, "The sun's strength from its patch's bounce"); the CLI's
  // --suns-from-bounce turns it on for diagnostics.
  bool sunsFromBounce = false;
  // A shaft whose window the photo does not show (no source_box_px, and the opening its beam
  // came through mostly out of view) lets the sky in through that window all the same: the
  // opening (lighting/shaft.h, openingOfBeam) becomes an area light whose intensity the lighting
  // fit finds and the refinement does not move.
  bool skyThroughUnseenWindows = true;
  // The depth of that window's reveal (the wall's thickness, m): the opening is the beam's
  // section widened on the side the light comes from, as the inner opening of a wall this thick
  // (openingOfBeam's revealDepthM): a high sun lights the reveal through the window's top part,
  // so the beam alone gave the sky too small a window (docs/generalization.md, "The unseen
  // window's reveal"). 0: the beam's section.
  double windowRevealDepthM = kWindowRevealDepthM;
  // The preparation's own randomness (the lighting fit's light samples and gathering, the
  // refinement's fixed samples), added to each stage's default seed. It is fixed per scene and
  // never the render seed (render.seed, --seed): renders of one scene with different render
  // seeds share one prepared scene, so they converge to one image.
  uint32_t seed = 0;
  // Diagnostics: LightingOptions::fitUnseenCeilingAlbedo (negative: the product's rule).
  Vec3 fitUnseenCeilingAlbedo = Vec3::Constant(-1);
  // LightingOptions::fitUnseenCeiling and renderFittedCeiling (diagnostics: --unseen-ceiling).
  bool fitUnseenCeiling = true;
  bool renderFittedCeiling = false;
  // camera.response "auto": a curve the estimate fitted is kept only when the light fit explains
  // the photo at least as well with it as with sRGB. The photo as loaded is prepared again with
  // sRGB up to the lighting refit (the stages that depend on the response), and when the curve's
  // LightingEstimate::fitResidualRelative is larger than sRGB's by more than
  // `responseFitTolerance` of it (refitFitsWorse), the sRGB preparation is kept, with a warning
  // and the estimate's decision saying why; the stages after the refit run once, for the one
  // kept. Measured on half A of the random cameras (docs/camera-response.md, "The light fit
  // checks the estimated curve"): both curves it met made the object worse and both left a
  // larger residual. The two are first compared on small copies (responseQuick); only when
  // those do not decide are the stages run a second time (docs/benchmarks.md, "The response
  // check decides on small copies first"), only on photos the estimate gives a curve. The full
  // check's two candidates are independent and prepared side by side: the curve's stages on the
  // calling thread (with the progress reports), sRGB's as a TBB task beside them (none); with
  // `threads` 1 one after the other (docs/benchmarks.md, "The response check's two candidates
  // side by side"). False: the estimate's curve is always kept.
  bool checkResponseByLightFit = true;
  double responseFitTolerance = 0;
  // The check's first comparison on small copies (ResponseQuickCheck): when it is clear, the
  // second preparation is not run at all.
  ResponseQuickCheck responseQuick;
  // The response estimate's options for "auto" (its `cancel` is this struct's): tests and
  // diagnostics.
  ResponseEstimateOptions responseEstimate;
};

// The camera and back wall of a scene: what the file gives is kept, the rest estimated from the
// photo (EXIF focal length as a prior) around it. `alwaysEstimate` runs the estimate even when
// the file gives everything (inlay-cli estimate reports its confidences). Warnings are lines for
// the user.
struct CameraAndLayout {
  Camera camera;
  std::array<Vec2, 4> backWallPx{};
  std::optional<CameraEstimate> estimate;  // when one was run
  std::vector<std::string> warnings;
};
Expected<CameraAndLayout> cameraAndLayoutOf(const CameraKeys& camera, const LayoutKeys& layout,
                                            const LoadedImage& photo, bool alwaysEstimate,
                                            const CancelToken* cancel = nullptr);

// The camera response of `photo` as `keys` ask (an EXR/HDR photo is linear whatever they say,
// with a warning when they say otherwise); "auto" estimates it (modeling/response.h). Warnings
// (why the estimate fell back to sRGB) go to `warnings`.
struct ChosenResponse {
  CameraResponse response;
  std::optional<ResponseEstimate> estimate;
  std::vector<std::string> warnings;
};
ChosenResponse responseOf(const ResponseKeys& keys, const LoadedImage& photo,
                          const ResponseEstimateOptions& options = {});

// Everything needed to render `doc`. Errors name the scene file's key and the reason.
Expected<PreparedScene> prepareScene(const SceneDoc& doc, const PrepareOptions& options = {});

// Whether the estimate's curve was taken away by PrepareOptions::checkResponseByLightFit (its
// decision says so; the wording is prepareScene's).
bool curveRefusedByTheLightFit(const ResponseEstimate& estimate);

// PrepareOptions::keepBetterFit's test: whether the refit's robust log residual `refit` is worse
// than the first estimate's `first` by more than `tolerance` of it (a relative tie keeps the
// refit). A residual that is not finite never wins; a negative or NaN tolerance counts as 0, an
// infinite one keeps every finite refit.
bool refitFitsWorse(double first, double refit, double tolerance);

// ResponseQuickCheck's verdict from the copies' relative residuals with the curve and with sRGB:
// +1 the curve is kept, -1 sRGB, 0 the copies do not decide (the full check runs). They decide
// when |log(withCurve / (withSrgb (1 + tolerance)))| > margin; a residual that is not finite and
// positive never decides, nor does a tie; a negative or NaN tolerance counts as 0, so does a
// negative margin; a NaN margin never decides.
int quickResponseVerdict(double withCurve, double withSrgb, double tolerance, double margin);

// PrepareOptions::refitMinLightMove's measure: over the lights, the largest distance a corner
// moved from `before` to `after`, in units of that light's size (the square root of its area
// before). Infinite when the lists differ in length, a light has no area but moved, or a corner
// is not finite; 0 for no lights.
double largestLightMove(const std::vector<AreaLight>& before, const std::vector<AreaLight>& after);

// Meshes by file (resolved path and subdivision levels), shared between object sets.
using MeshCache = std::map<std::string, std::shared_ptr<const TriangleMesh>>;
struct PlacedObjects {
  std::vector<InsertedObject> objects;  // RenderScene::objects
  std::vector<Placement> placements;    // per object
};
// The objects stage of prepareScene() alone: each object's mesh loaded (through `cache` when
// given; not thread-safe), placed on the room and given its material, exactly as prepareScene()
// does, so one prepared room serves many object sets (inlay-cli batch). Errors name
// "objects[i]...".
Expected<PlacedObjects> placeObjects(const std::vector<ObjectKeys>& objects,
                                     const SceneGeometry& geometry, const Camera& camera,
                                     MeshCache* cache = nullptr);

// Placement of object `index` from the document's current base_px / height_m / yaw_deg (the
// mesh stays loaded). Errors name "objects[index].base_px" etc.
Expected<Placement> placeObjectAt(const PreparedScene& scene, size_t index);

// The render scene with the objects the scene file marks `hidden` left out of the picture: they
// keep their index (and placement) but carry no mesh, so RenderSession::setObjectTransform
// indices stay the document's.
RenderScene shownRenderScene(const PreparedScene& scene);

// The grain prepareScene measures: the noise of an encoded photo (JPEG, PNG, TIFF) in the units
// of its linearRgb; none for a linear photo (EXR, HDR), whose pixels are radiances. From at most
// kGrainMaxPatches patches spread over the whole photo (NoiseMeasureOptions::maxPatches): a
// photo of up to about 0.8 MP is measured in every patch as before; a 12 MP one on a 4 times
// sparser grid than the measurement's own 200 000 (16 bins of about 3000 patches each still).
inline constexpr long kGrainMaxPatches = 50'000;
PhotoNoise photoNoiseOf(const LoadedImage& photo);

// The 8-bit-ready linear composite of a frame: differential composite over the photo, the
// photo's grain on the pixels the objects change (when the scene's render.grain and
// `withGrain`; false for the clean EXR layers), then the scene's exposure.
ImageF compositeOf(const PreparedScene& scene, const RenderFrame& frame, bool withGrain = true);
// The response an 8-bit output of the composite is encoded with: the photo's own (estimated or
// from camera.response), or null (plain sRGB) for a linear EXR/HDR photo.
const CameraResponse* outputResponseOf(const PreparedScene& scene);
// The same from just what it needs (for a render thread that holds no PreparedScene); `grain`
// null: no grain. `grainField`: grainField(*grain, W, H, grainSeed) computed once for many
// frames (render/grain.h; the same bits, without drawing the grain per frame). `unclipped`: the
// room's radiance where the photo clips it (differentialComposite; the prepared scene's
// renderScene.roomAlbedo.photoRadiance), or null.
// `vignetting`: the scene's PreparedScene::vignetting (the composite is multiplied by V).
ImageF compositeOf(const ImageF& photoLinear, double exposureStops, const RenderFrame& frame,
                   const PhotoNoise* grain = nullptr, uint32_t grainSeed = 1,
                   const ImageF* grainField = nullptr, const ImageF* unclipped = nullptr,
                   double vignetting = 0);

// The radial fall-off V = 1 - v r^2 at pixel (x, y) of a w x h image (r^2: the squared distance
// of the pixel's centre from the image centre over the corner's; LightingEstimate::vignetting's
// model). `v` is clamped to [0, VignettingKeys::kMax], so V >= 0.1 and finite.
double vignettingFalloff(double v, int x, int y, int w, int h);
// Divides every pixel of `image` by V (devignetting) or multiplies it (`undo`); v = 0: unchanged.
// Non-finite values stay as they were.
void divideByVignetting(ImageF& image, double v, bool undo = false);
// The strength camera.vignetting asks for ("none", the default: 0; a number: it); for "auto" the
// light fit's residual estimate `estimatedV`: the estimate
// when it is at least kMinAutoVignetting (below it: a plain photo's noise, 0 to 0.03 on the
// training rooms) and inside its search's range (LightingEstimate::vignetting stops at
// kMaxAutoVignetting: an estimate at that bound found no minimum), else 0.
inline constexpr double kMinAutoVignetting = 0.05;
inline constexpr double kMaxAutoVignetting = 0.6;
double vignettingToApply(const VignettingKeys& keys, double estimatedV);

// An object's mesh as the scene file asks for it: loaded (mesh key), then smoothly subdivided
// by its `subdivide` levels (Catmull-Clark for quad meshes, Loop for triangles). Errors are keyed
// "mesh" or "subdivide" (prefix them with the object's key).
Expected<TriangleMesh> loadObjectMesh(const ObjectKeys& object);

// Writes the prepared scene as glTF 2.0 for Blender and other tools (render/gltf_export.h): the
// room with its albedo baked into PNG textures, lights as emissive quads, the camera, and the
// objects where renderScene places them, with their materials. `path` ends in .gltf (with .bin
// and PNGs beside it) or .glb (one file). Warnings (what glTF cannot hold) go to `warnings`.
Status exportSceneGltf(const PreparedScene& scene, const std::string& path,
                       std::vector<std::string>* warnings = nullptr);

// The renderer's material for the scene file's material keys; `meshObject` (may be null)
// supplies the file's own material for preset "asset" (its first material).
Material materialFromKeys(const MaterialKeys& keys, const TriangleMesh* meshObject);
// A file's material (glTF metallic-roughness, OBJ/MTL) as the nearest of the renderer's models:
// emission -> Emissive (a light), transmission -> Glass / RoughGlass, metallic -> Mirror /
// Conductor, else Glossy (roughness < 0.6) or Diffuse.
Material materialFromAsset(const AssetMaterial& asset);
// Sets `object`'s material from the keys (materialFromKeys), and for preset "asset" on a mesh
// with per-triangle materials also its partMaterials, one per file material, so that each part
// renders in its own (a lamp's shade glows, its stand stays brass). `object.meshObject` must be
// set first.
void setObjectMaterial(InsertedObject& object, const MaterialKeys& keys);
// RenderScene::roomMaterials from the scene file's "room.materials": one entry per surface of
// `room`, nullopt where unmarked (or "diffuse"). A name this room does not have is an error
// naming "room.materials.<name>".
Expected<std::vector<std::optional<Material>>> roomMaterialsOf(const RoomKeys& keys,
                                                               const SceneGeometry& room);

// Path of the bundled example scene (resources/example/scene.json) in the source tree or the
// install prefix; empty when not found.
std::string exampleScenePath();
const char* versionString();

}  // namespace inlay
