#include "layout.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace inlay::detail {

namespace {

// Faces of the box seen from inside, and which line families lie in each (a face's two
// in-plane axes): back wall (normal z) holds x and y lines, floor and ceiling x and z, the side
// walls y and z. Exception: vertical lines over the floor are furniture legs and door frames
// standing on it far more often than a wrong box, so they do not count against the floor.
enum Face { kBack = 0, kCeiling, kRight, kFloor, kLeft };
constexpr bool kAllowed[5][3] = {{true, true, false},
                                 {true, false, true},
                                 {false, true, true},
                                 {true, true, true},
                                 {false, true, true}};

// One line family's evidence: exp(-d^2 / 2 sigma^2) of the distance to its nearest segment pixel.
struct EvidenceMap {
  cv::Mat e;  // CV_32F, working pixels
  float at(const Vec2& pw) const {
    const int x = int(pw.x()), y = int(pw.y());
    if (x < 0 || y < 0 || x >= e.cols || y >= e.rows) return 0.f;
    return e.at<float>(y, x);
  }
};

struct Sample {
  Vec2 pw;       // working pixels
  double angle;  // around the forward vanishing point
  int family;
  double weight;  // working pixels of line it stands for
};

// Liang-Barsky: the part of segment a->b inside [0,w] x [0,h]; false when none.
bool clipToRect(Vec2& a, Vec2& b, double w, double h) {
  double t0 = 0, t1 = 1;
  const Vec2 d = b - a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x(), w - a.x(), a.y(), h - a.y()};
  for (int i = 0; i < 4; ++i) {
    if (std::abs(p[i]) < 1e-15) {
      if (q[i] < 0) return false;
      continue;
    }
    const double r = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
    if (t0 > t1) return false;
  }
  const Vec2 a0 = a;
  a = a0 + t0 * d;
  b = a0 + t1 * d;
  return true;
}

Vec3 hom(const Vec2& p) { return Vec3(p.x(), p.y(), 1.0); }

bool dehom(const Vec3& h, Vec2& out) {
  if (!(std::abs(h.z()) > 1e-12 * h.norm())) return false;
  out = Vec2(h.x() / h.z(), h.y() / h.z());
  return out.allFinite();
}

// A vertical edge's end within this many layout pixels of a horizontal segment meets it
// (furnitureTops).
constexpr double kTopTolLayoutPx = 3;
// Verticals whose line passes this share of the diagonal from the forward vanishing point
// could be a floor's receding lines: they say nothing about furniture tops.
constexpr double kForwardShare = 0.03;

// The share of a top edge that must lie on an edge for it to be a ceiling crease (showsCeiling).
// A ceiling and a wall painted alike, lit alike, often meet in a faint crease: York P1020872's
// covered area shows 44 % of it, receding lines above it (the ceiling's lights, the window
// wall's head) outweighing vertical ones ten to one, and under it a floor crease on a ledge's top
// 19.5 m away. It was 1/2; 1/3 was chosen on York half A (odd-numbered photos, even indices): the
// lowest share no accepted box there notices, with a margin over its one accepted box whose top
// edge has receding lines above it and little support (P1030001, a facade under power lines,
// 28 %).
constexpr double kCeilingSeenShare = 1.0 / 3;

// The floor crease's score gains this much per layout pixel of vertical edge standing on it
// (standingOn): a door frame or a cabinet's side ending there from above. Chosen on York half A
// (odd-numbered photos): from 0.2 one rejected box's crease comes down from an upper storey's
// front to the facade's foot on the sidewalk (P1080079); at 0.3 the accepted lounge P1040845's
// crease rises onto the printer and the sofa's seat (8.9 m deep, was 7.2 m); at 0.45 the accepted
// corridor P1020839 loses its end wall (28.1 m to 8.3 m deep).
constexpr double kStandingWeight = 0.2;

// A crease seen only as contrast counts a little less than a detected segment.
constexpr double kContrastWeight = 0.8;

// Contrast is read every kContrastStepPx layout pixels along a line, averaged over kRun reads.
constexpr double kContrastStepPx = 2;
constexpr int kRun = 8;

// A visible step: about 1.5 grey levels per pixel, more on textured or noisy photos.
double edgeThreshold(double noise) { return std::max(1.5 / 255.0, 1.5 * noise); }

// How much of a line in the photo is an edge, from the brightness gradient across it (`across`:
// every kContrastStepPx along the line, the gradient's component normal to it, signed). A real edge
// keeps one sign along its length; noise averages out along it; a bright patch crossed over
// part of the line (a window's frame) is not an edge along the rest. So: running means over
// kRun reads, and the weaker tail (20th percentile) of them for the better polarity, against a
// threshold of about 1.5 grey levels per pixel (more on textured photos).
double lineContrast(std::vector<float>& across, double noise) {
  const int n = int(across.size());
  if (n < kRun) return 0;
  // Running means in place: a mean overwrites a read that the running sum has already dropped
  // (the last kRun reads are kept aside for that).
  float ring[kRun];
  double run = 0;
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const float v = across[k];
    run += v;
    if (k >= kRun) run -= ring[k % kRun];
    ring[k % kRun] = v;
    if (k >= kRun - 1) across[m++] = float(run / kRun);
  }
  // The weaker tail of either polarity: the 20th percentile of the means, and of their
  // negatives (the 80th percentile of the means, negated).
  const size_t q = size_t(m) / 5;
  auto first = across.begin(), last = across.begin() + m;
  std::nth_element(first, first + q, last);
  const double lowTail = *(first + q);
  std::nth_element(first, first + (m - 1 - q), last);
  const double highTail = *(first + (m - 1 - q));
  const double t = std::max({0.0, lowTail, -highTail});
  const double g1 = edgeThreshold(noise);
  return t * t / (t * t + g1 * g1);
}

// The longest stretch (reads) of `across` whose running means keep one sign above the
// threshold.
double longestEdgeRun(const std::vector<float>& across, double noise) {
  const int n = int(across.size());
  const double g1 = edgeThreshold(noise);
  double run = 0;
  int best = 0, cur = 0, sign = 0;
  for (int k = 0; k < n; ++k) {
    run += across[k];
    if (k >= kRun) run -= across[k - kRun];
    if (k < kRun - 1) continue;
    const double m = run / kRun;
    const int s = m > g1 ? 1 : m < -g1 ? -1 : 0;
    cur = s != 0 && s == sign ? cur + 1 : (s != 0 ? 1 : 0);
    sign = s;
    best = std::max(best, cur);
  }
  return best > 0 ? best + kRun - 1 : 0;
}

// Everything about one photo's layout search that does not depend on the hypothesis.
class LayoutSearch {
 public:
  LayoutSearch(const LayoutInput& in) : in_(in), rules_(in.rules) {}

  bool setUp(std::string& problem) {
    const Camera& cam = *in_.camera;
    W_ = cam.widthPx;
    H_ = cam.heightPx;
    ws_ = std::min(1.0, kLayoutSidePx / std::max(W_, H_));
    rules_.creaseSigmaPx = std::max(rules_.creaseSigmaPx, 1.0 / ws_);  // a layout pixel at least
    diag_ = std::hypot(double(W_), double(H_));
    hx_ = cam.vanishingPointOf(Vec3::UnitX());
    hy_ = cam.vanishingPointOf(Vec3::UnitY());
    const Vec3 hf = cam.vanishingPointOf(-Vec3::UnitZ());
    // The forward vanishing point is the image of the point straight ahead on the back wall:
    // it must be finite and in front (w > 0) for the camera to stand in the box.
    if (!(hf.z() > 1e-6) || !dehom(hf, vz_) || (vz_ - Vec2(0.5 * W_, 0.5 * H_)).norm() > 50 * diag_) {
      problem = "the camera looks along a wall (no back wall in view)";
      return false;
    }
    uY_ = Vec2(hy_.x() - vz_.x() * hy_.z(), hy_.y() - vz_.y() * hy_.z());
    uX_ = Vec2(hx_.x() - vz_.x() * hx_.z(), hx_.y() - vz_.y() * hx_.z());
    if (uY_.norm() < 1e-12 || uX_.norm() < 1e-12) {
      problem = "degenerate vanishing points";
      return false;
    }
    uY_.normalize();
    uX_.normalize();
    if (uY_.y() < 0) uY_ = -uY_;
    if (uX_.x() < 0) uX_ = -uX_;
    // Parameter ranges: from the forward point to beyond the farthest image corner.
    const double margin = 0.3 * diag_, eps = 0.01 * diag_;
    double yMin = 0, yMax = 0, xMin = 0, xMax = 0;
    for (const Vec2& c : {Vec2(0, 0), Vec2(W_, 0), Vec2(W_, H_), Vec2(0, H_)}) {
      yMin = std::min(yMin, (c - vz_).dot(uY_));
      yMax = std::max(yMax, (c - vz_).dot(uY_));
      xMin = std::min(xMin, (c - vz_).dot(uX_));
      xMax = std::max(xMax, (c - vz_).dot(uX_));
    }
    lo_ = {yMin - margin, eps, xMin - margin, eps};  // top, bottom, left, right
    hi_ = {-eps, yMax + margin, -eps, xMax + margin};
    outside_ = {std::min(-eps, yMin - eps), std::max(eps, yMax + eps), std::min(-eps, xMin - eps),
                std::max(eps, xMax + eps)};
    buildEvidence();
    defaultParams();
    return true;
  }

  // params: top, bottom (along uY from vz), left, right (along uX).
  std::array<Vec3, 4> lines(const std::array<double, 4>& t) const {
    return {hx_.cross(hom(vz_ + t[0] * uY_)), hx_.cross(hom(vz_ + t[1] * uY_)),
            hy_.cross(hom(vz_ + t[2] * uX_)), hy_.cross(hom(vz_ + t[3] * uX_))};
  }
  bool corners(const std::array<double, 4>& t, std::array<Vec2, 4>& c) const {
    const auto l = lines(t);
    return dehom(l[0].cross(l[2]), c[0]) && dehom(l[0].cross(l[3]), c[1]) &&
           dehom(l[1].cross(l[3]), c[2]) && dehom(l[1].cross(l[2]), c[3]);
  }
  // Parameter of the line through vanishing point `h` and point p, on the reference line
  // through vz along u.
  double paramThrough(const Vec3& h, const Vec2& p, const Vec2& u) const {
    const Vec3 l = h.cross(hom(p));
    const Vec3 ref = hom(vz_).cross(Vec3(u.x(), u.y(), 0));
    Vec2 q;
    if (!dehom(l.cross(ref), q)) return std::numeric_limits<double>::quiet_NaN();
    return (q - vz_).dot(u);
  }
  double paramOfCorner(int line, const Vec2& p) const {
    return line < 2 ? paramThrough(hx_, p, uY_) : paramThrough(hy_, p, uX_);
  }

  struct Score {
    double total = -1e300;
    double edgeSupported = 0, edgeVisible = 0, regionSigned = 0, regionTotal = 0;
    double topSupported = 0, topVisible = 0;        // the back wall's top edge alone
    double bottomSupported = 0, bottomVisible = 0;  // its bottom edge, the floor crease
    double ceilingZ = 0, ceilingY = 0;              // receding and vertical line samples on the ceiling
    double standing = 0;  // in total: the uprights standing on the floor crease
  };

  // Whether the photo shows the box's top edge as a ceiling crease: at least kCeilingSeenShare of
  // its visible part on an edge, and above it a ceiling: receding lines (panels, lights, beams; at
  // least a quarter of the edge's length) outweighing vertical ones (a facade over a roofline,
  // not a ceiling).
  static bool showsCeiling(const Score& s) {
    return s.topVisible > 0 && s.topSupported >= kCeilingSeenShare * s.topVisible &&
           s.ceilingZ > s.ceilingY && s.ceilingZ >= 0.25 * s.topVisible;
  }
  // Why the box of parameters t (scored s) is implausible (BoxRules); empty when it is not.
  // With the top edge held (the search's second pass after a ceiling refusal) it is a ceiling.
  Implausible implausible(const std::array<double, 4>& t, const Score& s) const {
    std::array<Vec2, 4> c;
    if (!corners(t, c)) return {};
    return implausibility(cam(), c, topHeld_ || showsCeiling(s), rules_, refuse_);
  }
  // From now on score() refuses implausible boxes (the search's second pass); topHeld: the top
  // edge is held where the photo shows a ceiling crease.
  void setRefuseImplausible(bool topHeld) {
    refuse_ = true;
    topHeld_ = topHeld;
  }

  // full: also the photo's contrast along the edges (slower; the search's final stages).
  Score score(const std::array<double, 4>& t, bool full = true) const {
    Score s;
    std::array<Vec2, 4> c;
    if (!corners(t, c)) return s;
    s.total = 0;
    // Edges: the back wall's four, then the four receding ones from each corner away from vz.
    const int edgeFamily[8] = {0, 1, 0, 1, 2, 2, 2, 2};
    Vec2 ea[8], eb[8];
    for (int i = 0; i < 4; ++i) {
      ea[i] = c[i];
      eb[i] = c[(i + 1) % 4];
      Vec2 d = c[i] - vz_;
      const double n = d.norm();
      ea[4 + i] = c[i];
      eb[4 + i] = n > 1e-9 ? Vec2(c[i] + d / n * 4 * diag_) : c[i];
    }
    for (int i = 0; i < 8; ++i) {
      Vec2 a = ea[i] * ws_, b = eb[i] * ws_;
      if (!clipToRect(a, b, W_ * ws_, H_ * ws_)) continue;
      const double len = (b - a).norm();
      if (len < 1) continue;
      const double sup = edgeSupport(i, edgeFamily[i], a, b, full);
      s.edgeSupported += sup;
      s.edgeVisible += len;
      if (i == 0) {
        s.topSupported = sup;
        s.topVisible = len;
      }
      if (i == 2) {
        s.bottomSupported = sup;
        s.bottomVisible = len;
      }
    }
    // Faces: inside the quad is the back wall, else the sector around vz between corner rays.
    const auto l = lines(t);
    double sign[4];
    for (int i = 0; i < 4; ++i) sign[i] = l[i].dot(hom(vz_)) >= 0 ? 1 : -1;
    double ang[4];
    for (int i = 0; i < 4; ++i) ang[i] = std::atan2(c[i].y() - vz_.y(), c[i].x() - vz_.x());
    auto rel = [&](double a) {
      double r = a - ang[0];
      while (r < 0) r += 2 * M_PI;
      while (r >= 2 * M_PI) r -= 2 * M_PI;
      return r;
    };
    const double r1 = rel(ang[1]), r2 = rel(ang[2]), r3 = rel(ang[3]);
    const bool ordered = r1 < r2 && r2 < r3;  // TL, TR, BR, BL clockwise around vz
    if (!ordered) {
      s.total = -1e300;
      return s;
    }
    for (const Sample& p : samples_) {
      const Vec3 ph = hom(p.pw / ws_);
      bool inside = true;
      for (int i = 0; i < 4 && inside; ++i) inside = l[i].dot(ph) * sign[i] >= 0;
      int face = kBack;
      if (!inside) {
        const double r = rel(p.angle);
        face = r < r1 ? kCeiling : r < r2 ? kRight : r < r3 ? kFloor : kLeft;
      }
      s.regionSigned += (kAllowed[face][p.family] ? 1.0 : -1.0) * p.weight;
      if (face == kCeiling && p.family == 2) s.ceilingZ += p.weight;
      if (face == kCeiling && p.family == 1) s.ceilingY += p.weight;
      s.regionTotal += p.weight;
    }
    constexpr double kEdgeBias = 0.15;  // evidence below this along an edge counts against it
    constexpr double kRegionWeight = 0.2;
    s.total = s.edgeSupported - kEdgeBias * s.edgeVisible + kRegionWeight * s.regionSigned;
    // Tie-break toward an ordinary room where the photo says nothing (a wall out of view); the
    // top edge toward the one the bottom edge implies (ceilingFromFloor).
    double prior = 0;
    for (int i = 0; i < 4; ++i) {
      const double paired = i == 0 ? ceilingFromFloor(t[1]) : std::numeric_limits<double>::quiet_NaN();
      prior += std::abs(t[i] - (std::isfinite(paired) ? paired : default_[i])) / diag_;
    }
    s.total -= 0.5 * ws_ * prior;
    // Vertical edges standing on the floor crease (the back wall's bottom edge, BL to BR).
    s.standing = kStandingWeight * ws_ * standingOn(uprights_, c[3], c[2], uY_, kTopTolLayoutPx / ws_);
    s.total += s.standing;
    if (refuse_ && implausible(t, s)) s.total = -1e300;
    return s;
  }

  // The top edge (line 0's parameter) that a bottom edge at parameter tBottom implies: the floor
  // crease fixes the back wall's distance (the camera stands heightM above the floor), and the
  // ceiling is the ordinary room's, 2.7 m over a 1.6 m eye (scaled with heightM, as
  // defaultParams). So a ceiling out of view sits where the visible floor says, not at a
  // 5 m-deep wall's. NaN when the bottom edge is not below the horizon.
  double ceilingFromFloor(double tBottom) const {
    const Camera& c = cam();
    const Vec3 d = c.directionThroughPixel(vz_ + tBottom * uY_);
    if (!(d.y() < -1e-9) || !d.allFinite()) return std::numeric_limits<double>::quiet_NaN();
    const Vec3 floorPoint = c.centreWorld() + d * (c.heightM / -d.y());
    const auto top = c.project(floorPoint + Vec3(0, c.heightM * 2.7 / 1.6, 0));
    return top ? paramOfCorner(0, *top) : std::numeric_limits<double>::quiet_NaN();
  }

  // The support of box edge `slot` (family f, visible part a-b in layout pixels): the evidence
  // along it, floored by the photo's contrast (full). The coordinate ascent moves one line at a
  // time, which leaves three of the eight edges where they were: the last value per slot is
  // kept.
  double edgeSupport(int slot, int f, const Vec2& a, const Vec2& b, bool full) const {
    EdgeMemo& memo = memo_[slot];
    if (memo.valid && memo.full == full && memo.a == a && memo.b == b) return memo.value;
    const double len = (b - a).norm();
    const int n = std::max(2, int(len / 4.0));
    // Slot 2 is the back wall's bottom edge, the floor crease: no furniture top supports it.
    const bool crease = slot == 2;
    const double floor = full ? kContrastWeight * contrastAlong(f, a, b, false, crease) : 0.0;
    const EvidenceMap& ev = crease ? floorEvidence_ : evidence_[f];
    double sum = 0;
    for (int k = 0; k < n; ++k) sum += std::max(floor, double(ev.at(a + (b - a) * ((k + 0.5) / n))));
    memo = {true, full, a, b, sum / n * len};
    return memo.value;
  }

  // Where the photo shows an edge along line i (0 top, 1 bottom: x lines; 2 left, 3 right: y
  // lines) with no segment found: the strongest local maxima of the summed contrast along the
  // line, swept over its parameter range in steps of about a layout pixel.
  std::vector<double> contrastCandidates(int i, size_t keep) const {
    std::vector<double> out;
    if (!in_.edges) return out;
    const Vec2& u = i < 2 ? uY_ : uX_;
    const Vec3& h = i < 2 ? hx_ : hy_;
    const double step = 1.0 / ws_;
    const double t0 = std::max(lo_[i], outside_[i < 2 ? 0 : 2]),
                 t1 = std::min(hi_[i], outside_[i < 2 ? 1 : 3]);
    std::vector<std::pair<double, double>> prof;  // (param, summed contrast)
    for (double t = t0; t <= t1; t += step) {
      const Vec3 l = h.cross(hom(vz_ + t * u));
      // The line's visible part: intersect with the photo through two far points on it.
      const Vec2 dir(l.y(), -l.x());
      if (dir.norm() < 1e-12) continue;
      const Vec2 base = vz_ + t * u;
      Vec2 a = (base - 4 * diag_ * dir.normalized()) * ws_,
           b = (base + 4 * diag_ * dir.normalized()) * ws_;
      double sum = 0;
      if (clipToRect(a, b, W_ * ws_, H_ * ws_)) sum = contrastAlong(i < 2 ? 0 : 1, a, b, true, i == 1);
      prof.push_back({t, sum});
    }
    std::vector<std::pair<double, double>> peaks;  // (sum, param)
    for (size_t k = 1; k + 1 < prof.size(); ++k)
      if (prof[k].second > prof[k - 1].second && prof[k].second >= prof[k + 1].second &&
          prof[k].second > 15.0)
        peaks.push_back({prof[k].second, prof[k].first});
    std::sort(peaks.begin(), peaks.end(),
              [](const auto& x, const auto& y) { return x.first > y.first; });
    for (size_t k = 0; k < std::min(keep, peaks.size()); ++k) out.push_back(peaks[k].second);
    return out;
  }

  // lineContrast of the segment a-b (layout pixels) of a family-f line.
  // longestRun: instead, the length (layout pixels) of its longest stretch that is an edge (a
  // line through the photo crosses other surfaces beyond the back wall's corners).
  // floorCrease: the floor crease's contrast (floorAcross_; f is 0).
  double contrastAlong(int f, const Vec2& a, const Vec2& b, bool longestRun = false,
                       bool floorCrease = false) const {
    if (across_[f].empty()) return 0;
    const double len = (b - a).norm();
    const int n = int(len / kContrastStepPx);
    if (n < 2) return 0;
    std::vector<float>& v = scratch_;
    v.clear();
    const cv::Mat& m = floorCrease && !floorAcross_.empty() ? floorAcross_ : across_[f];
    for (int k = 0; k < n; ++k) {
      const Vec2 q = a + (b - a) * ((k + 0.5) / n);
      const int x = std::clamp(int(q.x()), 0, m.cols - 1), y = std::clamp(int(q.y()), 0, m.rows - 1);
      v.push_back(m.at<float>(y, x));
    }
    return longestRun ? kContrastStepPx * longestEdgeRun(v, in_.edges->noise)
                      : lineContrast(v, in_.edges->noise);
  }

  const std::array<double, 4>& lo() const { return lo_; }
  const std::array<double, 4>& hi() const { return hi_; }
  const std::array<double, 4>& defaults() const { return default_; }
  const std::array<double, 4>& outside() const { return outside_; }
  // The end of a receding segment nearer the forward vanishing point (deeper in the room).
  Vec2 farEnd(const LineSegment& s) const {
    return (s.aPx - vz_).norm() < (s.bPx - vz_).norm() ? s.aPx : s.bPx;
  }
  double diag() const { return diag_; }
  bool bordersBright(size_t i) const { return bright_[i]; }

 private:
  // Segments along a saturated patch (a window, a lamp, a sunlit floor patch: the photo is
  // clipped on one side of them over most of their length) are the patch's outline, not the
  // room's edges: they vote for no box edge (they still count where they lie, for the faces).
  void markBright() {
    bright_.assign(in_.segments->size(), false);
    if (!in_.edges || in_.edges->clipped.empty()) return;
    const cv::Mat& m = in_.edges->clipped;
    for (size_t i = 0; i < in_.segments->size(); ++i) {
      const LineSegment& s = (*in_.segments)[i];
      const Vec2 a = s.aPx * ws_, b = s.bPx * ws_;
      const double len = (b - a).norm();
      if (len < 1) continue;
      const Vec2 n = Vec2(a.y() - b.y(), b.x() - a.x()) / len;
      const int count = std::max(3, int(len / 2));
      int side[2] = {0, 0};
      for (int k = 0; k < count; ++k) {
        const Vec2 p = a + (b - a) * ((k + 0.5) / count);
        for (int j = 0; j < 2; ++j) {
          const Vec2 q = p + (j ? 2.0 : -2.0) * n;
          const int x = int(q.x()), y = int(q.y());
          if (x >= 0 && y >= 0 && x < m.cols && y < m.rows && m.at<unsigned char>(y, x)) ++side[j];
        }
      }
      bright_[i] = std::max(side[0], side[1]) * 2 > count;
    }
  }

  // The evidence map of family f (evidence_): exp(-d^2 / 2 sigma^2) of the distance to the
  // family's segments and, for x and y, to the far ends of receding lines. floorCrease: for the
  // back wall's bottom edge, without the furniture's tops (furnitureTops).
  cv::Mat evidenceOf(int f, int w, int h, bool floorCrease) const {
    cv::Mat mask(h, w, CV_8U, cv::Scalar(255));
    for (size_t i = 0; i < in_.segments->size(); ++i) {
      const LineSegment& s = (*in_.segments)[i];
      if (s.family == f && !s.userGiven && !bright_[i] && !(floorCrease && top_[i]))
        cv::line(mask, cv::Point2d(s.aPx.x() * ws_ - 0.5, s.aPx.y() * ws_ - 0.5),
                 cv::Point2d(s.bPx.x() * ws_ - 0.5, s.bPx.y() * ws_ - 0.5), cv::Scalar(0), 1);
    }
    // Receding (z) lines of a floor, ceiling or side wall end where the back wall begins:
    // their far ends mark the back wall's edges, drawn as short x strokes (top and bottom
    // edges) and y strokes (side edges).
    if (f == 0 || f == 1)
      for (size_t i = 0; i < in_.segments->size(); ++i) {
        const LineSegment& s = (*in_.segments)[i];
        if (s.family != 2 || s.userGiven || bright_[i]) continue;
        const Vec2 far = farEnd(s);
        const Vec3& hv = f == 0 ? hx_ : hy_;
        Vec2 dir(hv.x() - far.x() * hv.z(), hv.y() - far.y() * hv.z());
        if (dir.norm() < 1e-12) continue;
        dir = dir.normalized() * (4.0 / ws_);
        const Vec2 a = (far - dir) * ws_, b = (far + dir) * ws_;
        cv::line(mask, cv::Point2d(a.x() - 0.5, a.y() - 0.5), cv::Point2d(b.x() - 0.5, b.y() - 0.5),
                 cv::Scalar(0), 1);
      }
    cv::Mat dist;
    cv::distanceTransform(mask, dist, cv::DIST_L2, 3);
    constexpr double kSigma = 1.2;  // working pixels
    cv::Mat e;
    cv::multiply(dist, dist, e, -1.0 / (2 * kSigma * kSigma));
    cv::exp(e, e);
    return e;
  }

  // The contrast across x lines for the floor crease: none within 2 layout pixels of a
  // furniture top (its edge is the top's, not the crease's).
  void buildFloorAcross() {
    floorAcross_ = across_[0].clone();
    cv::Mat near(floorAcross_.size(), CV_8U, cv::Scalar(0));
    for (size_t i = 0; i < in_.segments->size(); ++i) {
      if (!top_[i]) continue;
      const LineSegment& s = (*in_.segments)[i];
      cv::line(near, cv::Point2d(s.aPx.x() * ws_ - 0.5, s.aPx.y() * ws_ - 0.5),
               cv::Point2d(s.bPx.x() * ws_ - 0.5, s.bPx.y() * ws_ - 0.5), cv::Scalar(255), 5);
    }
    floorAcross_.setTo(0.f, near);
  }

  void buildEvidence() {
    markBright();
    top_ = furnitureTops(*in_.segments, kTopTolLayoutPx / ws_, vz_, kForwardShare * diag_);
    uprights_ = uprightsOf(*in_.segments, bright_, vz_, kForwardShare * diag_);
    const int w = std::max(1, int(std::lround(W_ * ws_))), h = std::max(1, int(std::lround(H_ * ws_)));
    for (int f = 0; f < 3; ++f) evidence_[f].e = evidenceOf(f, w, h, false);
    floorEvidence_.e = evidenceOf(0, w, h, true);
    if (in_.edges && in_.edges->gx.cols == w && in_.edges->gx.rows == h) {
      for (int f = 0; f < 3; ++f) buildAcross(f);
      buildFloorAcross();
    }
    // Samples every 4 working pixels, at most about 400 in all.
    double total = 0;
    for (const LineSegment& s : *in_.segments)
      if (s.family >= 0 && !s.userGiven) total += s.lengthPx() * ws_;
    const double step = std::max(4.0, total / 400.0);
    for (const LineSegment& s : *in_.segments) {
      if (s.family < 0 || s.userGiven) continue;
      const double len = s.lengthPx() * ws_;
      const int n = std::max(1, int(len / step));
      for (int k = 0; k < n; ++k) {
        const Vec2 p = s.aPx + (s.bPx - s.aPx) * ((k + 0.5) / n);
        samples_.push_back({p * ws_, std::atan2(p.y() - vz_.y(), p.x() - vz_.x()), s.family, len / n});
      }
    }
  }

  // The gradient's component across the family-f line through each pixel (the line from the
  // pixel to that family's vanishing point), with a sign that is the same along any such line
  // on one side of the vanishing point.
  void buildAcross(int f) {
    const Vec3 h = cam().vanishingPointOf(Vec3::Unit(f));
    const PhotoEdges& pe = *in_.edges;
    cv::Mat& m = across_[f];
    m.create(pe.gx.rows, pe.gx.cols, CV_32F);
    for (int y = 0; y < m.rows; ++y)
      for (int x = 0; x < m.cols; ++x) {
        const double px = (x + 0.5) / ws_, py = (y + 0.5) / ws_;
        Vec2 d(h.x() - px * h.z(), h.y() - py * h.z());
        const double dn = d.norm();
        if (h.z() < 0) d = -d;  // the same image direction whatever the point's sign
        m.at<float>(y, x) =
            dn > 1e-12 ? float((pe.gx.at<float>(y, x) * -d.y() + pe.gy.at<float>(y, x) * d.x()) / dn)
                       : 0.f;
      }
  }
  const Camera& cam() const { return *in_.camera; }

  // An ordinary room: 5 m wide, the back wall 5 m ahead, the ceiling 1.1 m above a 1.6 m eye.
  void defaultParams() {
    const Camera& cam = *in_.camera;
    const double k = cam.heightM / 1.6;
    const Vec3 eye = cam.centreWorld();
    const Vec3 fwd = cam.worldFromCamera * Vec3(0, 0, -1);
    Vec3 f(fwd.x(), 0, fwd.z());
    f = f.norm() > 1e-6 ? f.normalized() : Vec3(0, 0, -1);
    const double zB = -5.0 * k * std::max(0.3, -f.z());
    const Vec3 p[4] = {
        {-2.5 * k, 2.7 * k, zB}, {2.5 * k, 2.7 * k, zB}, {2.5 * k, 0, zB}, {-2.5 * k, 0, zB}};
    const double fallback[4] = {-0.3 * diag_, 0.3 * diag_, -0.3 * diag_, 0.3 * diag_};
    for (int i = 0; i < 4; ++i) default_[i] = fallback[i];
    const auto a = cam.project(p[0] + Vec3(eye.x(), 0, eye.z()));
    const auto b = cam.project(p[2] + Vec3(eye.x(), 0, eye.z()));
    if (a && b) {
      const double t[4] = {paramOfCorner(0, *a), paramOfCorner(1, *b), paramOfCorner(2, *a),
                           paramOfCorner(3, *b)};
      for (int i = 0; i < 4; ++i)
        if (std::isfinite(t[i])) default_[i] = t[i];
    }
    for (int i = 0; i < 4; ++i) default_[i] = std::clamp(default_[i], lo_[i], hi_[i]);
  }

  const LayoutInput& in_;
  BoxRules rules_;
  bool refuse_ = false, topHeld_ = false;
  int W_ = 0, H_ = 0;
  double ws_ = 1, diag_ = 1;
  Vec3 hx_, hy_;
  Vec2 vz_, uX_, uY_;
  std::array<double, 4> lo_{}, hi_{}, default_{}, outside_{};
  EvidenceMap evidence_[3];
  EvidenceMap floorEvidence_;  // family 0 without the furniture's tops: the floor crease's
  cv::Mat across_[3];
  cv::Mat
      floorAcross_;  // across_[0] without the furniture's tops  // per family: the gradient across that family's line through each pixel
  mutable std::vector<float> scratch_;
  struct EdgeMemo {
    bool valid = false, full = false;
    Vec2 a{0, 0}, b{0, 0};
    double value = 0;
  };
  mutable std::array<EdgeMemo, 8> memo_;  // edgeSupport's last value per edge slot
  std::vector<bool> bright_;              // per segment: outlines a saturated patch (markBright)
  std::vector<bool> top_;                 // per segment: a furniture top (furnitureTops)
  std::vector<Upright> uprights_;         // the verticals that may stand on the floor crease
  std::vector<Sample> samples_;
};

}  // namespace

std::shared_ptr<const PhotoEdges> photoEdgesOf(const cv::Mat& grey8, int photoW, int photoH) {
  if (grey8.empty() || photoW <= 0 || photoH <= 0) return nullptr;
  const double ws = std::min(1.0, kLayoutSidePx / std::max(photoW, photoH));
  const int w = std::max(1, int(std::lround(photoW * ws))),
            h = std::max(1, int(std::lround(photoH * ws)));
  if (w < 8 || h < 8) return nullptr;
  cv::Mat g;
  grey8.convertTo(g, CV_32F, 1.0 / 255.0);
  cv::Mat r;
  cv::resize(g, r, cv::Size(w, h), 0, 0, cv::INTER_AREA);
  auto pe = std::make_shared<PhotoEdges>();
  cv::Sobel(r, pe->gx, CV_32F, 1, 0, 3, 1.0 / 8.0);
  cv::Sobel(r, pe->gy, CV_32F, 0, 1, 3, 1.0 / 8.0);
  // Saturated patches (windows, lamps, sunlit floor): their outlines are not the room's edges.
  cv::Mat clipped = r >= 0.97f;
  cv::dilate(clipped, pe->clipped, cv::Mat::ones(5, 5, CV_8U));
  pe->gx.setTo(0.f, pe->clipped);
  pe->gy.setTo(0.f, pe->clipped);
  cv::Mat mag;
  cv::magnitude(pe->gx, pe->gy, mag);
  std::vector<float> v(mag.begin<float>(), mag.end<float>());
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  pe->noise = v[v.size() / 2];
  return pe;
}

namespace {

// Lines fixed by placed corners: TL fixes top and left, TR top and right, BR bottom and right,
// BL bottom and left.
constexpr int kCornerLines[4][2] = {{0, 2}, {0, 3}, {1, 3}, {1, 2}};

// Candidates per line: lines through its vanishing point and the photo's own segments of that
// family (weighted by length, merged when close), the line just outside the photo, and the
// ordinary room's.
std::vector<double> lineCandidates(const LayoutSearch& search, const LayoutInput& in, int i,
                                   double current) {
  std::vector<double> cand;
  const auto& lo = search.lo();
  const auto& hi = search.hi();
  // Two kinds of votes, clustered separately: lines of the edge's own family (their
  // midpoints), and the far ends of receding lines (where the floor, ceiling or a side wall
  // meets the back wall): the best 4 and 2 clusters.
  for (const bool receding : {false, true}) {
    std::vector<std::pair<double, double>> votes;  // (param, weight)
    for (size_t k = 0; k < in.segments->size(); ++k) {
      const LineSegment& sg = (*in.segments)[k];
      if (sg.userGiven || search.bordersBright(k)) continue;
      const bool mine = (i < 2 && sg.family == 0) || (i >= 2 && sg.family == 1);
      if (receding ? sg.family != 2 : !mine) continue;
      const double v =
          search.paramOfCorner(i, receding ? search.farEnd(sg) : Vec2(0.5 * (sg.aPx + sg.bPx)));
      if (std::isfinite(v) && v >= lo[i] && v <= hi[i]) votes.push_back({v, sg.lengthPx()});
    }
    std::sort(votes.begin(), votes.end());
    std::vector<std::pair<double, double>> merged;  // (weight, param)
    const double tol = 0.01 * search.diag();
    for (size_t a = 0; a < votes.size();) {
      size_t b = a;
      double w = 0, sum = 0;
      while (b < votes.size() && votes[b].first - votes[a].first < tol) {
        w += votes[b].second;
        sum += votes[b].second * votes[b].first;
        ++b;
      }
      merged.push_back({w, sum / w});
      a = b;
    }
    std::sort(merged.begin(), merged.end(),
              [](const auto& x, const auto& y) { return x.first > y.first; });
    const size_t keep = receding ? 2 : 4;
    for (size_t k = 0; k < std::min(keep, merged.size()); ++k) cand.push_back(merged[k].second);
  }
  for (double v : search.contrastCandidates(i, 3)) cand.push_back(v);
  cand.push_back(search.outside()[i]);
  cand.push_back(current);
  // Candidates closer than half a percent of the diagonal are one.
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end(),
                         [&](double x, double y) { return y - x < 0.005 * search.diag(); }),
             cand.end());
  return cand;
}

// The coordinate ascent's starting boxes: every combination of the lines' candidates scored
// on the segments, the best few re-scored with the photo's contrast (a crease no segment
// found); the best two, each also with the top edge its bottom edge implies (a ceiling out of
// view); and the ordinary room.
std::vector<std::array<double, 4>> globalStarts(const LayoutSearch& search, const LayoutInput& in,
                                                const std::array<double, 4>& t,
                                                const std::array<bool, 4>& isFixed) {
  std::array<std::vector<double>, 4> cand;
  for (int i = 0; i < 4; ++i)
    cand[i] = isFixed[i] ? std::vector<double>{t[i]} : lineCandidates(search, in, i, t[i]);
  struct Cand {
    double score;
    std::array<double, 4> t;
  };
  std::vector<Cand> cands;
  auto stop = [&] { return in.cancel && in.cancel->shouldStop(); };
  for (double a : cand[0])
    for (double b : cand[1]) {
      if (stop()) break;
      for (double c : cand[2])
        for (double d : cand[3]) {
          const std::array<double, 4> p{a, b, c, d};
          cands.push_back({search.score(p, false).total, p});
        }
    }
  auto byScore = [](const Cand& x, const Cand& y) { return x.score > y.score; };
  std::sort(cands.begin(), cands.end(), byScore);
  cands.resize(std::min<size_t>(12, cands.size()));
  for (Cand& c : cands) c.score = search.score(c.t).total;
  std::sort(cands.begin(), cands.end(), byScore);
  std::vector<std::array<double, 4>> starts;
  for (size_t i = 0; i < std::min<size_t>(2, cands.size()); ++i) {
    starts.push_back(cands[i].t);
    const double top = search.ceilingFromFloor(cands[i].t[1]);
    if (!isFixed[0] && std::isfinite(top) && top >= search.lo()[0] && top <= search.hi()[0]) {
      starts.push_back(cands[i].t);
      starts.back()[0] = top;
    }
  }
  starts.push_back(t);  // the ordinary room
  return starts;
}

// Coordinate ascent from each start, coarse to fine (a window around the current value,
// shrinking); the best box reached.
std::pair<LayoutSearch::Score, std::array<double, 4>> ascend(
    const LayoutSearch& search, const LayoutInput& in, const std::vector<std::array<double, 4>>& starts,
    const std::array<bool, 4>& isFixed) {
  LayoutSearch::Score best;
  std::array<double, 4> bestT = starts.back();
  auto stop = [&] { return in.cancel && in.cancel->shouldStop(); };
  const auto& lo = search.lo();
  const auto& hi = search.hi();
  for (auto s : starts) {
    LayoutSearch::Score cur = search.score(s);
    double window = in.startCornersPx ? 0.05 : 0.25;
    for (int round = 0; round < 30 && window * search.diag() > 0.5; ++round) {
      if (stop()) break;
      bool improved = false;
      for (int i = 0; i < 4; ++i) {
        if (isFixed[i]) continue;
        const double span = window * search.diag();
        constexpr int kSteps = 8;
        double tried = std::numeric_limits<double>::quiet_NaN();
        for (int k = -kSteps; k <= kSteps; ++k) {
          auto q = s;
          q[i] = std::clamp(s[i] + span * k / kSteps, lo[i], hi[i]);
          // The current value, or the bound again: the same score, never an improvement.
          if (q[i] == s[i] || q[i] == tried) continue;
          tried = q[i];
          const auto sc = search.score(q);
          if (sc.total > cur.total + 1e-9) {
            cur = sc;
            s = q;
            improved = true;
          }
        }
      }
      if (!improved) window *= 0.35;
    }
    if (cur.total > best.total) {
      best = cur;
      bestT = s;
    }
  }
  return {best, bestT};
}

std::string metresText(const BoxSize& b) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%.1f m deep, %.1f m wide", b.depthM, b.widthM);
  std::string out = buf;
  if (std::isfinite(b.ceilingM)) {
    std::snprintf(buf, sizeof buf, ", ceiling %.1f m", b.ceilingM);
    out += buf;
  }
  return out;
}

// The four lines' parameters to start from: the default box's, and those that placed corners
// fix (two corners on one line: the mean parameter).
struct LineParams {
  std::array<double, 4> t{};
  std::array<bool, 4> isFixed{};
  bool anyFixed = false;  // some corner was placed
};

LineParams fixedLineParams(const LayoutSearch& search, const LayoutInput& in) {
  std::array<double, 4> fixedSum{0, 0, 0, 0};
  std::array<int, 4> fixedCount{0, 0, 0, 0};
  LineParams lp;
  for (int c = 0; c < 4; ++c) {
    if (!in.fixedCornersPx[c]) continue;
    lp.anyFixed = true;
    for (int line : kCornerLines[c]) {
      const double t = search.paramOfCorner(line, *in.fixedCornersPx[c]);
      if (!std::isfinite(t)) continue;
      fixedSum[line] += t;
      ++fixedCount[line];
    }
  }
  lp.t = search.defaults();
  for (int i = 0; i < 4; ++i)
    if (fixedCount[i] > 0) {
      lp.isFixed[i] = true;
      lp.t[i] = fixedSum[i] / fixedCount[i];
    }
  return lp;
}

// A correction's one start: each free line through the previous quad's corners. Each line
// passes through two of them: the first that gives a finite parameter.
std::array<double, 4> startFromPrevious(const LayoutSearch& search, const LayoutInput& in,
                                        const LineParams& lp) {
  std::array<double, 4> s = lp.t;
  for (int i = 0; i < 4; ++i) {
    if (lp.isFixed[i]) continue;
    for (int c = 0; c < 4; ++c)
      if (kCornerLines[c][0] == i || kCornerLines[c][1] == i) {
        const double v = search.paramOfCorner(i, (*in.startCornersPx)[c]);
        if (std::isfinite(v)) {
          s[i] = std::clamp(v, search.lo()[i], search.hi()[i]);
          break;
        }
      }
  }
  return s;
}

using BestBox = std::pair<LayoutSearch::Score, std::array<double, 4>>;

// The automatic box only: an implausible best box gives way to the best plausible one (the
// search again, refusing implausible boxes; a ceiling the photo shows stays, the floor crease
// must come down to a plausible one), else to the ordinary room. out.doubts.refused says which.
// Returns true when `out` is final (the ordinary room).
bool replaceImplausibleBox(LayoutSearch& search, const LayoutInput& in, LineParams& lp, BestBox& best,
                           LayoutResult& out) {
  const Implausible why = search.implausible(best.second, best.first);
  if (!why) return false;
  const Camera& cam = *in.camera;
  std::array<Vec2, 4> refusedCorners;
  search.corners(best.second, refusedCorners);
  const BoxSize refused = boxSizeOf(cam, refusedCorners);
  const bool holdTop = why.rule == Implausible::kCeiling || why.rule == Implausible::kExtent;
  if (holdTop) {
    lp.isFixed[0] = true;
    lp.t[0] = best.second[0];
  }
  search.setRefuseImplausible(holdTop);
  auto [best2, bestT2] = ascend(search, in, globalStarts(search, in, lp.t, lp.isFixed), lp.isFixed);
  std::array<Vec2, 4> c2;
  const bool found = best2.total > -1e299 && search.corners(bestT2, c2);
  if (!found || !ledByStandingAlone(best.first.total, best.first.standing, best2.total, best2.standing))
    out.doubts.refused = "the best-supported box (" + metresText(refused) +
                         ") is implausible: " + why.why + "; " +
                         (found ? "the next-best box is used (" + metresText(boxSizeOf(cam, c2)) + ")"
                                : std::string("an ordinary room is assumed"));
  if (found) {
    best = {best2, bestT2};
    return false;
  }
  std::array<Vec2, 4> c0;
  if (search.corners(lp.t, c0)) out.cornersPx = c0;
  out.ok = true;
  out.score01 = 0;
  out.advice = boxAdvice(out.doubts, out.cornersPx, cam.widthPx, cam.heightPx);
  return true;
}

// A corner in a warning: "(x, y)", or "(x, y), outside the photo".
std::string cornerText(const Vec2& p, double W, double H) {
  if (!p.allFinite()) return "(undefined)";
  char b[96];
  const bool inside = p.x() >= -0.5 && p.y() >= -0.5 && p.x() <= W + 0.5 &&
                      p.y() <= H + 0.5;                                     // as printed
  const auto whole = [](double v) { return std::abs(v) < 0.5 ? 0.0 : v; };  // no "-0"
  std::snprintf(b, sizeof b, "(%.0f, %.0f)%s", whole(p.x()), whole(p.y()),
                inside ? "" : ", outside the photo");
  return b;
}

// When the automatic box's floor crease is in view but nothing in the photo marks it (every
// candidate hidden behind furniture, or no horizontal line below the horizon at all): why the
// depth is a guess (for boxAdvice); empty otherwise.
std::string unseenCreaseReason(const LayoutSearch::Score& s) {
  // Under 2 % of the edge on a line or a step in brightness. Chosen on York half A: no box a user
  // accepts warns (a facade's faint base along a sidewalk, P1080005, has 3 %).
  constexpr double kSeenShare = 0.02;
  if (!(s.bottomVisible > 0) || s.bottomSupported >= kSeenShare * s.bottomVisible) return {};
  char buf[160];
  std::snprintf(buf, sizeof buf, "%.0f%%", 100 * s.bottomSupported / s.bottomVisible);
  return "no floor crease is seen along the back wall's bottom edge (" + std::string(buf) +
         " of it on a line or an edge in the photo): the room's depth is a guess";
}

// When the automatic box's floor crease lies below the photo (both bottom corners at or below its
// bottom edge, no part of the crease in view): the box shows no floor, everything in the photo's
// lower part is back wall. Right for a wall photographed from close by; wrong, and silent until
// the fourth York round, when the only lines below the eye are furniture (tops with legs hanging
// from them: no crease to hold the edge; York P1080025, P1080049, P1040801, all rejected boxes).
// Why (for boxAdvice); empty otherwise.
std::string floorOutOfViewReason(const LayoutSearch::Score& s, const Camera& cam,
                                 const std::array<Vec2, 4>& c) {
  const double H = cam.heightPx;
  if (s.bottomVisible > 0 || !(c[2].y() >= H && c[3].y() >= H)) return {};
  const BoxSize b = boxSizeOf(cam, c);
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.1f m", b.depthM);
  return "the back wall's foot lies below the photo (the wall " + std::string(b.ok ? buf : "?") +
         " away): the box shows no floor, and everything in the photo's lower part is taken for "
         "the back wall";
}

// The share of the box the photo supports: its visible edges' support and its faces' agreement
// with the line orientation.
double supportedShare(const LayoutSearch::Score& best) {
  const double edgeFrac = best.edgeVisible > 0 ? best.edgeSupported / best.edgeVisible : 0;
  const double regionFrac = best.regionTotal > 0 ? 0.5 * (1 + best.regionSigned / best.regionTotal) : 0;
  return std::clamp(0.6 * edgeFrac + 0.4 * regionFrac, 0.0, 1.0);
}

}  // namespace

namespace {

// Whether segment v's line passes within `px` of the forward vanishing point: below it, a floor's
// receding lines (tiles, boards) look vertical and may have been taken for verticals.
bool alongForward(const LineSegment& v, const std::optional<Vec2>& forwardPx, double px) {
  if (!forwardPx) return false;
  const Vec2 d = v.bPx - v.aPx;
  const double len = d.norm();
  if (!(len > 0)) return false;
  const Vec2 r = *forwardPx - v.aPx;
  return std::abs(d.x() * r.y() - d.y() * r.x()) / len < px;
}

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

}  // namespace

std::vector<bool> furnitureTops(const std::vector<LineSegment>& segs, double tolPx,
                                const std::optional<Vec2>& forwardPx, double ambiguousPx) {
  std::vector<bool> top(segs.size(), false);
  struct End {
    Vec2 at;
    double length;
  };
  for (size_t i = 0; i < segs.size(); ++i) {
    const LineSegment& s = segs[i];
    if (s.family != 0 || s.userGiven) continue;
    std::vector<End> hanging, standing;
    for (const LineSegment& v : segs) {
      if (v.family != 1 || v.userGiven || alongForward(v, forwardPx, ambiguousPx)) continue;
      // Image y grows downwards: `up` is the vertical's upper end, `down` its lower.
      const bool aUp = v.aPx.y() < v.bPx.y();
      const Vec2& up = aUp ? v.aPx : v.bPx;
      const Vec2& down = aUp ? v.bPx : v.aPx;
      const double du = distanceToSegment(up, s.aPx, s.bPx), dd = distanceToSegment(down, s.aPx, s.bPx);
      if (du <= tolPx && dd > tolPx) hanging.push_back({up, v.lengthPx()});
      else if (dd <= tolPx && du > tolPx) standing.push_back({down, v.lengthPx()});
    }
    // A vertical split where it crosses the segment (a pillar in front of it; on a glossy
    // floor, a door frame and its reflection) is one edge crossing: it counts for neither.
    double hangs = 0, stands = 0;
    std::vector<bool> paired(standing.size(), false);
    for (const End& h : hanging) {
      bool crossing = false;
      for (size_t k = 0; k < standing.size() && !crossing; ++k)
        if (!paired[k] && (standing[k].at - h.at).norm() <= 2 * tolPx) crossing = paired[k] = true;
      if (!crossing) hangs += h.length;
    }
    for (size_t k = 0; k < standing.size(); ++k)
      if (!paired[k]) stands += standing[k].length;
    top[i] = hangs > stands;
  }
  return top;
}

std::vector<Upright> uprightsOf(const std::vector<LineSegment>& segs, const std::vector<bool>& skip,
                                const std::optional<Vec2>& forwardPx, double ambiguousPx) {
  std::vector<Upright> out;
  for (size_t i = 0; i < segs.size(); ++i) {
    const LineSegment& v = segs[i];
    if (v.family != 1 || v.userGiven || (i < skip.size() && skip[i]) ||
        alongForward(v, forwardPx, ambiguousPx) || !v.aPx.allFinite() || !v.bPx.allFinite())
      continue;
    const bool aUp = v.aPx.y() < v.bPx.y();  // image y grows downwards
    out.push_back({aUp ? v.aPx : v.bPx, aUp ? v.bPx : v.aPx});
  }
  return out;
}

namespace {

// Whether u's edge goes on below the line through `a` (downward normal n): another upright lies
// on u's line below it, or hangs from it where u stands (an edge split where it crosses the line).
bool continuesBelow(const std::vector<Upright>& uprights, const Upright& u, const Vec2& a, const Vec2& n,
                    double tolPx) {
  const Vec2 d = u.downPx - u.upPx;
  const double len = d.norm();
  if (!(len > 0)) return false;
  const auto off = [&](const Vec2& p) {
    const Vec2 r = p - u.upPx;
    return std::abs(d.x() * r.y() - d.y() * r.x()) / len;
  };
  for (const Upright& v : uprights) {
    if (&v == &u) continue;
    const double vUp = (v.upPx - a).dot(n), vDown = (v.downPx - a).dot(n);
    const bool inLine = vUp > tolPx && off(v.upPx) <= 1.5 * tolPx && off(v.downPx) <= 1.5 * tolPx;
    const bool hangsHere = std::abs(vUp) <= tolPx && vDown > tolPx &&
                           (v.upPx - u.downPx).norm() <= 2 * tolPx;
    if (inLine || hangsHere) return true;
  }
  return false;
}

}  // namespace

double standingOn(const std::vector<Upright>& uprights, const Vec2& a, const Vec2& b, const Vec2& down,
                  double tolPx) {
  const Vec2 e = b - a;
  const double e2 = e.squaredNorm();
  if (!(e2 > 0) || !std::isfinite(e2) || !down.allFinite()) return 0;
  Vec2 n = Vec2(-e.y(), e.x()) / std::sqrt(e2);  // across the line, pointing down
  if (n.dot(down) < 0) n = -n;
  // Between a and b, within tolPx beyond either end: an edge standing at the line's end (the wall's
  // own corner) counts whether the end lies just inside or just outside it, so the side edges
  // gain nothing by taking it in.
  const double margin = tolPx / std::sqrt(e2);
  double sum = 0;
  for (const Upright& u : uprights) {
    const double t = (u.downPx - a).dot(e) / e2;
    if (!(t >= -margin && t <= 1 + margin)) continue;
    const double below = (u.downPx - a).dot(n), upBelow = (u.upPx - a).dot(n);
    if (std::abs(below) <= tolPx && upBelow < -tolPx && !continuesBelow(uprights, u, a, n, tolPx))
      sum += (u.downPx - u.upPx).norm();
  }
  return sum;
}

bool ledByStandingAlone(double refusedTotal, double refusedStanding, double nextTotal,
                        double nextStanding) {
  const double lead = refusedTotal - nextTotal;
  return std::isfinite(lead) && std::isfinite(refusedStanding - nextStanding) && lead > 0 &&
         lead <= refusedStanding - nextStanding;
}

std::string boxAdvice(const BoxDoubts& r, const std::array<Vec2, 4>& c, double W, double H) {
  std::string why = r.unseenCrease;
  if (!r.refused.empty()) why += (why.empty() ? "" : "; and ") + r.refused;
  if (why.empty()) return {};
  // A refused box: the photo's best evidence misled once, every edge is in doubt; else only the
  // floor crease is.
  const std::string what =
      !r.refused.empty() || r.unseenCrease.empty()
          ? "drag the back wall's corners, now at " + cornerText(c[0], W, H) + ", " +
                cornerText(c[1], W, H) + ", " + cornerText(c[2], W, H) + " and " +
                cornerText(c[3], W, H) +
                ", onto the far wall's corners in the photo (where it meets the floor, the "
                "ceiling and the side walls)"
          : std::string(r.floorOutOfView ? "if the photo shows the floor, " : "") +
                "drag the back wall's bottom corners, now at " + cornerText(c[3], W, H) + " and " +
                cornerText(c[2], W, H) + ", onto the crease where the floor meets the far wall";
  return "check the room box: " + what + "; why: " + why;
}

BoxSize boxSizeOf(const Camera& cam, const std::array<Vec2, 4>& c) {
  BoxSize b;
  const Vec3 o = cam.centreWorld();
  Vec3 foot[2];
  for (int k = 0; k < 2; ++k) {
    const Vec3 d = cam.directionThroughPixel(c[3 - k]);  // BL, then BR
    if (!d.allFinite() || !(d.y() < -1e-9)) return b;
    foot[k] = o + d * (cam.heightM / -d.y());
  }
  const double zBack = 0.5 * (foot[0].z() + foot[1].z());
  if (!(zBack < -1e-6)) return b;
  b.depthM = -zBack;
  b.widthM = foot[1].x() - foot[0].x();
  b.creaseRad = std::atan2(cam.heightM, b.depthM);
  double sum = 0;
  int n = 0;
  for (int i : {0, 1}) {
    const Vec3 d = cam.directionThroughPixel(c[i]);
    if (!d.allFinite() || std::abs(d.z()) < 1e-12) continue;
    const double t = (zBack - o.z()) / d.z();
    if (!(t > 0)) continue;
    sum += o.y() + t * d.y();
    ++n;
  }
  if (n > 0) b.ceilingM = sum / n;
  b.ok = std::isfinite(b.depthM) && std::isfinite(b.widthM);
  return b;
}

Implausible implausibility(const Camera& cam, const std::array<Vec2, 4>& c, bool showsCeiling,
                           const BoxRules& r, bool replacing) {
  const BoxSize b = boxSizeOf(cam, c);
  if (!b.ok) return {};  // not a box at all: the room builder says why
  const double h = cam.heightM;
  char buf[320];
  // The crease's angle is known to s: the horizon's and the crease's own 1-sigma.
  const double s = std::hypot(r.horizonSigmaRad, std::atan(r.creaseSigmaPx / cam.focalPx));
  const double lo = b.creaseRad - 2 * s, hi = b.creaseRad + 2 * s;
  if (!(lo > 0) || std::tan(hi) / std::tan(lo) > r.depthFactor) {
    std::snprintf(buf, sizeof buf,
                  "its floor crease is %.1f deg below the horizon, too near it to place a back "
                  "wall %.1f m away from a camera %.2f m up (the photo bounds that depth only to "
                  "%s)",
                  b.creaseRad * 180 / M_PI, b.depthM, h,
                  lo > 0 ? (std::to_string(int(std::lround(h / std::tan(hi)))) + "-" +
                            std::to_string(int(std::lround(h / std::tan(lo)))) + " m")
                               .c_str()
                         : "no bound");
    return {Implausible::kDepth, buf};
  }
  if (b.widthM < r.minWidthOverEye * h) {
    std::snprintf(buf, sizeof buf, "it is %.2f m wide, too narrow to hold a camera %.2f m up", b.widthM,
                  h);
    return {Implausible::kWidth, buf};
  }
  if (showsCeiling && std::isfinite(b.ceilingM) && b.ceilingM > r.maxCeilingOverEye * h) {
    std::snprintf(buf, sizeof buf,
                  "its ceiling crease, seen in the photo, would be %.1f m up (%.1f camera "
                  "heights) over a floor crease %.1f m away: that floor crease is more likely "
                  "the top of furniture or a sill",
                  b.ceilingM, b.ceilingM / h, b.depthM);
    return {Implausible::kCeiling, buf};
  }
  const double extent = replacing ? std::max(b.depthM, b.widthM) : std::min(b.depthM, b.widthM);
  if (showsCeiling && extent > r.maxRoomOverEye * h) {
    std::snprintf(buf, sizeof buf,
                  "under the ceiling crease the photo shows, a room %.1f m deep and %.1f m wide "
                  "(%s more than %.0f camera heights) means the floor crease lies on furniture, "
                  "a sill or a window's rail",
                  b.depthM, b.widthM, replacing ? "one" : "both", r.maxRoomOverEye);
    return {Implausible::kExtent, buf};
  }
  return {};
}

LayoutResult estimateLayout(const LayoutInput& in) {
  LayoutResult out;
  INLAY_CHECK(in.camera && in.segments);
  const Camera& cam = *in.camera;
  // Whatever happens, a usable default: the middle half of the photo.
  const double W = cam.widthPx, H = cam.heightPx;
  out.cornersPx = {Vec2(0.25 * W, 0.25 * H), Vec2(0.75 * W, 0.25 * H), Vec2(0.75 * W, 0.75 * H),
                   Vec2(0.25 * W, 0.75 * H)};
  LayoutSearch search(in);
  if (!search.setUp(out.problem)) return out;

  LineParams lp = fixedLineParams(search, in);
  const std::vector<std::array<double, 4>> starts =
      in.startCornersPx ? std::vector<std::array<double, 4>>{startFromPrevious(search, in, lp)}
                        : globalStarts(search, in, lp.t, lp.isFixed);
  BestBox best = ascend(search, in, starts, lp.isFixed);
  if (in.refuseImplausible && !lp.anyFixed && !in.startCornersPx && best.first.total > -1e299 &&
      replaceImplausibleBox(search, in, lp, best, out))
    return out;

  std::array<Vec2, 4> c;
  if (!(best.first.total > -1e299) || !search.corners(best.second, c)) {
    out.problem = "no back wall hypothesis fits the vanishing points";
    return out;
  }
  for (int i = 0; i < 4; ++i)
    if (in.fixedCornersPx[i]) c[i] = *in.fixedCornersPx[i];
  out.cornersPx = c;
  out.ok = true;
  out.score01 = supportedShare(best.first);
  if (!lp.isFixed[1] && !in.startCornersPx) {
    BoxDoubts& d = out.doubts;
    d.unseenCrease = unseenCreaseReason(best.first);
    if (d.unseenCrease.empty()) {
      d.unseenCrease = floorOutOfViewReason(best.first, cam, c);
      d.floorOutOfView = !d.unseenCrease.empty();
    }
  }
  out.advice = boxAdvice(out.doubts, out.cornersPx, W, H);
  return out;
}

}  // namespace inlay::detail
