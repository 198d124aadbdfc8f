// Caustics through glass from an area light must converge, not vanish: a glass ball over a
// diffuse floor focuses the ceiling light into a bright spot, which path tracing reaches by
// BSDF-sampled paths (floor -> glass -> glass -> light), or, for smooth glass, the caustic
// photon map (TracerOptions::causticPhotons). Low-sample renders agree with a high-sample
// reference of other samples in the spot, and the error falls with samples. Below: the photon
// map's light against the slab's Fresnel series and against path tracing alone, converged.
#include "render_test_scenes.h"
#include "test_support.h"

#include "inlay/render/path_tracer.h"

#include <chrono>

namespace inlay {
namespace {

constexpr int kW = 32, kH = 24;  // a narrow view of the floor around the spot

RenderScene ballScene(Material::Kind kind, double roughness) {
  RenderScene s = test::roomScene(test::testCamera(kW, kH, 14, 1.3, -33), RoomBox{}, 0.7);
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.55, -2.0), Vec3(0.15, 0, 0), Vec3(0, 0, 0.15), Vec3::Constant(40)));
  InsertedObject ball;
  ball.meshObject = test::sphereMesh(0.3, 48, 96);
  // A ball lens focuses at n R / (2 (n - 1)) = 0.45 m from its centre for n = 1.5.
  ball.worldFromObject = test::translation(Vec3(0, 0.45, -2.0));
  ball.material.kind = kind;
  ball.material.roughness = roughness;
  ball.material.albedo = Vec3::Constant(0.8);
  s.objects.push_back(ball);
  return s;
}

struct Rendered {
  ImageF with, without, mask;
};
constexpr int kPhotons = 200000;  // the setting docs/generalization.md measures

Rendered render(const RenderScene& s, int firstSample, int spp, int causticPhotons = kPhotons) {
  TracerOptions opt;
  opt.pixelFilterWidth = 0;  // the box: the sample sequences the tolerances below were read on
  opt.maxDepth = 12;
  opt.causticPhotons = causticPhotons;
  PathTracer tracer(s, opt);
  DifferentialBuffers b(kW, kH);
  EXPECT_TRUE(tracer.render(b, firstSample, spp, 17));
  EXPECT_EQ(tracer.stats().nonFiniteSamples, 0u);
  return {b.meanWith(), b.meanWithout(), b.meanMask()};
}

// Path tracing alone (the caustic photon map off: with it the spot has no noise of its own to
// fall at 16 samples already; CausticPhotons below holds it to this).
void expectCausticConverges(Material::Kind kind, double roughness, const char* name) {
  const RenderScene s = ballScene(kind, roughness);
  const Rendered ref = render(s, 100000, 512, 0);
  // The spot: floor pixels (never the ball) at least twice as bright with the ball as without.
  std::vector<size_t> spot;
  for (size_t i = 0; i < ref.with.pixelCount(); ++i)
    if (ref.mask.data[i] == 0.f && ref.with.data[i * 3] > 2.0 * ref.without.data[i * 3])
      spot.push_back(i);
  ASSERT_GE(spot.size(), 20u) << name << ": no caustic";
  double refMean = 0;
  for (size_t i : spot) refMean += ref.with.data[i * 3];
  refMean /= spot.size();
  double previous = 1e300;
  for (int spp : {16, 64, 256}) {
    const Rendered r = render(s, 0, spp, 0);
    double mean = 0, sq = 0;
    for (size_t i : spot) {
      mean += r.with.data[i * 3];
      const double e = r.with.data[i * 3] / ref.with.data[i * 3] - 1.0;
      sq += e * e;
    }
    mean /= spot.size();
    const double rms = std::sqrt(sq / spot.size());
    std::printf(
        "[ caustic ] %s: %zu spot px, %4d spp: mean %.3f (reference %.3f, rel %+.3f), rms rel %.3f\n",
        name, spot.size(), spp, mean, refMean, mean / refMean - 1, rms);
    // At 64 spp a few long caustic paths still weigh on the mean: rough glass gave +0.129 by
    // BSDF sampling alone and +0.157 with NEE through the glass (the same sample sequence; both
    // +0.03 at 256 spp), so 64 spp is held to 0.2 and 256 spp to 0.05.
    if (spp >= 64) {
      EXPECT_NEAR(mean / refMean, 1.0, spp >= 256 ? 0.05 : 0.2) << name << " at " << spp;
    }
    EXPECT_LT(rms, previous) << name << " at " << spp;
    previous = rms;
  }
}

TEST(Caustic, SmoothGlassBallFocusesTheLightAndConverges) {
  expectCausticConverges(Material::Kind::Glass, 0.0, "smooth glass");
}

TEST(Caustic, RoughGlassBallConverges) {
  expectCausticConverges(Material::Kind::RoughGlass, 0.15, "rough glass");
}

// --- The caustic photon map (TracerOptions::causticPhotons) ---

// A glass slab 1.2 m x 2 cm x 1.2 m, 0.8 m above a dark floor (albedo 0.05, the rest of the room
// black), under a small light 1.75 m above it; the camera, low (0.3 m), sees the floor under the
// slab only, never the slab. The floor's light passes the slab near normal incidence: with /
// without is the slab's incoherent Fresnel series (1 - R) / (1 + R), R = ((n - 1) / (n + 1))^2,
// times the light's apparent solid angle (the slab brings its image t (1 - 1/n) closer), plus the
// floor's light that the slab's underside (reflectance 2R / (1 + R)) returns to it (view factor
// of the slab from below its centre: 0.413).
constexpr double kSlabM = 0.02, kLightM = 2.55;
RenderScene slabScene(double ior) {
  RenderScene s = test::roomScene(test::testCamera(kW, kH, 4, 0.3, -8.5), RoomBox{}, 0.0);
  s.roomAlbedo.surfaceMean[0] = Vec3::Constant(0.05);  // the floor
  s.lights.push_back(
      test::rectLight(Vec3(0, kLightM, -2.0), Vec3(0.05, 0, 0), Vec3(0, 0, 0.05), Vec3::Constant(200)));
  s.objects.push_back(test::placedObject(test::boxMesh(RoomBox{-0.6, 0.6, -0.6, 0.6, kSlabM}),
                                         Vec3(0, 0.8, -2.0), Material::Kind::Glass));
  s.objects.back().material.ior = ior;
  return s;
}

struct Ratio {
  double withOverWithout = 0;
  bool finite = false;
};
Ratio slabRatio(const RenderScene& s, int spp, int photons) {
  const Rendered r = render(s, 0, spp, photons);
  double with = 0, without = 0;
  for (size_t i = 0; i < r.with.pixelCount(); ++i) {
    EXPECT_EQ(r.mask.data[i], 0.f) << "the camera sees the slab";
    with += r.with.data[i * 3], without += r.without.data[i * 3];
  }
  return {with / without, test::allFinite(r.with) && test::allFinite(r.without) && without > 0};
}

double slabSeries(double ior) {
  const double r = (ior - 1) * (ior - 1) / ((ior + 1) * (ior + 1));
  const double closer = kLightM / (kLightM - kSlabM * (1 - 1 / ior));
  return (1 - r) / (1 + r) * closer * closer * (1 + 0.05 * 0.413 * 2 * r / (1 + r));
}

// The floor under the slab (next-event estimation blocked by the glass, the light tiny for BSDF
// sampling) gets the slab's transmission from the photons at 16 samples, for a plain (1.5), a
// barely refracting (1.0001) and a strongly reflecting (4) slab. Without the photon map the
// same renders find the light through the slab by chance (a few hits in all).
TEST(CausticPhotons, SlabPassesItsFresnelSeriesToTheFloor) {
  for (double ior : {1.5, 1.0001, 4.0}) {
    const Ratio r = slabRatio(slabScene(ior), 16, 1000000);
    std::printf("[ caustic ] slab ior %.4f: with / without %.4f, series %.4f\n", ior, r.withOverWithout,
                slabSeries(ior));
    EXPECT_TRUE(r.finite);
    EXPECT_NEAR(r.withOverWithout, slabSeries(ior), 0.015) << "ior " << ior;
  }
}

// A sun straight above the slab: the photons leave a disc across the beam (its parallel light
// keeps the floor's solid angle, so the series alone, with the underside's inter-reflection).
TEST(CausticPhotons, SunThroughTheSlabGivesItsFresnelSeries) {
  RenderScene s = slabScene(1.5);
  s.lights.clear();
  SunLight sun;
  sun.travelDirection = Vec3(0, -1, 0);
  sun.irradianceOverPi = Vec3::Constant(2);
  s.suns.push_back(sun);
  const double r = 0.04, expected = (1 - r) / (1 + r) * (1 + 0.05 * 0.413 * 2 * r / (1 + r));
  const Ratio got = slabRatio(s, 16, 1000000);
  std::printf("[ caustic ] slab under a sun: with / without %.4f, series %.4f\n", got.withOverWithout,
              expected);
  EXPECT_TRUE(got.finite);
  EXPECT_NEAR(got.withOverWithout, expected, 0.015);
}

// No double counting: the paths floor -> glass -> light that the photons bring are removed from
// the path tracer. Around the ball's spot (the floor pixels the photons make 10 % brighter than
// the room without the ball, grown by the map's blur) the floor carries the same light at 64
// samples with the photons as path tracing alone converged (2048 samples); the photon map blurs
// the spot but keeps its energy. Counted twice, the spot's light would be about 1.5 x.
TEST(CausticPhotons, BallsCausticCarriesThePathTracersEnergyOnce) {
  const RenderScene s = ballScene(Material::Kind::Glass, 0.0);
  const Rendered photons = render(s, 0, 64);
  const Rendered reference = render(s, 100000, 2048, 0);
  double a = 0, b = 0, plain = 0;
  for (size_t i = 0; i < photons.with.pixelCount(); ++i) {
    if (reference.mask.data[i] != 0.f || photons.mask.data[i] != 0.f) continue;
    if (!(photons.with.data[i * 3] > 1.1 * photons.without.data[i * 3])) continue;
    a += photons.with.data[i * 3], b += reference.with.data[i * 3],
        plain += reference.without.data[i * 3];
  }
  std::printf("[ caustic ] ball: spot with photons %.4f, path traced %.4f (no ball %.4f)\n", a, b,
              plain);
  EXPECT_GT(b, 1.5 * plain) << "no caustic to compare";
  EXPECT_NEAR(a / b, 1.0, 0.05);
}

// A light path's flux is never created: what the photons carry to surfaces is at most what the
// lights send into the glass objects' spheres, and stays finite in the stiff cases: total
// internal reflection (a cube lit from the side at IOR 1.5 and 4), the light inside the glass
// ball, a single photon, none.
TEST(CausticPhotons, StiffCasesStayFiniteAndCreateNoLight) {
  struct Case {
    const char* name;
    double ior;
    Vec3 lightCentre;
    int photons;
    bool cube;
  };
  for (const Case& c : {Case{"cube, light from the side", 1.5, Vec3(1.2, 1.0, -2.0), 200000, true},
                        Case{"cube, ior 4", 4.0, Vec3(1.2, 1.0, -2.0), 200000, true},
                        Case{"light inside the ball", 1.5, Vec3(0, 0.45, -2.0), 200000, false},
                        Case{"one photon", 1.5, Vec3(0, 2.55, -2.0), 1, false},
                        Case{"no photons", 1.5, Vec3(0, 2.55, -2.0), 0, false}}) {
    RenderScene s = ballScene(Material::Kind::Glass, 0.0);
    s.lights[0] = test::rectLight(c.lightCentre, Vec3(0.05, 0, 0), Vec3(0, 0, 0.05), Vec3::Constant(40));
    if (c.cube) s.objects[0].meshObject = test::boxMesh(RoomBox{-0.3, 0.3, -0.3, 0.3, 0.6});
    s.objects[0].material.ior = c.ior;
    TracerOptions opt;
    opt.causticPhotons = c.photons;
    PathTracer tracer(s, opt);
    const PathTracer::CausticStats st = tracer.causticStats();
    // Flux out of the light's front: pi L A (an upper bound on what enters the sphere).
    const double emitted = test::kPi * 40 * 0.1 * 0.1;
    std::printf("[ caustic ] %s: %zu photons, flux %.4f of at most %.4f W\n", c.name, st.photons,
                st.flux, emitted);
    EXPECT_TRUE(std::isfinite(st.flux)) << c.name;
    EXPECT_LE(st.flux, emitted) << c.name;
    if (c.photons == 0) {
      EXPECT_EQ(st.photons, 0u);
    } else if (c.photons >= 200000) {
      EXPECT_GT(st.photons, 1000u) << c.name;
    }
    DifferentialBuffers b(kW, kH);
    ASSERT_TRUE(tracer.render(b, 0, 4, 3));
    EXPECT_EQ(tracer.stats().nonFiniteSamples, 0u) << c.name;
    EXPECT_TRUE(test::allFinite(b.meanWith())) << c.name;
  }
}

// Scenes without smooth glass build no map and render bit for bit as with the pass off; with
// glass the map is the same at every build (parallel emission, ordered batches).
TEST(CausticPhotons, NoGlassNoPhotonsAndTheMapIsDeterministic) {
  const RenderScene diffuse = ballScene(Material::Kind::Diffuse, 0.0);
  const Rendered on = render(diffuse, 0, 4), off = render(diffuse, 0, 4, 0);
  EXPECT_TRUE(test::sameBits(on.with, off.with));
  EXPECT_TRUE(test::sameBits(on.without, off.without));
  TracerOptions opt;
  opt.causticPhotons = kPhotons;
  EXPECT_EQ(PathTracer(diffuse, opt).causticStats().photons, 0u);
  const RenderScene glass = ballScene(Material::Kind::Glass, 0.0);
  EXPECT_EQ(PathTracer(glass).causticStats().photons, 0u) << "the pass is off by default";
  auto seconds = [&](int photons) {
    TracerOptions timed;
    timed.causticPhotons = photons;
    const auto t0 = std::chrono::steady_clock::now();
    const PathTracer t(glass, timed);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  const double plainS = seconds(0), photonS = seconds(kPhotons);
  std::printf("[ caustic ] tracer built in %.3f s without the photon pass, %.3f s with it\n", plainS,
              photonS);
  const PathTracer a(glass, opt), b(glass, opt);
  EXPECT_GT(a.causticStats().photons, 0u);
  EXPECT_EQ(a.causticStats().photons, b.causticStats().photons);
  EXPECT_EQ(a.causticStats().flux, b.causticStats().flux);
  const Rendered r1 = render(glass, 0, 2), r2 = render(glass, 0, 2);
  EXPECT_TRUE(test::sameBits(r1.with, r2.with));
}

}  // namespace
}  // namespace inlay
