# INLAY_SANITIZE: build every target with sanitizers, e.g. -DINLAY_SANITIZE="address;undefined"
# or -DINLAY_SANITIZE=thread (the two cannot be combined). Any finding aborts the program (no
# recovery), so a test that trips one fails. INLAY_FUZZ: libFuzzer targets (clang only); every
# unit is then compiled with coverage instrumentation and ASan+UBSan.
set(INLAY_SANITIZE "" CACHE STRING "Sanitizers for every target: address;undefined, or thread")
option(INLAY_FUZZ "Build the libFuzzer targets in tests/fuzz (needs clang)" OFF)

if(INLAY_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "INLAY_FUZZ=ON needs clang (libFuzzer): -DCMAKE_CXX_COMPILER=clang++")
  endif()
  if(NOT INLAY_SANITIZE)
    set(INLAY_SANITIZE address undefined)
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(INLAY_SANITIZE)
  if("thread" IN_LIST INLAY_SANITIZE AND "address" IN_LIST INLAY_SANITIZE)
    message(FATAL_ERROR "INLAY_SANITIZE: thread and address cannot be combined")
  endif()
  list(JOIN INLAY_SANITIZE "," _inlay_sanitizers)
  add_compile_options(-fsanitize=${_inlay_sanitizers} -fno-sanitize-recover=all
                      -fno-omit-frame-pointer -g1)
  add_link_options(-fsanitize=${_inlay_sanitizers})
  # The environment every test runs with: findings are fatal and print a stack.
  set(INLAY_SANITIZER_ENV
      "ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=0:suppressions=${CMAKE_SOURCE_DIR}/tests/sanitizers/asan.supp"
      "LSAN_OPTIONS=suppressions=${CMAKE_SOURCE_DIR}/tests/sanitizers/lsan.supp:print_suppressions=0"
      "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:suppressions=${CMAKE_SOURCE_DIR}/tests/sanitizers/ubsan.supp"
      "TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=${CMAKE_SOURCE_DIR}/tests/sanitizers/tsan.supp")
  message(STATUS "Sanitizers: ${_inlay_sanitizers}")
endif()

# How much longer a test may wait for a worker, a frame or a child process (studio QtTests get it
# as INLAY_TEST_WAIT_SCALE; ctest timeouts of the slow labels use it too). TSan slows our
# threaded code 5-15x, ASan+UBSan about 2-3x.
if("thread" IN_LIST INLAY_SANITIZE)
  set(INLAY_TEST_WAIT_SCALE 10)
elseif(INLAY_SANITIZE)
  set(INLAY_TEST_WAIT_SCALE 3)
else()
  set(INLAY_TEST_WAIT_SCALE 1)
endif()
