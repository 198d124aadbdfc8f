// Image input and output through OpenImageIO (the only unit that includes it).
#include "inlay/modeling/image_io.h"
#include "inlay/modeling/parallel.h"
#include "inlay/modeling/response.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <signal.h>
#include <zlib.h>
#include <sys/stat.h>
#include <unistd.h>

namespace inlay {
namespace {

namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

std::string lowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// A unique name beside `path` that keeps its extension (OpenImageIO picks the writer by it).
fs::path tempPathBeside(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const fs::path target(path);
  std::ostringstream name;
  name << '.' << target.stem().string() << ".inlay-tmp-" << ::getpid() << '-'
       << std::hash<std::thread::id>{}(std::this_thread::get_id()) % 100000 << '-'
       << counter.fetch_add(1) << target.extension().string();
  return target.parent_path() / name.str();
}

// Temporaries of processes that died between write and rename (a crash, kill -9, power loss)
// would pile up beside the file: remove those whose process no longer exists. A live process
// that reused the pid keeps them (the safe side).
void removeStaleTemps(const std::string& path) {
  const fs::path target(path);
  const std::string prefix = '.' + target.stem().string() + ".inlay-tmp-";
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
    if (pid <= 0 || pid == long(::getpid())) continue;
    if (::kill(pid_t(pid), 0) != 0 && errno == ESRCH) {
      std::error_code ignored;
      fs::remove(it->path(), ignored);
    }
  }
}

// Renames `temp` over `path`; removes `temp` on failure.
Status commitTemp(const fs::path& temp, const std::string& path) {
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) {
    fs::remove(temp, ec);
    return Error{path, "", "cannot replace the file: " + ec.message()};
  }
  return {};
}

std::string oiioError(const std::string& fallback, const std::string& detail) {
  std::string d = detail;
  while (!d.empty() && (d.back() == '\n' || d.back() == ' ')) d.pop_back();
  return d.empty() ? fallback : fallback + ": " + d;
}

// Source pixel of output pixel (u, v) for EXIF orientation `o` of a W x H stored image.
inline void orientedSource(int o, int w, int h, int u, int v, int& x, int& y) {
  switch (o) {
    case 2:
      x = w - 1 - u;
      y = v;
      break;
    case 3:
      x = w - 1 - u;
      y = h - 1 - v;
      break;
    case 4:
      x = u;
      y = h - 1 - v;
      break;
    case 5:
      x = v;
      y = u;
      break;
    case 6:
      x = v;
      y = h - 1 - u;
      break;
    case 7:
      x = w - 1 - v;
      y = h - 1 - u;
      break;
    case 8:
      x = w - 1 - v;
      y = u;
      break;
    default:
      x = u;
      y = v;
      break;
  }
}

int channelIndex(const OIIO::ImageSpec& spec, const char* name, int fallback) {
  for (int c = 0; c < spec.nchannels; ++c)
    if (spec.channel_name(c) == name) return c;
  return std::min(fallback, spec.nchannels - 1);
}

std::optional<double> positiveFloatAttr(const OIIO::ImageSpec& spec, const char* name) {
  if (!spec.find_attribute(name)) return std::nullopt;
  const double v = spec.get_float_attribute(name, 0.f);
  if (!std::isfinite(v) || v <= 0) return std::nullopt;
  return v;
}

ExifInfo readExif(const OIIO::ImageSpec& spec) {
  ExifInfo e;
  e.focalLengthMm = positiveFloatAttr(spec, "Exif:FocalLength");
  if (spec.find_attribute("Exif:FocalLengthIn35mmFilm")) {
    const int f35 = spec.get_int_attribute("Exif:FocalLengthIn35mmFilm", 0);
    if (f35 > 0) e.focalLength35mm = f35;
  }
  e.focalPlaneXResolution = positiveFloatAttr(spec, "Exif:FocalPlaneXResolution");
  if (spec.find_attribute("Exif:FocalPlaneResolutionUnit"))
    e.focalPlaneResolutionUnit = spec.get_int_attribute("Exif:FocalPlaneResolutionUnit", 0);
  e.orientation = spec.get_int_attribute("Orientation", 1);
  if (e.orientation < 1 || e.orientation > 8) e.orientation = 1;
  e.make = std::string(spec.get_string_attribute("Make"));
  e.model = std::string(spec.get_string_attribute("Model"));
  return e;
}

// Linear float (C = 1, 3 or 4) -> interleaved 8-bit sRGB (or `response`'s encoding when given) with `outChannels` <= C channels
// (grey stays grey, RGBA may drop its alpha for JPEG).
std::vector<unsigned char> toSrgb8(const ImageF& linear, int outChannels,
                                   const CameraResponse* response) {
  std::vector<unsigned char> out(linear.pixelCount() * size_t(outChannels));
  for (size_t i = 0; i < linear.pixelCount(); ++i) {
    const float* p = &linear.data[i * size_t(linear.channels)];
    for (int c = 0; c < outChannels; ++c) {
      if (c < 3 && response) {
        out[i * size_t(outChannels) + size_t(c)] =
            response->encodeCode8(p[linear.channels == 1 ? 0 : c]);
        continue;
      }
      out[i * size_t(outChannels) + size_t(c)] =
          c < 3 ? srgbCode8(p[linear.channels == 1 ? 0 : c])
                : (unsigned char)std::lround(std::clamp(p[c], 0.f, 1.f) * 255.f);  // alpha stays linear
    }
  }
  return out;
}

Status checkImage(const std::string& path, const ImageF& img) {
  if (img.width <= 0 || img.height <= 0 || img.empty())
    return Error{path, "", "cannot write an empty image"};
  if (img.channels != 1 && img.channels != 3 && img.channels != 4)
    return Error{
        path, "",
        "cannot write an image with " + std::to_string(img.channels) + " channels (1, 3 or 4 expected)"};
  if (img.data.size() != img.pixelCount() * size_t(img.channels))
    return Error{path, "", "image buffer size does not match its dimensions"};
  return {};
}

// Writes a temporary file beside `path`, reads it back completely (a short write shows up as a
// decode error), then renames it over `path`.
Status writeViaVerifiedTemp(const std::string& path, const OIIO::ImageSpec& spec,
                            const OIIO::TypeDesc& bufType, const void* pixels) {
  removeStaleTemps(path);
  const fs::path temp = tempPathBeside(path);
  std::error_code ec;
  auto failWith = [&](const std::string& msg) {
    fs::remove(temp, ec);
    return Status(Error{path, "", msg});
  };
  {
    auto out = OIIO::ImageOutput::create(temp.string());
    if (!out) return failWith(oiioError("no writer for this file type", OIIO::geterror()));
    if (!out->open(temp.string(), spec))
      return failWith(oiioError("cannot create a temporary file beside it", out->geterror()));
    const bool wrote = out->write_image(bufType, pixels);
    const std::string writeErr = wrote ? "" : out->geterror();
    if (!out->close() || !wrote)
      return failWith(oiioError("write failed", wrote ? out->geterror() : writeErr));
  }
  {
    auto in = OIIO::ImageInput::open(temp.string());
    std::vector<float> check;
    if (in) check.resize(size_t(in->spec().image_pixels()) * size_t(in->spec().nchannels));
    if (!in || in->spec().width != spec.width || in->spec().height != spec.height ||
        !in->read_image(0, 0, 0, in->spec().nchannels, OIIO::TypeDesc::FLOAT, check.data()) ||
        in->has_error())
      return failWith("write failed: the written file does not read back (disk full?)");
  }
  return commitTemp(temp, path);
}

// Encodes `pixels` (interleaved; `spec.format` is the file's type, `bufType` the buffer's)
// in memory, then writes the bytes through writeFileAtomically, whose every write is checked:
// OpenImageIO's file writers do not all report a short write (a full disk left a truncated PNG
// and returned success), so they never touch the target folder themselves.
Status writeAtomically(const std::string& path, const OIIO::ImageSpec& spec,
                       const OIIO::TypeDesc& bufType, const void* pixels) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return Error{path, "", oiioError("no writer for this file type", OIIO::geterror())};
  // TIFF seeks back to patch its directories, which OpenImageIO 2.4's in-memory proxy gets
  // wrong (an unreadable file): write it beside the target and read it back instead.
  if (!out->supports("ioproxy") || std::string(out->format_name()) == "tiff")
    return writeViaVerifiedTemp(path, spec, bufType, pixels);
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  if (!out->set_ioproxy(&memory) || !out->open(path, spec))
    return Error{path, "", oiioError("cannot encode the image", out->geterror())};
  const bool wrote = out->write_image(bufType, pixels);
  const std::string writeErr = wrote ? "" : out->geterror();
  const bool closed = out->close();
  if (!wrote || !closed)
    return Error{path, "", oiioError("cannot encode the image", wrote ? out->geterror() : writeErr)};
  out.reset();
  return writeFileAtomically(path, std::string(bytes.begin(), bytes.end()));
}

uint32_t bigEndian32(const unsigned char* p) {
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

// What IHDR says, and the concatenated IDAT bytes.
struct PngStream {
  uint32_t width = 0, height = 0;
  int bitDepth = 0, colorType = 0, interlace = 0;
  std::vector<unsigned char> idat;
};

// Bytes per row (without the filter byte) of a non-interlaced PNG; 0 for an invalid header.
uint64_t pngRowBytes(const PngStream& png) {
  int channels = 0;
  switch (png.colorType) {
    case 0:
    case 3: channels = 1; break;
    case 2: channels = 3; break;
    case 4: channels = 2; break;
    case 6: channels = 4; break;
    default: return 0;
  }
  return (uint64_t(png.width) * uint64_t(channels) * uint64_t(png.bitDepth) + 7) / 8;
}

// Inflates the pixel stream without keeping it: every row must start with a filter type 0..4
// and the stream must hold exactly the rows IHDR promises (interlaced: must inflate cleanly).
Status checkPngPixels(const std::string& path, const PngStream& png) {
  const uint64_t row = pngRowBytes(png) + 1;
  if (row == 1) return Error{path, "", "corrupt PNG: invalid IHDR colour type or bit depth"};
  const uint64_t expected = row * png.height;
  z_stream z{};
  if (inflateInit(&z) != Z_OK) return Error{path, "", "cannot inflate the PNG pixel stream"};
  z.next_in = const_cast<unsigned char*>(png.idat.data());
  z.avail_in = uInt(png.idat.size());
  std::vector<unsigned char> buf(1 << 16);
  uint64_t total = 0;
  int rc = Z_OK;
  bool badFilter = false;
  while (rc == Z_OK && !badFilter) {
    z.next_out = buf.data();
    z.avail_out = uInt(buf.size());
    rc = inflate(&z, Z_NO_FLUSH);
    const uint64_t produced = buf.size() - z.avail_out;
    for (uint64_t i = 0; png.interlace == 0 && i < produced; ++i)
      if ((total + i) % row == 0 && buf[i] > 4) badFilter = true;
    total += produced;
    if (rc == Z_BUF_ERROR && produced > 0) rc = Z_OK;  // output buffer was full: go on
  }
  inflateEnd(&z);
  if (badFilter) return Error{path, "", "corrupt PNG: a row has an invalid filter type"};
  if (rc != Z_STREAM_END)
    return Error{path, "",
                 rc == Z_BUF_ERROR ? "truncated PNG: the pixel data ends early"
                                   : "corrupt PNG: the compressed pixel data is invalid"};
  if (png.interlace == 0 && total != expected)
    return Error{path, "",
                 "corrupt PNG: " + std::to_string(total) + " bytes of pixel data, " +
                     std::to_string(expected) + " expected"};
  return {};
}

// A PNG's chunk structure (lengths, CRCs, IEND) and its pixel stream, checked before libpng
// sees the file: libpng reports corrupt data by printing to stderr itself, which would break
// the one clear line a user gets. Files that are not PNG pass unchecked, and so do headers
// beyond `limits` (loadImage refuses them without decoding).
Status checkPng(const std::string& path, const ImageLimits& limits) {
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return Error{path, "", std::string("cannot open: ") + std::strerror(errno)};
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> closer(f, std::fclose);
  unsigned char head[8];
  if (std::fread(head, 1, 8, f) != 8 || std::memcmp(head, kSignature, 8) != 0) return {};
  std::error_code ec;
  const unsigned long long fileSize = fs::file_size(path, ec);
  if (ec) return Error{path, "", "cannot read: " + ec.message()};
  PngStream png;
  std::vector<unsigned char> data;
  long long at = 8;
  for (;;) {
    unsigned char h[8], crc[4];
    if (std::fread(h, 1, 8, f) != 8)
      return Error{
          path, "",
          "truncated PNG: the file ends at byte " + std::to_string(at) + " before its IEND chunk"};
    const uint32_t length = bigEndian32(h);
    const std::string type(reinterpret_cast<const char*>(h + 4), 4);
    const std::string where = "chunk '" + type + "' at byte " + std::to_string(at);
    if (length > 0x7FFFFFFFu) return Error{path, "", "corrupt PNG: " + where + " has an invalid length"};
    // A length beyond the file's end is refused before allocating it (the fuzzer's 1.2 GB chunk).
    if ((unsigned long long)at + 12 + length > fileSize)
      return Error{path, "", "truncated PNG: the file ends inside " + where};
    try {
      data.resize(length);
    } catch (const std::bad_alloc&) {
      return Error{path, "", "not enough memory for PNG " + where};
    }
    if (std::fread(data.data(), 1, length, f) != length || std::fread(crc, 1, 4, f) != 4)
      return Error{path, "", "truncated PNG: the file ends inside " + where};
    // zlib's crc32() is the PNG CRC (ISO 3309, pre- and post-inverted), over type and data.
    uLong c = crc32(crc32(0L, h + 4, 4), data.data(), uInt(data.size()));
    if (uint32_t(c) != bigEndian32(crc))
      return Error{path, "", "corrupt PNG: " + where + " fails its CRC check"};
    if (type == "IHDR" && length == 13) {
      png.width = bigEndian32(data.data());
      png.height = bigEndian32(data.data() + 4);
      png.bitDepth = data[8];
      png.colorType = data[9];
      png.interlace = data[12];
    } else if (type == "IDAT") {
      png.idat.insert(png.idat.end(), data.begin(), data.end());
    } else if (type == "IEND") {
      break;
    }
    at += 12 + (long long)length;
  }
  if (png.width == 0 || png.height == 0 || (long long)png.width * png.height > limits.maxPixels ||
      png.width > uint32_t(limits.maxDimension) || png.height > uint32_t(limits.maxDimension))
    return {};
  return checkPngPixels(path, png);
}

// The header's claimed size against the limits: the one message for every format, given before
// anything is decoded (from the file's own header when we parse it, else from OpenImageIO's).
Status checkImageSize(const std::string& path, long long width, long long height,
                      const ImageLimits& limits) {
  if (width > limits.maxDimension || height > limits.maxDimension || width * height > limits.maxPixels)
    return Error{path, "",
                 "image of " + std::to_string(width) + " x " + std::to_string(height) +
                     " pixels exceeds the limit (" + std::to_string(limits.maxPixels) + " pixels, " +
                     std::to_string(limits.maxDimension) + " per side)"};
  return {};
}

int32_t littleEndian32(const unsigned char* p) {
  return int32_t(uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24);
}

// An EXR header's NUL-terminated name (at most 255 bytes); nullopt at the file's end or when no
// NUL comes. Bytes outside printable ASCII show as '?' (the name goes into a message).
std::optional<std::string> readExrName(std::FILE* f) {
  std::string name;
  for (int c = std::fgetc(f); c != EOF; c = std::fgetc(f)) {
    if (c == 0) return name;
    if (name.size() == 255) return std::nullopt;
    name += (c >= 0x20 && c < 0x7F) ? char(c) : '?';
  }
  return std::nullopt;
}

// An EXR data window (box2i: xMin, yMin, xMax, yMax, inclusive), the next 16 bytes of `f`.
Status checkExrDataWindow(const std::string& path, std::FILE* f, const ImageLimits& limits) {
  unsigned char box[16];
  if (std::fread(box, 1, 16, f) != 16)  // its size was checked against the file's: a disk error
    return Error{path, "", "cannot read: " + std::string(std::strerror(errno))};
  const long long w = (long long)littleEndian32(box + 8) - littleEndian32(box) + 1;
  const long long h = (long long)littleEndian32(box + 12) - littleEndian32(box + 4) + 1;
  if (w <= 0 || h <= 0) return Error{path, "", "corrupt EXR: empty data window"};
  return checkImageSize(path, w, h, limits);
}

// One EXR header (all of it, for each part of a multi-part file): every attribute's claimed size
// must fit in the file, and a data window must fit the limits. OpenEXR allocates and clears an
// attribute's claimed size before reading it, so a 517-byte file claiming a 1.6 GB string took
// seconds and that much memory per load (fuzz_image's slow unit, now in its corpus); a data
// window sizes OpenEXR's line-offset table before OpenImageIO shows us the header.
Status checkExrHeader(const std::string& path, std::FILE* f, unsigned long long fileSize,
                      const ImageLimits& limits) {
  for (;;) {
    const long long at = std::ftell(f);
    const std::optional<std::string> name = readExrName(f);
    if (!name)
      return Error{path, "",
                   "truncated or corrupt EXR: no complete attribute name at byte " + std::to_string(at)};
    if (name->empty()) return {};
    const std::optional<std::string> type = readExrName(f);
    unsigned char sizeBytes[4];
    if (!type || std::fread(sizeBytes, 1, 4, f) != 4)
      return Error{path, "",
                   "truncated or corrupt EXR: attribute '" + *name + "' at byte " + std::to_string(at) +
                       " has no complete type and size"};
    const long long size = littleEndian32(sizeBytes), left = (long long)fileSize - std::ftell(f);
    if (size < 0 || size > left)
      return Error{path, "",
                   "corrupt EXR: attribute '" + *name + "' at byte " + std::to_string(at) + " claims " +
                       std::to_string(size) + " bytes, the file has " + std::to_string(left) + " left"};
    if (*name == "dataWindow" && *type == "box2i" && size == 16) {
      if (Status s = checkExrDataWindow(path, f, limits); !s) return s;
    } else if (std::fseek(f, long(size), SEEK_CUR) != 0) {
      return Error{path, "", "cannot read: " + std::string(std::strerror(errno))};
    }
  }
}

// An OpenEXR file's headers, checked before OpenEXR sees them (see checkExrHeader). Files that
// are not EXR pass unchecked.
Status checkExr(const std::string& path, const ImageLimits& limits) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return Error{path, "", std::string("cannot open: ") + std::strerror(errno)};
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> closer(f, std::fclose);
  unsigned char head[8];
  if (std::fread(head, 1, 8, f) != 8 || littleEndian32(head) != 20000630) return {};
  std::error_code ec;
  const unsigned long long fileSize = fs::file_size(path, ec);
  if (ec) return Error{path, "", "cannot read: " + ec.message()};
  const bool multiPart = (littleEndian32(head + 4) & 0x1000) != 0;
  for (;;) {
    if (Status s = checkExrHeader(path, f, fileSize, limits); !s) return s;
    if (!multiPart) return {};
    const int next = std::fgetc(f);  // a multi-part file ends its list of headers with a NUL
    if (next == 0 || next == EOF) return {};
    std::ungetc(next, f);
  }
}
// The linear value of each 8-bit sRGB code: srgbToLinear of the float OpenImageIO makes of it.
const std::array<float, 256>& codeTable8() {
  static const std::array<float, 256> table = [] {
    std::array<unsigned char, 256> codes{};
    for (int k = 0; k < 256; ++k) codes[size_t(k)] = (unsigned char)k;
    std::array<float, 256> t{};
    OIIO::convert_pixel_values(OIIO::TypeDesc::UINT8, codes.data(), OIIO::TypeDesc::FLOAT, t.data(),
                               256);
    for (float& v : t) v = srgbToLinear(v);
    return t;
  }();
  return table;
}

// The R, G and B source channels of a decoded image (grey: channel 0 three times).
std::array<int, 3> rgbChannels(const OIIO::ImageSpec& spec) {
  if (spec.nchannels < 3) return {0, 0, 0};  // grey (and grey + alpha): alpha dropped
  return {channelIndex(spec, "R", 0), channelIndex(spec, "G", 1), channelIndex(spec, "B", 2)};
}

// The W x H x 3 image of `raw` (spec's size and channels, interleaved) in EXIF orientation
// `o`, each value through `decode`; rows in parallel.
template <class T, class Decode>
ImageF orientedRgbOf(const T* raw, const OIIO::ImageSpec& spec, int o, Decode decode) {
  const bool swap = o >= 5;
  const int W = spec.width, H = spec.height, nch = spec.nchannels;
  const int outW = swap ? H : W, outH = swap ? W : H;
  const std::array<int, 3> ci = rgbChannels(spec);
  ImageF img(outW, outH, 3);
  parallelFor(tbb::blocked_range<int>(0, outH), [&](const tbb::blocked_range<int>& rows) {
    for (int v = rows.begin(); v < rows.end(); ++v)
      for (int u = 0; u < outW; ++u) {
        int x, y;
        orientedSource(o, W, H, u, v, x, y);
        const T* s = &raw[(size_t(y) * size_t(W) + size_t(x)) * size_t(nch)];
        float* d = img.pixel(u, v);
        for (int c = 0; c < 3; ++c) d[c] = decode(s[ci[size_t(c)]]);
      }
  });
  return img;
}

ImageF orientedRgb(const unsigned char* raw, const OIIO::ImageSpec& spec, int o,
                   const std::array<float, 256>& table) {
  return orientedRgbOf(raw, spec, o, [&](unsigned char c) { return table[c]; });
}

ImageF orientedRgb(const float* raw, const OIIO::ImageSpec& spec, int o, bool isLinear) {
  return orientedRgbOf(raw, spec, o, [isLinear](float val) {
    if (!std::isfinite(val)) val = 0.f;
    return isLinear ? std::max(val, 0.f) : srgbToLinear(val);
  });
}

}  // namespace

std::optional<double> ExifInfo::focalPx(int width, int height) const {
  const double longSide = double(std::max(width, height));
  if (longSide <= 0) return std::nullopt;
  if (focalLength35mm && *focalLength35mm > 0) return *focalLength35mm / 36.0 * longSide;
  if (focalLengthMm && focalPlaneXResolution && focalPlaneResolutionUnit) {
    double mmPerUnit = 0;
    switch (*focalPlaneResolutionUnit) {
      case 2: mmPerUnit = 25.4; break;
      case 3: mmPerUnit = 10.0; break;
      case 4: mmPerUnit = 1.0; break;
      default: return std::nullopt;
    }
    const double f = *focalLengthMm * (*focalPlaneXResolution / mmPerUnit);
    if (std::isfinite(f) && f > 0) return f;
  }
  return std::nullopt;
}

Expected<LoadedImage> loadImage(const std::string& path, const ImageLimits& limits) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return Error{path, "", "file not found"};
  if (!fs::is_regular_file(path, ec)) return Error{path, "", "not a regular file"};
  if (fs::file_size(path, ec) == 0) return Error{path, "", "empty file"};
  if (Status s = checkPng(path, limits); !s) return s.error();
  if (Status s = checkExr(path, limits); !s) return s.error();

  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // colour as stored, not premultiplied
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) return Error{path, "", oiioError("cannot read the image", OIIO::geterror())};
  const OIIO::ImageSpec spec = in->spec();  // header only: nothing decoded yet

  // Decompression-bomb guard, from the header alone.
  if (spec.width <= 0 || spec.height <= 0 || spec.depth > 1)
    return Error{path, "", "invalid image dimensions"};
  if (Status s = checkImageSize(path, spec.width, spec.height, limits); !s) return s.error();
  if (spec.width < limits.minDimension || spec.height < limits.minDimension)
    return Error{path, "",
                 "image of " + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                     " pixels is too small (at least " + std::to_string(limits.minDimension) +
                     " per side)"};
  if (spec.nchannels < 1 || spec.nchannels > 64)
    return Error{path, "", "unsupported channel count " + std::to_string(spec.nchannels)};

  // OpenImageIO converts CMYK JPEG/TIFF to RGB itself (channels R, G, B); raw CMYK channels
  // would need a colour profile we do not have.
  if (spec.nchannels >= 4 && spec.channel_name(0) == "C" && spec.channel_name(1) == "M" &&
      spec.channel_name(2) == "Y")
    return Error{path, "", "CMYK images are not supported; convert the photo to RGB"};

  const std::string formatName = in->format_name();
  const bool floatData = spec.format.basetype == OIIO::TypeDesc::FLOAT ||
                         spec.format.basetype == OIIO::TypeDesc::HALF ||
                         spec.format.basetype == OIIO::TypeDesc::DOUBLE;
  const bool isLinear = formatName == "openexr" || formatName == "hdr" || floatData;

  const int nch = spec.nchannels;
  // 8-bit sources are read as their codes and decoded through a table of the 256 codes (what
  // the float path gives them, bit for bit, a quarter of its memory and no pow per value).
  const bool codes8 = !isLinear && spec.format.basetype == OIIO::TypeDesc::UINT8;
  const size_t values = size_t(spec.width) * size_t(spec.height) * size_t(nch);
  std::vector<unsigned char> raw8;
  std::vector<float> rawF;
  try {
    codes8 ? raw8.resize(values) : rawF.resize(values);
  } catch (const std::bad_alloc&) {
    return Error{path, "", "not enough memory for the image"};
  }
  const bool read = codes8 ? in->read_image(0, 0, 0, nch, OIIO::TypeDesc::UINT8, raw8.data())
                           : in->read_image(0, 0, 0, nch, OIIO::TypeDesc::FLOAT, rawF.data());
  if (!read || in->has_error())
    return Error{path, "", oiioError("corrupt or truncated image", in->geterror())};
  in->close();

  LoadedImage result;
  result.exif = readExif(spec);
  result.wasSrgbEncoded = !isLinear;
  result.sourceBitsPerChannel = int(spec.format.size()) * 8;
  const int o = result.exif.orientation;
  result.linearRgb = codes8 ? orientedRgb(raw8.data(), spec, o, codeTable8())
                            : orientedRgb(rawF.data(), spec, o, isLinear);
  return result;
}

Status saveImage(const std::string& path, const ImageF& linear, const SaveOptions& options) {
  if (Status s = checkImage(path, linear); !s) return s;
  const std::string ext = lowerExtension(path);
  if (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".tif" || ext == ".tiff") {
    const bool jpeg = ext == ".jpg" || ext == ".jpeg";
    int outC = linear.channels == 4 ? (jpeg ? 3 : 4) : (linear.channels == 1 ? 1 : 3);
    const std::vector<unsigned char> px = toSrgb8(linear, outC, options.response);
    OIIO::ImageSpec spec(linear.width, linear.height, outC, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    if (jpeg) spec.attribute("CompressionQuality", std::clamp(options.jpegQuality, 1, 100));
    return writeAtomically(path, spec, OIIO::TypeDesc::UINT8, px.data());
  }
  if (ext == ".exr") {
    OIIO::ImageSpec spec(linear.width, linear.height, linear.channels,
                         options.exrHalf ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
    if (linear.channels == 1) spec.channelnames = {"Y"};
    spec.attribute("compression", "zip");
    return writeAtomically(path, spec, OIIO::TypeDesc::FLOAT, linear.data.data());
  }
  if (ext == ".hdr") {
    std::vector<float> rgb(linear.pixelCount() * 3);
    for (size_t i = 0; i < linear.pixelCount(); ++i)
      for (int c = 0; c < 3; ++c) {
        const float v = linear.data[i * size_t(linear.channels) + size_t(linear.channels == 1 ? 0 : c)];
        rgb[i * 3 + size_t(c)] = std::isfinite(v) ? std::max(v, 0.f) : 0.f;
      }
    OIIO::ImageSpec spec(linear.width, linear.height, 3, OIIO::TypeDesc::FLOAT);
    return writeAtomically(path, spec, OIIO::TypeDesc::FLOAT, rgb.data());
  }
  return Error{
      path, "",
      "unknown image extension '" + ext + "' (expected .png, .jpg, .jpeg, .tif, .tiff, .exr or .hdr)"};
}

Status saveLayersExr(const std::string& path, const std::vector<NamedLayer>& layers, bool half) {
  if (layers.empty()) return Error{path, "", "no layers to write"};
  const ImageF* first = layers.front().image;
  std::vector<std::string> names;
  std::vector<std::pair<const ImageF*, int>> sources;  // (image, channel) per output channel
  for (const NamedLayer& layer : layers) {
    const std::string key = "layer '" + layer.name + "'";
    if (!layer.image) return Error{path, key, "no image"};
    if (layer.name.empty() || layer.name.find('.') != std::string::npos)
      return Error{path, key, "layer names must be non-empty and contain no '.'"};
    if (Status s = checkImage(path, *layer.image); !s) return s.error().underKey(key);
    if (layer.image->width != first->width || layer.image->height != first->height)
      return Error{path, key, "size differs from the first layer"};
    static const char* rgba[] = {"R", "G", "B", "A"};
    for (int c = 0; c < layer.image->channels; ++c) {
      names.push_back(layer.name + "." + (layer.image->channels == 1 ? "Y" : rgba[c]));
      sources.emplace_back(layer.image, c);
    }
  }
  const size_t nch = names.size();
  std::vector<float> buf(first->pixelCount() * nch);
  for (size_t i = 0; i < first->pixelCount(); ++i)
    for (size_t c = 0; c < nch; ++c)
      buf[i * nch + c] =
          sources[c].first->data[i * size_t(sources[c].first->channels) + size_t(sources[c].second)];
  OIIO::ImageSpec spec(first->width, first->height, int(nch),
                       half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
  spec.channelnames = names;
  spec.alpha_channel = -1;
  spec.attribute("compression", "zip");
  return writeAtomically(path, spec, OIIO::TypeDesc::FLOAT, buf.data());
}

Status writeFileAtomically(const std::string& path, const std::string& bytes) {
  removeStaleTemps(path);
  const fs::path temp = tempPathBeside(path);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0)
    return Error{path, "",
                 std::string("cannot create a temporary file beside it: ") + std::strerror(errno)};
  // Keep the permissions of the file being replaced.
  struct stat old {};
  if (::stat(path.c_str(), &old) == 0 && S_ISREG(old.st_mode)) ::fchmod(fd, old.st_mode & 07777);
  size_t done = 0;
  int err = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      err = n < 0 ? errno : EIO;
      break;
    }
    done += size_t(n);
  }
  if (!err && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && !err) err = errno;
  if (err) {
    std::error_code ec;
    fs::remove(temp, ec);
    return Error{path, "", std::string("write failed: ") + std::strerror(err)};
  }
  return commitTemp(temp, path);
}

namespace {

// Per destination index: the source indices and weights along one axis.
struct AxisTaps {
  std::vector<int> begin;  // offsets into idx/w, size n+1
  std::vector<int> idx;
  std::vector<float> w;
};

AxisTaps axisTaps(int srcN, int dstN) {
  AxisTaps t;
  t.begin.push_back(0);
  const double scale = double(srcN) / double(dstN);
  for (int i = 0; i < dstN; ++i) {
    if (dstN < srcN) {  // area average over [i*scale, (i+1)*scale)
      const double a = i * scale, b = (i + 1) * scale;
      const int j0 = int(std::floor(a)), j1 = std::min(srcN - 1, int(std::ceil(b)) - 1);
      for (int j = j0; j <= j1; ++j) {
        const double overlap = std::min(b, double(j + 1)) - std::max(a, double(j));
        if (overlap > 0) {
          t.idx.push_back(j);
          t.w.push_back(float(overlap / scale));
        }
      }
    } else {  // bilinear between pixel centres, edges clamped
      const double s = std::clamp((i + 0.5) * scale - 0.5, 0.0, double(srcN - 1));
      const int j0 = int(std::floor(s)), j1 = std::min(j0 + 1, srcN - 1);
      const double f = s - j0;
      t.idx.push_back(j0);
      t.w.push_back(float(1 - f));
      if (j1 != j0) {
        t.idx.push_back(j1);
        t.w.push_back(float(f));
      }
    }
    t.begin.push_back(int(t.idx.size()));
  }
  return t;
}

}  // namespace

ImageF resizeImage(const ImageF& src, int width, int height) {
  if (src.empty() || width <= 0 || height <= 0) return {};
  if (width == src.width && height == src.height) return src;
  const int C = src.channels;
  const AxisTaps tx = axisTaps(src.width, width), ty = axisTaps(src.height, height);
  // Rows in parallel: each output row is summed in the same order as on one thread, so the
  // result does not depend on the thread count.
  ImageF tmp(width, src.height, C);  // horizontal pass
  parallelFor(tbb::blocked_range<int>(0, src.height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < width; ++x) {
        float* d = tmp.pixel(x, y);
        for (int k = tx.begin[x]; k < tx.begin[x + 1]; ++k) {
          const float* s = src.pixel(tx.idx[k], y);
          for (int c = 0; c < C; ++c) d[c] += tx.w[k] * s[c];
        }
      }
  });
  ImageF dst(width, height, C);  // vertical pass
  parallelFor(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int k = ty.begin[y]; k < ty.begin[y + 1]; ++k) {
        const float wk = ty.w[k];
        const float* srow = tmp.pixel(0, ty.idx[k]);
        float* drow = dst.pixel(0, y);
        for (size_t i = 0; i < size_t(width) * size_t(C); ++i) drow[i] += wk * srow[i];
      }
  });
  return dst;
}

}  // namespace inlay
