# The installed `sbsim` must find libsumocpp.so and libpython3.11.so without LD_LIBRARY_PATH.
# Installed by pip, the program lands in <env>/bin and SUMO in <env>/lib/pythonX.Y/site-packages/sumo,
# so an $ORIGIN-relative entry finds SUMO wherever the environment is moved; the absolute entries
# serve the build tree and a build whose SUMO lives elsewhere.
include(GNUInstallDirs)

set(SBSIM_PYTHON_LIBDIR "${Python_LIBRARY_DIRS}")
if(NOT SBSIM_PYTHON_LIBDIR)
  get_filename_component(SBSIM_PYTHON_LIBDIR "${Python_LIBRARIES}" DIRECTORY)
endif()

set(SBSIM_INSTALL_RPATH
    "$ORIGIN/../lib/python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/site-packages/sumo/lib64"
    "${SBSIM_SUMO_LIBDIR}"
    "${SBSIM_PYTHON_LIBDIR}")

# Gives `target` the run-time search path above, in the build tree and once installed.
function(sbsim_set_runtime_paths target)
  set_target_properties(${target} PROPERTIES
    BUILD_RPATH "${SBSIM_SUMO_LIBDIR};${SBSIM_PYTHON_LIBDIR}"
    INSTALL_RPATH "${SBSIM_INSTALL_RPATH}")
endfunction()
