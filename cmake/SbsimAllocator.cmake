# The malloc the sbsim program runs with. SUMO allocates and frees heavily in every step, and a
# faster allocator speeds up SUMO's own step inside sbsim (figures: bench/README.md). It is linked
# into the program, so every library of the process (SUMO, Python, sbsim) uses it. `system` keeps
# glibc's; the sanitizer build needs that (ASan brings its own allocator).
set(SBSIM_ALLOCATOR "jemalloc" CACHE STRING "malloc of the sbsim program: jemalloc, mimalloc or system")
set_property(CACHE SBSIM_ALLOCATOR PROPERTY STRINGS jemalloc mimalloc system)

function(sbsim_link_allocator target)
  if(SBSIM_ALLOCATOR STREQUAL "system")
    return()
  endif()
  if(NOT SBSIM_ALLOCATOR MATCHES "^(jemalloc|mimalloc)$")
    message(FATAL_ERROR "SBSIM_ALLOCATOR must be jemalloc, mimalloc or system, not '${SBSIM_ALLOCATOR}'")
  endif()
  find_library(SBSIM_ALLOCATOR_LIBRARY NAMES ${SBSIM_ALLOCATOR})
  if(NOT SBSIM_ALLOCATOR_LIBRARY)
    message(WARNING "lib${SBSIM_ALLOCATOR} not found (Debian: apt-get install lib${SBSIM_ALLOCATOR}-dev): "
                    "sbsim uses the system allocator")
    return()
  endif()
  message(STATUS "sbsim allocator: ${SBSIM_ALLOCATOR_LIBRARY}")
  # Kept although no symbol of ours names it: its malloc replaces glibc's for the whole process.
  target_link_libraries(${target} PRIVATE "-Wl,--no-as-needed" "${SBSIM_ALLOCATOR_LIBRARY}" "-Wl,--as-needed")
endfunction()
