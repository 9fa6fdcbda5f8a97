# Locates every dependency from where the brief says it comes from: the Python packages
# (pybind11, eclipse-sumo) through the Python interpreter being built for; Eigen, CLI11, {fmt},
# nlohmann-json, tinyxml2, RE2, zlib and GoogleTest from the system.

find_package(Python 3.11 REQUIRED COMPONENTS Interpreter Development.Embed)

# Asks the target interpreter one question; fails configuration with its answer if it cannot.
function(sbsim_python_query out code what)
  execute_process(
    COMMAND "${Python_EXECUTABLE}" -c "${code}"
    OUTPUT_VARIABLE value ERROR_VARIABLE err RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sbsim: cannot find ${what} with ${Python_EXECUTABLE}: ${err}"
                        "Install it with: ${Python_EXECUTABLE} -m pip install pybind11 'eclipse-sumo==1.28.*'")
  endif()
  set(${out} "${value}" PARENT_SCOPE)
endfunction()

if(NOT pybind11_DIR)
  sbsim_python_query(_pybind11_dir "import pybind11; print(pybind11.get_cmake_dir())" "pybind11")
  set(pybind11_DIR "${_pybind11_dir}" CACHE PATH "pybind11's CMake package folder")
endif()
find_package(pybind11 2.10 CONFIG REQUIRED)

if(NOT SUMO_DIR)
  sbsim_python_query(_sumo_home "import sumo; print(sumo.SUMO_HOME)" "eclipse-sumo")
  set(SUMO_DIR "${_sumo_home}/cmake" CACHE PATH "SUMO's CMake package folder ($SUMO_HOME/cmake)")
endif()
find_package(SUMO CONFIG REQUIRED)
# SUMOConfig names Parquet as a link dependency it does not ship a target for; libsumocpp.so
# finds its own libraries through its RPATH, so that entry is only noise for the linker.
set_property(TARGET SUMO::libsumocpp PROPERTY IMPORTED_LINK_DEPENDENT_LIBRARIES_RELEASE "")
get_target_property(SBSIM_SUMO_LIBRARY SUMO::libsumocpp IMPORTED_LOCATION_RELEASE)
get_filename_component(SBSIM_SUMO_LIBDIR "${SBSIM_SUMO_LIBRARY}" DIRECTORY)
get_filename_component(SBSIM_SUMO_HOME "${SBSIM_SUMO_LIBDIR}" DIRECTORY)

find_package(Threads REQUIRED)  # the kernel's worker pool
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
# Used only behind the sources, never in a public header: libsbsim's users need none of them.
find_package(CLI11 2.1 CONFIG REQUIRED)  # the program's command line (header-only)
find_package(fmt 9 CONFIG REQUIRED)
find_package(nlohmann_json 3.11 CONFIG REQUIRED)
# The radio's obstacle index (Boost.Geometry's R-tree, header-only) and its settings file (toml++,
# header-only in Debian's libtomlplusplus-dev).
find_package(Boost 1.74 REQUIRED)
find_package(tomlplusplus 3 CONFIG REQUIRED)

# The services file's XML reader (version 6 added line numbers). Debian's libtinyxml2-dev ships a
# CMake package; elsewhere pkg-config may be all there is.
find_package(tinyxml2 6 CONFIG QUIET)
if(NOT TARGET tinyxml2::tinyxml2)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(tinyxml2 REQUIRED IMPORTED_TARGET GLOBAL tinyxml2>=6)
  add_library(tinyxml2::tinyxml2 ALIAS PkgConfig::tinyxml2)
endif()

# Regular expressions in linear time (TypeCondition, services filters: a pattern cannot stall a
# step). Debian's libre2-dev ships only a pkg-config file; elsewhere RE2 may bring its CMake package.
find_package(re2 CONFIG QUIET)
if(NOT TARGET re2::re2)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(re2 REQUIRED IMPORTED_TARGET GLOBAL re2)
  add_library(re2::re2 ALIAS PkgConfig::re2)
endif()

# gzip-compressed SUMO files (a state to load, its network), read by the program's checks.
find_package(ZLIB REQUIRED)

if(SBSIM_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
