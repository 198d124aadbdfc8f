// The measurements behind docs/architecture.md's "Hand-written or library" rows that run in
// seconds: our resize against OpenImageIO's, the 8-bit sRGB encoder against a pow per value and
// a 65536-entry table, and OpenCV's Otsu threshold against the exact optimum on sorted values.
// One thread each (OIIO's own pool off), best of `repeats`. Writes OUT.csv with one row per
// method: what, method, ms, error (what the error means is in the row's `error_is`).
//
//   build/tests/bench/bench_library_choices OUT.csv [repeats [PHOTO]]
//   /usr/bin/python3 tests/bench/benchlib.py table OUT.csv library_choices
#include "inlay/modeling/image.h"
#include "inlay/modeling/image_io.h"
#include "inlay/lighting/shaft.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace inlay;

int gRepeats = 3;

double bestMs(const std::function<void()>& f) {
  double best = 1e300;
  for (int k = 0; k < gRepeats; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(
        best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

struct Row {
  std::string what, method;
  double ms, error;
  std::string errorIs;
};

ImageF oiioResize(const ImageF& src, int w, int h, const char* filter, float width) {
  OIIO::ImageSpec in(src.width, src.height, src.channels, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf a(in, const_cast<float*>(src.data.data()));
  OIIO::ImageBuf b(OIIO::ImageSpec(w, h, src.channels, OIIO::TypeDesc::FLOAT));
  OIIO::ImageBufAlgo::resize(b, a, filter, width);
  ImageF out(w, h, src.channels);
  b.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, out.data.data());
  return out;
}

// Resize a 12 MP photo to the studio's 1600 x 1200; error: the mean absolute difference from the
// exact area average of a 4:1 shrink (ours is exact there), on the 4032 x 3024 -> 1008 x 756 case.
void resizeRows(std::vector<Row>& rows) {
  ImageF big(4032, 3024, 3);
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0, 1);
  for (float& x : big.data) x = u(rng);
  ImageF exact(1008, 756, 3);
  for (int y = 0; y < 756; ++y)
    for (int x = 0; x < 1008; ++x)
      for (int c = 0; c < 3; ++c) {
        double s = 0;
        for (int j = 0; j < 4; ++j)
          for (int i = 0; i < 4; ++i) s += big.at(4 * x + i, 4 * y + j, c);
        exact.at(x, y, c) = float(s / 16);
      }
  auto meanAbs = [&](const ImageF& a) {
    double s = 0;
    for (size_t i = 0; i < a.data.size(); ++i) s += std::abs(a.data[i] - exact.data[i]);
    return s / double(a.data.size());
  };
  const char* what = "resize 4032x3024 -> 1600x1200";
  const char* errorIs = "mean |value - exact 4:1 area average| at 1008x756";
  ImageF out;
  rows.push_back({what, "ours (resizeImage)", bestMs([&] { out = resizeImage(big, 1600, 1200); }),
                  meanAbs(resizeImage(big, 1008, 756)), errorIs});
  rows.push_back({what, "OIIO resize, default filter",
                  bestMs([&] { out = oiioResize(big, 1600, 1200, "", 0); }),
                  meanAbs(oiioResize(big, 1008, 756, "", 0)), errorIs});
  rows.push_back({what, "OIIO resize, box",
                  bestMs([&] { out = oiioResize(big, 1600, 1200, "box", 4032.f / 1600); }),
                  meanAbs(oiioResize(big, 1008, 756, "box", 4)), errorIs});
}

// Encode 4.8 M linear values (a 1600 x 1000 RGB frame) to 8-bit sRGB; error: values whose code
// differs from lround(255 * linearToSrgb(v)).
void srgbRows(std::vector<Row>& rows) {
  std::vector<float> v(size_t(1600) * 1000 * 3);
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0, 1.2f);
  for (float& x : v) x = u(rng) * u(rng);
  std::vector<unsigned char> exact(v.size()), out(v.size());
  for (size_t i = 0; i < v.size(); ++i)
    exact[i] = (unsigned char)std::lround(255.f * linearToSrgb(v[i]));
  static std::array<unsigned char, 65536> lut;
  for (int i = 0; i < 65536; ++i)
    lut[size_t(i)] = (unsigned char)std::lround(255.f * linearToSrgb(float(i) / 65535.f));
  auto wrong = [&] {
    double n = 0;
    for (size_t i = 0; i < v.size(); ++i) n += out[i] != exact[i];
    return n;
  };
  const char* what = "sRGB encode 4.8 M values";
  const char* errorIs = "codes differing from lround(255 linearToSrgb(v))";
  double ms = bestMs([&] {
    for (size_t i = 0; i < v.size(); ++i) out[i] = srgbCode8(v[i]);
  });
  rows.push_back({what, "srgbCode8 (boundaries + bucket table)", ms, wrong(), errorIs});
  ms = bestMs([&] {
    for (size_t i = 0; i < v.size(); ++i) {
      const float x = v[i];
      // x is in (0, 1) here: adding 0.5 and truncating rounds it (what the LUT variant costs).
      out[i] = !(x > 0.f) ? 0
               : x >= 1.f ? 255
                          : lut[size_t(x * 65535.f + 0.5f)];  // NOLINT(bugprone-incorrect-roundings)
    }
  });
  rows.push_back({what, "65536-entry table (the studio's before)", ms, wrong(), errorIs});
  ms = bestMs([&] {
    for (size_t i = 0; i < v.size(); ++i)
      out[i] = (unsigned char)std::lround(255.f * linearToSrgb(v[i]));
  });
  rows.push_back({what, "pow per value", ms, wrong(), errorIs});
}

// Between-class variance of splitting `v` above `t`.
double betweenClass(const std::vector<double>& v, double t) {
  double s[2] = {0, 0}, n[2] = {0, 0};
  for (double x : v) s[x > t] += x, n[x > t] += 1;
  if (n[0] == 0 || n[1] == 0) return 0;
  const double d = s[0] / n[0] - s[1] / n[1];
  return n[0] * n[1] * d * d;
}

// The best split of the sorted values (exact Otsu, no bins).
double bestBetweenClass(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  double total = 0, s = 0, best = 0;
  for (double x : v) total += x;
  for (size_t i = 0; i + 1 < v.size(); ++i) {
    s += v[i];
    const double n0 = double(i + 1), n1 = double(v.size()) - n0, d = s / n0 - (total - s) / n1;
    best = std::max(best, n0 * n1 * d * d);
  }
  return best;
}

// 500 random two-mode sets of log luminances (200 to 20 200 values); error: the mean fraction
// of the exact optimum's between-class variance the threshold misses.
void otsuRows(std::vector<Row>& rows) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  double loss = 0, ms = 0;
  const int sets = 500;
  for (int k = 0; k < sets; ++k) {
    const int n = 200 + int(u(rng) * 20000);
    const double lit = 0.05 + 0.9 * u(rng), lo = -3 + u(rng), hi = lo + 0.2 + 3 * u(rng);
    std::normal_distribution<double> a(lo, 0.05 + 0.5 * u(rng)), b(hi, 0.05 + 0.5 * u(rng));
    std::vector<double> v(size_t(n), 0.0);
    for (double& x : v) x = u(rng) < lit ? b(rng) : a(rng);
    double t = 0, mLow = 0, mHigh = 0;
    ms += bestMs([&] { t = detail::otsuThreshold(v, &mLow, &mHigh); });
    loss += 1 - betweenClass(v, t) / bestBetweenClass(v);
  }
  rows.push_back({"Otsu threshold, 500 two-mode sets", "cv::threshold(THRESH_OTSU) on 256 levels",
                  ms / sets, loss / sets,
                  "mean share of the exact optimum's between-class variance missed"});
}

// Loading a photo as the engine does (linear float, EXIF applied, checks) and encoding it for the
// screen: what the studio's quick preview would cost through image_io instead of QImageReader.
void photoRows(std::vector<Row>& rows, const std::string& path) {
  std::vector<unsigned char> codes;
  const double ms = bestMs([&] {
    const auto loaded = loadImage(path);
    if (!loaded) return;
    codes.resize(loaded->linearRgb.data.size());
    for (size_t i = 0; i < codes.size(); ++i) codes[i] = srgbCode8(loaded->linearRgb.data[i]);
  });
  rows.push_back({"photo preview " + path.substr(path.find_last_of('/') + 1), "loadImage + srgbCode8",
                  ms, 0, "(time only)"});
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_library_choices OUT.csv [repeats [PHOTO]]\n");
    return 2;
  }
  if (argc > 2) gRepeats = std::max(1, std::atoi(argv[2]));
  const std::string photo = argc > 3 ? argv[3] : "";
  OIIO::attribute("threads", 1);
  std::vector<Row> rows;
  srgbRows(rows);
  otsuRows(rows);
  resizeRows(rows);
  if (!photo.empty()) photoRows(rows, photo);
  std::ofstream csv(argv[1]);
  csv << "what,method,ms,error,error_is\n";
  for (const Row& r : rows) {
    csv << '"' << r.what << "\",\"" << r.method << "\"," << r.ms << ',' << r.error << ",\"" << r.errorIs
        << "\"\n";
    std::printf("%-36s %-42s %10.2f ms  error %.4g (%s)\n", r.what.c_str(), r.method.c_str(), r.ms,
                r.error, r.errorIs.c_str());
  }
  return csv ? 0 : 1;
}
