// Image I/O: round trips, EXIF orientation and focal length, corrupt and hostile files, atomic
// writes, resampling. Test images are made here (hand-written PNG/EXIF bytes where needed).
#include "inlay/modeling/image_io.h"

#include "test_support.h"

#include <chrono>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/resource.h>

namespace inlay {
namespace {

namespace fs = std::filesystem;

using test::countFiles;
using test::FileSizeCap;
using test::readBytes;

void writeBytes(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

uint32_t crc32(const std::string& data) {
  uint32_t c = 0xffffffffu;
  for (unsigned char b : data) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return ~c;
}
void putBe32(std::string& s, uint32_t v) {
  for (int i = 3; i >= 0; --i) s.push_back(char((v >> (8 * i)) & 0xff));
}
void putLe16(std::string& s, uint32_t v) {
  s.push_back(char(v & 0xff));
  s.push_back(char((v >> 8) & 0xff));
}
void putLe32(std::string& s, uint32_t v) {
  putLe16(s, v & 0xffff);
  putLe16(s, v >> 16);
}
std::string pngChunk(const std::string& type, const std::string& payload) {
  std::string c;
  putBe32(c, uint32_t(payload.size()));
  c += type + payload;
  putBe32(c, crc32(type + payload));
  return c;
}
const std::string kPngSignature("\x89PNG\r\n\x1a\n", 8);

std::string ihdr(uint32_t w, uint32_t h, int bitDepth, int colourType) {
  std::string p;
  putBe32(p, w);
  putBe32(p, h);
  p += char(bitDepth);
  p += char(colourType);
  p += std::string(3, '\0');
  return pngChunk("IHDR", p);
}

// zlib stream with one stored (uncompressed) deflate block.
std::string zlibStored(const std::string& raw) {
  std::string z("\x78\x01", 2);
  z += char(1);  // final stored block
  putLe16(z, uint32_t(raw.size()));
  putLe16(z, uint32_t(~raw.size() & 0xffff));
  z += raw;
  uint32_t a = 1, b = 0;
  for (unsigned char c : raw) {
    a = (a + c) % 65521;
    b = (b + a) % 65521;
  }
  putBe32(z, (b << 16) | a);
  return z;
}

// A minimal little-endian EXIF APP1 payload: IFD0 (Make, Model, Orientation, Exif pointer)
// and an Exif IFD (FocalLength, FocalPlaneXResolution, FocalPlaneResolutionUnit,
// FocalLengthIn35mmFilm).
std::string exifPayload(int orientation, const std::string& make, const std::string& model,
                        uint32_t focalTenthsMm, uint32_t planeResPerInch, int f35) {
  struct Entry {
    uint16_t tag, type;
    uint32_t count;
    std::string data;  // value bytes (placed inline when <= 4)
  };
  auto shortVal = [](uint32_t v) {
    std::string s;
    putLe16(s, v);
    return s;
  };
  auto rational = [](uint32_t n, uint32_t d) {
    std::string s;
    putLe32(s, n);
    putLe32(s, d);
    return s;
  };
  const std::string makeZ = make + '\0', modelZ = model + '\0';
  std::vector<Entry> ifd0 = {{0x010F, 2, uint32_t(makeZ.size()), makeZ},
                             {0x0110, 2, uint32_t(modelZ.size()), modelZ},
                             {0x0112, 3, 1, shortVal(uint32_t(orientation))},
                             {0x8769, 4, 1, ""}};
  std::vector<Entry> exif = {{0x920A, 5, 1, rational(focalTenthsMm, 10)},
                             {0xA20E, 5, 1, rational(planeResPerInch, 1)},
                             {0xA210, 3, 1, shortVal(2)},
                             {0xA405, 3, 1, shortVal(uint32_t(f35))}};
  const uint32_t ifd0At = 8, exifAt = ifd0At + 2 + 12 * 4 + 4, dataAt = exifAt + 2 + 12 * 4 + 4;
  std::string tiff("II\x2a\x00", 4), data;
  putLe32(tiff, ifd0At);
  auto writeIfd = [&](const std::vector<Entry>& entries) {
    putLe16(tiff, uint32_t(entries.size()));
    for (const Entry& e : entries) {
      putLe16(tiff, e.tag);
      putLe16(tiff, e.type);
      putLe32(tiff, e.count);
      if (e.tag == 0x8769) {
        putLe32(tiff, exifAt);
      } else if (e.data.size() <= 4) {
        tiff += e.data + std::string(4 - e.data.size(), '\0');
      } else {
        putLe32(tiff, dataAt + uint32_t(data.size()));
        data += e.data;
      }
    }
    putLe32(tiff, 0);
  };
  writeIfd(ifd0);
  writeIfd(exif);
  EXPECT_EQ(tiff.size(), dataAt);
  return std::string("Exif\0\0", 6) + tiff + data;
}

// Inserts an APP1 segment right after the JPEG SOI marker.
std::string withApp1(const std::string& jpeg, const std::string& payload) {
  std::string seg("\xff\xe1", 2);
  seg += char(((payload.size() + 2) >> 8) & 0xff);
  seg += char((payload.size() + 2) & 0xff);
  return jpeg.substr(0, 2) + seg + payload + jpeg.substr(2);
}

// 32 x 16 with flat quadrants: top-left red, top-right green, bottom-left blue, bottom-right
// white.
ImageF quadrants() {
  ImageF img(32, 16, 3);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x) {
      const bool right = x >= 16, bottom = y >= 8;
      Vec3 c = !bottom ? (right ? Vec3(0, 1, 0) : Vec3(1, 0, 0))
                       : (right ? Vec3(1, 1, 1) : Vec3(0, 0, 1));
      img.setRgb(x, y, c);
    }
  return img;
}

// Colour of the quadrant around (x, y): 'r', 'g', 'b', 'w' or '?'.
char colourAt(const ImageF& img, int x, int y) {
  const Vec3 c = img.rgb(x, y);
  auto hi = [](double v) { return v > 0.7; };
  auto lo = [](double v) { return v < 0.1; };
  if (hi(c[0]) && lo(c[1]) && lo(c[2])) return 'r';
  if (lo(c[0]) && hi(c[1]) && lo(c[2])) return 'g';
  if (lo(c[0]) && lo(c[1]) && hi(c[2])) return 'b';
  if (hi(c[0]) && hi(c[1]) && hi(c[2])) return 'w';
  return '?';
}

TEST(ImageIo, PngRoundTripWithinOneStep) {
  const auto dir = test::tempDir("png_rt");
  ImageF img(7, 5, 3);
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = float((i * 37) % 101) / 100.f;
  const std::string path = (dir / "a.png").string();
  ASSERT_TRUE(saveImage(path, img).ok());
  auto loaded = loadImage(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message();
  EXPECT_TRUE(loaded->wasSrgbEncoded);
  EXPECT_EQ(loaded->sourceBitsPerChannel, 8);
  ASSERT_EQ(loaded->linearRgb.width, 7);
  ASSERT_EQ(loaded->linearRgb.height, 5);
  for (size_t i = 0; i < img.data.size(); ++i)
    EXPECT_NEAR(linearToSrgb(loaded->linearRgb.data[i]), linearToSrgb(img.data[i]), 1.0 / 255.0) << i;
  EXPECT_EQ(countFiles(dir), 1u);  // no temporary left behind
}

TEST(ImageIo, ExrFloatRoundTripIsExact) {
  const auto dir = test::tempDir("exr_rt");
  ImageF img(5, 3, 3);
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = 0.001f * float(i * i) + 1e-5f;
  img.data[4] = 123.456f;  // above 1: linear files are not clamped
  const std::string path = (dir / "a.exr").string();
  ASSERT_TRUE(saveImage(path, img, SaveOptions{.exrHalf = false}).ok());
  auto loaded = loadImage(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message();
  EXPECT_FALSE(loaded->wasSrgbEncoded);
  EXPECT_EQ(loaded->sourceBitsPerChannel, 32);
  EXPECT_EQ(loaded->linearRgb.data, img.data);

  ASSERT_TRUE(saveImage(path, img, SaveOptions{.exrHalf = true}).ok());
  loaded = loadImage(path);
  ASSERT_TRUE(loaded.ok());
  EXPECT_EQ(loaded->sourceBitsPerChannel, 16);
  for (size_t i = 0; i < img.data.size(); ++i)
    EXPECT_NEAR(loaded->linearRgb.data[i], img.data[i], 1e-3 * std::max(1.f, img.data[i]));
}

TEST(ImageIo, HdrAndTiffRoundTrip) {
  const auto dir = test::tempDir("hdr_rt");
  ImageF img(4, 4, 3);
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = 0.05f + 0.1f * float(i % 9);
  auto hdr = (dir / "a.hdr").string();
  ASSERT_TRUE(saveImage(hdr, img).ok());
  auto loaded = loadImage(hdr);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message();
  EXPECT_FALSE(loaded->wasSrgbEncoded);
  for (size_t i = 0; i < img.data.size(); ++i)
    EXPECT_NEAR(loaded->linearRgb.data[i], img.data[i], 0.85 / 128);  // shared exponent
  auto tif = (dir / "a.tif").string();
  ASSERT_TRUE(saveImage(tif, img).ok());
  loaded = loadImage(tif);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message();
  for (size_t i = 0; i < img.data.size(); ++i)
    EXPECT_NEAR(linearToSrgb(loaded->linearRgb.data[i]), linearToSrgb(img.data[i]), 1.0 / 255.0);
}

TEST(ImageIo, OnePixelImage) {
  const auto dir = test::tempDir("one_px");
  ImageF img(1, 1, 3);
  img.setRgb(0, 0, Vec3(0.25, 0.5, 1.0));
  for (const char* name : {"p.png", "p.exr", "p.jpg"}) {
    const std::string path = (dir / name).string();
    ASSERT_TRUE(saveImage(path, img).ok()) << name;
    auto loaded = loadImage(path);
    ASSERT_TRUE(loaded.ok()) << name << ": " << loaded.error().message();
    ASSERT_EQ(loaded->linearRgb.width, 1);
    ASSERT_EQ(loaded->linearRgb.height, 1);
    EXPECT_NEAR(loaded->linearRgb.at(0, 0, 1), 0.5, 0.03) << name;
  }
}

TEST(ImageIo, GreyAndAlphaBecomeRgb) {
  const auto dir = test::tempDir("grey");
  ImageF grey(3, 2, 1, 0.2f);
  ImageF rgba(3, 2, 4, 0.6f);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) rgba.at(x, y, 3) = 0.0f;  // fully transparent: alpha is dropped
  ASSERT_TRUE(saveImage((dir / "g.png").string(), grey).ok());
  ASSERT_TRUE(saveImage((dir / "a.png").string(), rgba).ok());
  auto g = loadImage((dir / "g.png").string());
  auto a = loadImage((dir / "a.png").string());
  ASSERT_TRUE(g.ok() && a.ok());
  EXPECT_EQ(g->linearRgb.channels, 3);
  EXPECT_EQ(a->linearRgb.channels, 3);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(g->linearRgb.at(2, 1, c), 0.2, 0.005);
    EXPECT_NEAR(a->linearRgb.at(2, 1, c), 0.6, 0.005);
  }
}

TEST(ImageIo, SixteenBitPngIsDecodedFromSrgb) {
  const auto dir = test::tempDir("png16");
  // 3 x 1 grey, 16 bits: 0, 32768, 65535 (filter byte 0 before the row).
  std::string row("\0\x00\x00\x80\x00\xff\xff", 7);
  const std::string png = kPngSignature + ihdr(3, 1, 16, 0) + pngChunk("IDAT", zlibStored(row)) +
                          pngChunk("IEND", "");
  const auto path = dir / "g16.png";
  writeBytes(path, png);
  auto loaded = loadImage(path.string());
  ASSERT_TRUE(loaded.ok()) << loaded.error().message();
  EXPECT_EQ(loaded->sourceBitsPerChannel, 16);
  EXPECT_TRUE(loaded->wasSrgbEncoded);
  ASSERT_EQ(loaded->linearRgb.width, 3);
  EXPECT_FLOAT_EQ(loaded->linearRgb.at(0, 0, 0), 0.f);
  EXPECT_NEAR(loaded->linearRgb.at(1, 0, 2), srgbToLinear(32768.f / 65535.f), 1e-5);
  EXPECT_NEAR(loaded->linearRgb.at(2, 0, 1), 1.f, 1e-6);
}

// 8-bit photos are decoded through a table of the 256 codes: every code gives the sRGB curve's
// value, and encodes back to itself (the response stage re-reads the codes through srgbCode8).
TEST(ImageIo, EveryEightBitCodeDecodesThroughTheSrgbCurve) {
  const auto dir = test::tempDir("codes8");
  ImageF img(16, 16, 3);
  const auto codeAt = [](int k, int c) { return c == 0 ? k : c == 1 ? 255 - k : (k * 7) % 256; };
  for (int k = 0; k < 256; ++k)
    for (int c = 0; c < 3; ++c) img.at(k % 16, k / 16, c) = srgbToLinear(float(codeAt(k, c)) / 255.f);
  const auto path = (dir / "codes.png").string();
  ASSERT_TRUE(saveImage(path, img).ok());
  auto loaded = loadImage(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message();
  EXPECT_EQ(loaded->sourceBitsPerChannel, 8);
  for (int k = 0; k < 256; ++k)
    for (int c = 0; c < 3; ++c) {
      const float v = loaded->linearRgb.at(k % 16, k / 16, c);
      const float want = srgbToLinear(float(codeAt(k, c)) / 255.f);
      ASSERT_NEAR(v, want, 1e-6f * want + 1e-12f) << "code " << codeAt(k, c);
      ASSERT_EQ(int(srgbCode8(v)), codeAt(k, c));
    }
}
// Writes a JPEG of quadrants() with the given EXIF orientation and returns the loaded image.
Expected<LoadedImage> loadOriented(const fs::path& dir, int orientation) {
  const auto plain = dir / "plain.jpg";
  EXPECT_TRUE(saveImage(plain.string(), quadrants()).ok());
  const auto tagged = dir / std::string("o").append(std::to_string(orientation)).append(".jpg");
  writeBytes(tagged,
             withApp1(readBytes(plain), exifPayload(orientation, "TestCam", "TC-1", 350, 2000, 52)));
  return loadImage(tagged.string());
}

TEST(ImageIo, ExifOrientation6RotatesClockwise) {
  auto loaded = loadOriented(test::tempDir("orient6"), 6);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message();
  EXPECT_EQ(loaded->exif.orientation, 6);
  const ImageF& img = loaded->linearRgb;
  ASSERT_EQ(img.width, 16);
  ASSERT_EQ(img.height, 32);
  // The stored top row is shown on the right: red top-right, blue top-left.
  EXPECT_EQ(colourAt(img, 4, 8), 'b');
  EXPECT_EQ(colourAt(img, 12, 8), 'r');
  EXPECT_EQ(colourAt(img, 4, 24), 'w');
  EXPECT_EQ(colourAt(img, 12, 24), 'g');
}

TEST(ImageIo, ExifOrientation8RotatesCounterClockwise) {
  auto loaded = loadOriented(test::tempDir("orient8"), 8);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message();
  EXPECT_EQ(loaded->exif.orientation, 8);
  const ImageF& img = loaded->linearRgb;
  ASSERT_EQ(img.width, 16);
  ASSERT_EQ(img.height, 32);
  EXPECT_EQ(colourAt(img, 4, 8), 'g');
  EXPECT_EQ(colourAt(img, 12, 8), 'w');
  EXPECT_EQ(colourAt(img, 4, 24), 'r');
  EXPECT_EQ(colourAt(img, 12, 24), 'b');
}

TEST(ImageIo, ExifOrientation3And1) {
  auto o3 = loadOriented(test::tempDir("orient3"), 3);
  ASSERT_TRUE(o3.ok());
  EXPECT_EQ(o3->linearRgb.width, 32);
  EXPECT_EQ(colourAt(o3->linearRgb, 8, 4), 'w');
  EXPECT_EQ(colourAt(o3->linearRgb, 24, 12), 'r');
  auto o1 = loadOriented(test::tempDir("orient1"), 1);
  ASSERT_TRUE(o1.ok());
  EXPECT_EQ(colourAt(o1->linearRgb, 8, 4), 'r');
  EXPECT_EQ(colourAt(o1->linearRgb, 24, 12), 'w');
}

TEST(ImageIo, ExifFocalLengthIsRead) {
  auto loaded = loadOriented(test::tempDir("exif_focal"), 1);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message();
  const ExifInfo& e = loaded->exif;
  ASSERT_TRUE(e.focalLengthMm.has_value());
  EXPECT_NEAR(*e.focalLengthMm, 35.0, 1e-6);
  ASSERT_TRUE(e.focalLength35mm.has_value());
  EXPECT_EQ(*e.focalLength35mm, 52);
  ASSERT_TRUE(e.focalPlaneXResolution.has_value());
  EXPECT_NEAR(*e.focalPlaneXResolution, 2000.0, 1e-6);
  EXPECT_EQ(e.focalPlaneResolutionUnit.value_or(0), 2);
  EXPECT_EQ(e.make, "TestCam");
  EXPECT_EQ(e.model, "TC-1");
  // 35 mm equivalent: 52 / 36 of the longer side.
  EXPECT_NEAR(e.focalPx(32, 16).value(), 52.0 / 36.0 * 32.0, 1e-9);
}

TEST(ImageIo, FocalPxFromFocalPlaneResolution) {
  ExifInfo e;
  EXPECT_FALSE(e.focalPx(640, 480).has_value());
  e.focalLengthMm = 35.0;
  EXPECT_FALSE(e.focalPx(640, 480).has_value());
  e.focalPlaneXResolution = 2000.0;  // per inch
  e.focalPlaneResolutionUnit = 2;
  EXPECT_NEAR(e.focalPx(640, 480).value(), 35.0 * 2000.0 / 25.4, 1e-9);
  e.focalPlaneResolutionUnit = 3;  // per cm
  EXPECT_NEAR(e.focalPx(640, 480).value(), 35.0 * 200.0, 1e-9);
  e.focalPlaneResolutionUnit = 1;  // no unit: unusable
  EXPECT_FALSE(e.focalPx(640, 480).has_value());
  e.focalLength35mm = 36.0;  // preferred when present
  EXPECT_NEAR(e.focalPx(480, 640).value(), 640.0, 1e-9);
}

TEST(ImageIo, TruncatedJpegIsAnError) {
  const auto dir = test::tempDir("trunc_jpg");
  ImageF img(64, 64, 3);
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = float((i * 7919) % 255) / 255.f;
  const auto full = dir / "full.jpg";
  ASSERT_TRUE(saveImage(full.string(), img).ok());
  const std::string bytes = readBytes(full);
  const auto cut = dir / "cut.jpg";
  writeBytes(cut, bytes.substr(0, bytes.size() / 2));
  auto loaded = loadImage(cut.string());
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().file, cut.string());
  EXPECT_FALSE(loaded.error().reason.empty());
  // Only the header: also an error, not a crash.
  writeBytes(cut, bytes.substr(0, 20));
  EXPECT_FALSE(loadImage(cut.string()).ok());
}

class TruncatedImage : public ::testing::TestWithParam<const char*> {};

TEST_P(TruncatedImage, IsAnErrorNotACrash) {
  const auto dir = test::tempDir(std::string("trunc_") + GetParam());
  ImageF img(64, 48, 3);
  uint32_t state = 7;
  for (float& x : img.data) {
    state = state * 1664525u + 1013904223u;
    x = float(state >> 8) / float(1u << 24);
  }
  const auto full = dir / (std::string("full.") + GetParam());
  ASSERT_TRUE(saveImage(full.string(), img).ok());
  const std::string bytes = readBytes(full);
  for (size_t cut : {bytes.size() / 2, bytes.size() * 9 / 10, size_t(40)}) {
    const auto p = dir / (std::string("cut.") + GetParam());
    writeBytes(p, bytes.substr(0, cut));
    auto loaded = loadImage(p.string());
    EXPECT_FALSE(loaded.ok()) << GetParam() << " cut at " << cut << " of " << bytes.size();
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, TruncatedImage, ::testing::Values("png", "jpg", "exr", "tif", "hdr"));

TEST(ImageIo, CmykIsConvertedByTheReader) {
  const auto dir = test::tempDir("cmyk");
  const auto path = dir / "cmyk.tif";
  if (std::system("oiiotool --help > /dev/null 2>&1") != 0) GTEST_SKIP() << "no oiiotool";
  ASSERT_EQ(std::system(("oiiotool --pattern constant:color=0.1,0.2,0.3,0.4 8x8 4 "
                         "--chnames C,M,Y,K -d uint8 --attrib tiff:ColorSpace CMYK -o " +
                         path.string() + " > /dev/null 2>&1")
                            .c_str()),
            0);
  auto loaded = loadImage(path.string());
  ASSERT_TRUE(loaded.ok()) << loaded.error().message();
  // R = (1 - C)(1 - K) and so on, then sRGB-decoded (8-bit quantised).
  EXPECT_NEAR(linearToSrgb(loaded->linearRgb.at(3, 3, 0)), 0.9 * 0.6, 2.0 / 255);
  EXPECT_NEAR(linearToSrgb(loaded->linearRgb.at(3, 3, 1)), 0.8 * 0.6, 2.0 / 255);
  EXPECT_NEAR(linearToSrgb(loaded->linearRgb.at(3, 3, 2)), 0.7 * 0.6, 2.0 / 255);
}

TEST(ImageIo, PngWithWrongCrcIsAnError) {
  const auto dir = test::tempDir("crc_png");
  ImageF img(8, 8, 3, 0.5f);
  const auto path = dir / "a.png";
  ASSERT_TRUE(saveImage(path.string(), img).ok());
  std::string bytes = readBytes(path);
  // The IHDR CRC sits right after signature (8), length+type (8) and payload (13).
  bytes[8 + 8 + 13] ^= 0x5a;
  writeBytes(path, bytes);
  auto loaded = loadImage(path.string());
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().message().find(path.string()), std::string::npos);
}

TEST(ImageIo, GarbageAndMissingFiles) {
  const auto dir = test::tempDir("garbage");
  writeBytes(dir / "x.png", "this is not a png at all");
  EXPECT_FALSE(loadImage((dir / "x.png").string()).ok());
  writeBytes(dir / "empty.jpg", "");
  EXPECT_FALSE(loadImage((dir / "empty.jpg").string()).ok());
  auto missing = loadImage((dir / "nope.png").string());
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().reason.find("not found"), std::string::npos);
}

TEST(ImageIo, HugeHeaderIsRefusedFastWithoutReadingPixels) {
  const auto dir = test::tempDir("bomb");
  // A valid PNG header claiming 60000 x 60000 RGB (10.8 GB decoded) and a tiny IDAT.
  const std::string png = kPngSignature + ihdr(60000, 60000, 8, 2) +
                          pngChunk("IDAT", zlibStored(std::string(4, '\0'))) + pngChunk("IEND", "");
  const auto path = dir / "bomb.png";
  writeBytes(path, png);
  const auto t0 = std::chrono::steady_clock::now();
  auto loaded = loadImage(path.string());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().reason.find("exceeds"), std::string::npos) << loaded.error().message();
  EXPECT_LT(seconds, 1.0);
  // Limits are the caller's: a small image is refused under a small limit.
  ASSERT_TRUE(saveImage((dir / "s.png").string(), ImageF(5, 4, 3)).ok());
  EXPECT_FALSE(loadImage((dir / "s.png").string(), ImageLimits{.maxPixels = 19}).ok());
  EXPECT_TRUE(loadImage((dir / "s.png").string(), ImageLimits{.maxPixels = 20}).ok());
  EXPECT_FALSE(loadImage((dir / "s.png").string(), ImageLimits{.maxDimension = 4}).ok());
}

// An EXR whose header lies (the OpenEXR reader believes it and allocates first): found by
// fuzz_image, a 517-byte file claiming a 1.6 GB attribute took seconds and that much memory.
TEST(ImageIo, ExrHeaderThatLiesIsRefusedBeforeOpenExrReadsIt) {
  const auto dir = test::tempDir("exr_lies");
  const auto good = dir / "good.exr";
  ASSERT_TRUE(saveImage(good.string(), ImageF(6, 4, 3, 0.25f)).ok());
  const std::string bytes = readBytes(good);
  ASSERT_TRUE(loadImage(good.string()).ok());
  // The file with the int32 `value` written `offset` bytes after the end of `attribute`.
  auto patched = [](std::string b, const std::string& attribute, size_t offset, int32_t value) {
    const size_t at = b.find(attribute);
    EXPECT_NE(at, std::string::npos) << attribute;
    for (int i = 0; i < 4; ++i) b[at + attribute.size() + offset + i] = char(value >> (8 * i));
    return b;
  };
  const std::string channels("channels\0chlist\0", 16);
  // Then the size (4 bytes) and the box xMin, yMin, xMax, yMax: xMax is at 12, yMax at 16.
  const std::string dataWindow("dataWindow\0box2i\0", 17);
  const std::string channelsAt = "attribute 'channels' at byte " + std::to_string(bytes.find(channels));
  struct Case {
    std::string name, bytes, reason;
  } cases[] = {
      {"huge_attribute.exr", patched(bytes, channels, 0, 0x61626364),
       "corrupt EXR: " + channelsAt + " claims 1633837924 bytes, the file has"},
      {"negative_attribute.exr", patched(bytes, channels, 0, -5),
       "corrupt EXR: " + channelsAt + " claims -5 bytes"},
      {"bomb.exr", patched(patched(bytes, dataWindow, 12, 59999), dataWindow, 16, 59999),
       "image of 60000 x 60000 pixels exceeds the limit"},
      {"empty_window.exr", patched(bytes, dataWindow, 12, -3), "corrupt EXR: empty data window"},
      {"cut_value.exr", bytes.substr(0, bytes.find(dataWindow) + 30),
       "attribute 'dataWindow' at byte"},  // ... claims 16 bytes, the file has 9 left
      {"cut_name.exr", bytes.substr(0, bytes.find(dataWindow) + 5),
       "truncated or corrupt EXR: no complete attribute name at byte"},
  };
  for (const Case& c : cases) {
    writeBytes(dir / c.name, c.bytes);
    const auto t0 = std::chrono::steady_clock::now();
    auto loaded = loadImage((dir / c.name).string());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_FALSE(loaded.ok()) << c.name;
    EXPECT_EQ(loaded.error().file, (dir / c.name).string());
    EXPECT_NE(loaded.error().reason.find(c.reason), std::string::npos)
        << c.name << ": " << loaded.error().message();
    EXPECT_LT(seconds, 1.0) << c.name;
  }
}

TEST(ImageIo, UnknownExtensionAndBadImagesAreRefused) {
  const auto dir = test::tempDir("badext");
  EXPECT_FALSE(saveImage((dir / "a.bmpx").string(), ImageF(2, 2, 3)).ok());
  EXPECT_FALSE(saveImage((dir / "a").string(), ImageF(2, 2, 3)).ok());
  EXPECT_FALSE(saveImage((dir / "a.png").string(), ImageF()).ok());
  EXPECT_FALSE(saveImage((dir / "a.png").string(), ImageF(2, 2, 2)).ok());
  EXPECT_FALSE(saveImage((dir / "missing_dir" / "a.png").string(), ImageF(2, 2, 3)).ok());
  EXPECT_EQ(countFiles(dir), 0u);
  // Extensions are case-insensitive.
  ASSERT_TRUE(saveImage((dir / "UPPER.PNG").string(), ImageF(2, 2, 3, 0.5f)).ok());
  EXPECT_TRUE(loadImage((dir / "UPPER.PNG").string()).ok());
}

TEST(ImageIo, FailedWriteLeavesTheOldFile) {
  const auto dir = test::tempDir("atomic");
  const auto path = dir / "user.txt";
  ASSERT_TRUE(writeFileAtomically(path.string(), "old contents").ok());
  EXPECT_TRUE(readBytes(path) == "old contents");
  {
    FileSizeCap cap(4096);
    EXPECT_FALSE(writeFileAtomically(path.string(), std::string(1 << 20, 'x')).ok());
  }
  EXPECT_TRUE(readBytes(path) == "old contents");
  EXPECT_EQ(countFiles(dir), 1u);

  const auto png = dir / "photo.png";
  ASSERT_TRUE(saveImage(png.string(), ImageF(4, 4, 3, 0.5f)).ok());
  const std::string before = readBytes(png);
  ImageF noisy(512, 512, 3);
  uint32_t state = 12345;  // LCG noise: incompressible enough to exceed the cap
  for (float& x : noisy.data) {
    state = state * 1664525u + 1013904223u;
    x = float(state >> 8) / float(1u << 24);
  }
  {
    FileSizeCap cap(4096);
    EXPECT_FALSE(saveImage(png.string(), noisy).ok());
  }
  EXPECT_TRUE(readBytes(png) == before);
  EXPECT_EQ(countFiles(dir), 2u);
  // TIFF takes the other path (temporary file read back before the rename).
  const auto tif = dir / "photo.tif";
  ASSERT_TRUE(saveImage(tif.string(), ImageF(4, 4, 3, 0.5f)).ok());
  const std::string tifBefore = readBytes(tif);
  {
    FileSizeCap cap(4096);
    EXPECT_FALSE(saveImage(tif.string(), noisy).ok());
  }
  EXPECT_TRUE(readBytes(tif) == tifBefore);
  EXPECT_EQ(countFiles(dir), 3u);

  // A writable folder: the new contents replace the old, keeping its permissions.
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  ASSERT_TRUE(writeFileAtomically(path.string(), "new").ok());
  EXPECT_TRUE(readBytes(path) == "new");
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST(ImageIo, LayersExrHasNamedChannels) {
  const auto dir = test::tempDir("layers");
  ImageF composite(4, 3, 3, 0.25f), mask(4, 3, 1, 1.f), rgba(4, 3, 4, 0.5f);
  const auto path = dir / "layers.exr";
  ASSERT_TRUE(saveLayersExr(path.string(),
                            {{"composite", &composite}, {"with_objects", &rgba}, {"mask", &mask}},
                            /*half=*/false)
                  .ok());
  EXPECT_EQ(countFiles(dir), 1u);
  ImageF wrongSize(2, 2, 3);
  EXPECT_FALSE(saveLayersExr(path.string(), {{"composite", &composite}, {"x", &wrongSize}}).ok());
  EXPECT_FALSE(saveLayersExr(path.string(), {{"a.b", &composite}}).ok());
  if (std::system("oiiotool --help > /dev/null 2>&1") != 0) GTEST_SKIP() << "no oiiotool";
  const auto info = dir / "info.txt";
  ASSERT_EQ(std::system(("oiiotool --info -v " + path.string() + " > " + info.string()).c_str()), 0);
  const std::string text = readBytes(info);
  for (const char* ch : {"composite.R", "composite.G", "composite.B", "with_objects.A", "mask.Y"})
    EXPECT_NE(text.find(ch), std::string::npos) << ch << " in\n" << text;
}

TEST(ImageIo, ResizeAveragesWhenShrinkingAndInterpolatesWhenEnlarging) {
  ImageF src(4, 2, 1);
  const float v[8] = {0, 2, 4, 6, 8, 10, 12, 14};
  std::copy(v, v + 8, src.data.begin());
  const ImageF half = resizeImage(src, 2, 1);
  ASSERT_EQ(half.width, 2);
  EXPECT_FLOAT_EQ(half.at(0, 0), (0 + 2 + 8 + 10) / 4.f);
  EXPECT_FLOAT_EQ(half.at(1, 0), (4 + 6 + 12 + 14) / 4.f);
  // Non-integer shrink keeps the mean.
  const ImageF third = resizeImage(src, 3, 1);
  double mean = 0;
  for (float x : third.data) mean += x / 3.0;
  EXPECT_NEAR(mean, 7.0, 1e-5);
  // Enlarge: bilinear between pixel centres, clamped at the edges.
  ImageF row(2, 1, 1);
  row.data = {0.f, 1.f};
  const ImageF big = resizeImage(row, 4, 1);
  ASSERT_EQ(big.data.size(), 4u);
  EXPECT_FLOAT_EQ(big.data[0], 0.f);
  EXPECT_FLOAT_EQ(big.data[1], 0.25f);
  EXPECT_FLOAT_EQ(big.data[2], 0.75f);
  EXPECT_FLOAT_EQ(big.data[3], 1.f);
  ImageF flat(3, 5, 3, 0.4f);
  for (float x : resizeImage(flat, 7, 2).data) EXPECT_NEAR(x, 0.4f, 1e-6);
  EXPECT_TRUE(resizeImage(flat, 0, 2).empty());
}

}  // namespace
}  // namespace inlay
