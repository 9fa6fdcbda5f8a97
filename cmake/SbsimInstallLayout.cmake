# Where things are installed, and how the installed binaries find their libraries without
# LD_LIBRARY_PATH. Under pip (scikit-build-core) the program goes to the environment's bin/ and
# everything else — libsbsim.so, its headers, its CMake package, the bundled scenarios — to
# <site-packages>/sbsim/{lib,include,lib/cmake/sbsim,share}, next to SUMO's <site-packages>/sumo.
# Destinations are relative to the install prefix, so the exported CMake package records paths
# relative to itself. $ORIGIN-relative run paths find SUMO and libsbsim wherever the environment
# is; the absolute entries serve the build tree and a build whose SUMO lives elsewhere.
include(GNUInstallDirs)

set(SBSIM_SITE_PACKAGES "lib/python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/site-packages")
if(SKBUILD)
  set(SBSIM_INSTALL_BINDIR "${SKBUILD_SCRIPTS_DIR}")
  set(SBSIM_INSTALL_LIBDIR "sbsim/lib")
  set(SBSIM_INSTALL_INCLUDEDIR "sbsim/include")
  set(SBSIM_INSTALL_CMAKEDIR "sbsim/lib/cmake/sbsim")
  set(SBSIM_INSTALL_DATADIR "sbsim/share")
else()
  set(SBSIM_INSTALL_BINDIR "bin")
  set(SBSIM_INSTALL_LIBDIR "lib")
  set(SBSIM_INSTALL_INCLUDEDIR "include")
  set(SBSIM_INSTALL_CMAKEDIR "lib/cmake/sbsim")
  set(SBSIM_INSTALL_DATADIR "share/sbsim")
endif()

set(SBSIM_PYTHON_LIBDIR "${Python_LIBRARY_DIRS}")
if(NOT SBSIM_PYTHON_LIBDIR)
  get_filename_component(SBSIM_PYTHON_LIBDIR "${Python_LIBRARIES}" DIRECTORY)
endif()

set(SBSIM_INSTALL_RPATH
    "$ORIGIN/../${SBSIM_SITE_PACKAGES}/sbsim/lib"   # the program → libsbsim.so (pip)
    "$ORIGIN/../lib"                                # the program → libsbsim.so (plain install)
    "$ORIGIN/../${SBSIM_SITE_PACKAGES}/sumo/lib64"  # the program → SUMO
    "$ORIGIN/../../sumo/lib64"                      # libsbsim.so → SUMO (pip)
    "${SBSIM_SUMO_LIBDIR}"
    "${SBSIM_PYTHON_LIBDIR}")

# Gives `target` the run-time search path above, in the build tree and once installed.
function(sbsim_set_runtime_paths target)
  set_target_properties(${target} PROPERTIES
    BUILD_RPATH "${SBSIM_SUMO_LIBDIR};${SBSIM_PYTHON_LIBDIR}"
    INSTALL_RPATH "${SBSIM_INSTALL_RPATH}")
endfunction()
