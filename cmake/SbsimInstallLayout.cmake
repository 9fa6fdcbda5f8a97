# Where things are installed, and how the installed binaries find their libraries without
# LD_LIBRARY_PATH. Under pip (scikit-build-core) the program goes to the environment's bin/, and
# libsbsim.so, its headers, its CMake package and the bundled scenarios to the environment's
# lib/, include/, lib/cmake/ and share/ (SKBUILD_DATA_DIR is the environment's root). SUMO lives in
# <env>/lib/pythonX.Y/site-packages/sumo, so $ORIGIN-relative entries find it wherever the
# environment is; the absolute entries serve the build tree and a build whose SUMO lives elsewhere.
include(GNUInstallDirs)

if(SKBUILD)
  set(SBSIM_INSTALL_BINDIR "${SKBUILD_SCRIPTS_DIR}")
  set(SBSIM_INSTALL_PREFIX_DIR "${SKBUILD_DATA_DIR}")
else()
  set(SBSIM_INSTALL_BINDIR "${CMAKE_INSTALL_BINDIR}")
  set(SBSIM_INSTALL_PREFIX_DIR ".")
endif()
set(SBSIM_INSTALL_LIBDIR "${SBSIM_INSTALL_PREFIX_DIR}/lib")
set(SBSIM_INSTALL_INCLUDEDIR "${SBSIM_INSTALL_PREFIX_DIR}/include")
set(SBSIM_INSTALL_CMAKEDIR "${SBSIM_INSTALL_LIBDIR}/cmake/sbsim")
set(SBSIM_INSTALL_DATADIR "${SBSIM_INSTALL_PREFIX_DIR}/share/sbsim")

set(SBSIM_PYTHON_LIBDIR "${Python_LIBRARY_DIRS}")
if(NOT SBSIM_PYTHON_LIBDIR)
  get_filename_component(SBSIM_PYTHON_LIBDIR "${Python_LIBRARIES}" DIRECTORY)
endif()

set(_sbsim_sumo_in_env "python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/site-packages/sumo/lib64")
set(SBSIM_INSTALL_RPATH
    "$ORIGIN/../lib"                     # the program → libsbsim.so
    "$ORIGIN/../lib/${_sbsim_sumo_in_env}"  # the program → SUMO
    "$ORIGIN/${_sbsim_sumo_in_env}"         # libsbsim.so → SUMO
    "${SBSIM_SUMO_LIBDIR}"
    "${SBSIM_PYTHON_LIBDIR}")

# Gives `target` the run-time search path above, in the build tree and once installed.
function(sbsim_set_runtime_paths target)
  set_target_properties(${target} PROPERTIES
    BUILD_RPATH "${SBSIM_SUMO_LIBDIR};${SBSIM_PYTHON_LIBDIR}"
    INSTALL_RPATH "${SBSIM_INSTALL_RPATH}")
endfunction()
