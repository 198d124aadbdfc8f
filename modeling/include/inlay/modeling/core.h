// Basic vocabulary shared by every Inlay library: vector types, the three kinds of error
// (bug -> INLAY_CHECK, bad input -> Expected<T>/Status with a message naming file, key and
// reason, background failure -> a job's status object), and the cancel token.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace inlay {

using Vec2 = Eigen::Vector2d;  // pixel positions unless the name says otherwise
using Vec3 = Eigen::Vector3d;  // world positions/directions in metres unless named otherwise
using Vec4 = Eigen::Vector4d;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;
using Vec3f = Eigen::Vector3f;
using Vec2f = Eigen::Vector2f;

// The Rec. 709 luminance of a linear RGB triple.
inline double luminance(const Vec3& rgb) {
  return 0.2126 * rgb.x() + 0.7152 * rgb.y() + 0.0722 * rgb.z();
}

// A bug (a broken invariant, never bad input): print the condition and where, then abort.
#define INLAY_CHECK(cond)                                                                             \
  do {                                                                                                \
    if (!(cond)) {                                                                                    \
      std::fprintf(stderr, "inlay: internal check failed: %s at %s:%d\n", #cond, __FILE__, __LINE__); \
      std::abort();                                                                                   \
    }                                                                                                 \
  } while (0)

// Bad input: which file, which key (a JSON pointer-like path such as "objects[2].height_m",
// or a pixel or mesh element), and why. `message()` is the one line the CLI prints.
struct Error {
  std::string file;
  std::string key;
  std::string reason;

  std::string message() const {
    std::string m;
    if (!file.empty()) m += file;
    if (!key.empty()) m += (m.empty() ? "" : ": ") + key;
    m += (m.empty() ? "" : ": ") + reason;
    return m;
  }
  // Returns a copy with `file` set when it was empty, and `prefix.` prepended to the key.
  Error inFile(const std::string& f) const {
    Error e = *this;
    if (e.file.empty()) e.file = f;
    return e;
  }
  Error underKey(const std::string& prefix) const {
    Error e = *this;
    e.key = e.key.empty() ? prefix : prefix + (e.key[0] == '[' ? "" : ".") + e.key;
    return e;
  }
};

// A value or the Error that prevented it (C++23's std::expected, reduced to what we need).
template <class T>
class Expected {
 public:
  Expected(T value) : v_(std::move(value)) {}
  Expected(Error error) : v_(std::move(error)) {}
  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& value() {
    INLAY_CHECK(ok());
    return std::get<0>(v_);
  }
  const T& value() const {
    INLAY_CHECK(ok());
    return std::get<0>(v_);
  }
  T& operator*() { return value(); }
  const T& operator*() const { return value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  const Error& error() const {
    INLAY_CHECK(!ok());
    return std::get<1>(v_);
  }

 private:
  std::variant<T, Error> v_;
};

// Success or an Error.
class Status {
 public:
  Status() = default;
  Status(Error e) : error_(std::move(e)) {}
  static Status Ok() { return {}; }
  bool ok() const { return !error_.has_value(); }
  explicit operator bool() const { return ok(); }
  const Error& error() const {
    INLAY_CHECK(!ok());
    return *error_;
  }

 private:
  std::optional<Error> error_;
};

// One token polled by every long loop (tiles, solver iterations, image loops). Cancel and the
// time limit are one check: shouldStop(). Thread-safe; cancel() may be called from any thread
// (including a signal handler: it only stores to a lock-free atomic).
class CancelToken {
 public:
  using Clock = std::chrono::steady_clock;
  void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
  void reset() { cancelled_.store(false, std::memory_order_relaxed); }
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }
  // Seconds <= 0 or infinite: no deadline.
  void setDeadlineFromNow(double seconds) {
    if (seconds > 0 && seconds < 1e9)
      deadlineNs_.store((Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                            std::chrono::duration<double>(seconds)))
                            .time_since_epoch()
                            .count());
    else deadlineNs_.store(0);
  }
  bool shouldStop() const {
    if (cancelled()) return true;
    const auto d = deadlineNs_.load(std::memory_order_relaxed);
    return d != 0 && Clock::now().time_since_epoch().count() >= d;
  }

 private:
  std::atomic<bool> cancelled_{false};
  std::atomic<Clock::rep> deadlineNs_{0};
};

// A ray in world space: origin in metres, unit direction.
struct Ray {
  Vec3 origin;
  Vec3 direction;
  Vec3 at(double t) const { return origin + t * direction; }
};

}  // namespace inlay
