// TsanEdge: a happens-before edge ThreadSanitizer can see, for hand-offs whose real
// synchronisation lives in uninstrumented libraries (Debian's oneTBB and Qt are not built with
// TSan). Empty without TSan. Users: parallel.h (TBB loops), the studio's queued calls.
#pragma once

#if defined(__SANITIZE_THREAD__)
#define INLAY_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define INLAY_TSAN 1
#endif
#endif

#ifdef INLAY_TSAN
#include <sanitizer/tsan_interface.h>
#endif

namespace inlay {

// A happens-before edge TSan can see, between threads whose real synchronisation lives in
// uninstrumented code. release() on one thread, then acquire() on another.
class TsanEdge {
 public:
#ifdef INLAY_TSAN
  void release() noexcept { __tsan_release(&tag_); }
  void acquire() noexcept { __tsan_acquire(&tag_); }
#else
  void release() noexcept {}
  void acquire() noexcept {}
#endif

 private:
  [[maybe_unused]] char tag_ =
      0;  // only its address is used (TSan builds): TSan keys its sync objects by address
};

}  // namespace inlay
