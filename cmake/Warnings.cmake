# Compiler warnings for every target of ours (docs/development.md, "Warnings").
#
# inlay_enable_warnings(<dir>...) walks the given source folders (and their sub-folders) and adds
# the warning flags to each compiled target defined there, so a new library, test or benchmark is
# covered without remembering to opt in. Third-party headers do not warn: every dependency is an
# imported target, whose include folders CMake passes as -isystem. INLAY_WERROR turns every
# warning into an error (CI builds with it; off by default so a newer compiler's new warning
# cannot break a user's build).
option(INLAY_WERROR "Treat compiler warnings in our code as errors (CI)" OFF)

# -Wshadow (GCC and Clang): a local, a parameter or a lambda's argument that hides another name,
# members included. On this tree it found no wrong variable, only a parameter named like the
# member it sat beside (path_tracer.cpp's intersect) and constructor arguments named after their
# fields; both are cheap to keep out, and a hidden name is a bug waiting for the next edit.
# -Wshadow=local (GCC) would leave members and globals out.
set(INLAY_WARNING_FLAGS -Wall -Wextra -Wpedantic -Wshadow)
# GCC 12 under ASan+UBSan reports -Wmaybe-uninitialized inside libstdc++'s std::regex (the NFA's
# std::function members, GCC bug 105562; no frame of ours), and its uninitialized analysis is
# unreliable under sanitizer instrumentation. The Release tree keeps the check.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND INLAY_SANITIZE)
  list(APPEND INLAY_WARNING_FLAGS -Wno-maybe-uninitialized)
endif()
if(INLAY_WERROR)
  list(APPEND INLAY_WARNING_FLAGS -Werror)
endif()

function(_inlay_collect_targets dir out)
  get_property(targets DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    _inlay_collect_targets("${sub}" sub_targets)
    list(APPEND targets ${sub_targets})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

function(inlay_enable_warnings)
  set(compiled EXECUTABLE STATIC_LIBRARY SHARED_LIBRARY MODULE_LIBRARY OBJECT_LIBRARY)
  foreach(dir IN LISTS ARGN)
    _inlay_collect_targets("${dir}" targets)
    foreach(t IN LISTS targets)
      get_target_property(type ${t} TYPE)
      if(type IN_LIST compiled)
        target_compile_options(${t} PRIVATE ${INLAY_WARNING_FLAGS})
      endif()
    endforeach()
  endforeach()
endfunction()
