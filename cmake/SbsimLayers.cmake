# sbsim's layers: kernel ← traffic ← radio ← facilities ← {storyboard, services} ← app, and traffic ← python
# (the embedded interpreter, which the stories' and services' Python bindings link). Each layer is one library
# target that links only the layers below it. Its sources include headers as
# "sbsim/<layer>/Name.h", and a layer's include path holds only its own folder and, through the
# layers it links, theirs: an include against the order names a header the compiler cannot find,
# so the build fails. A layer's folder is cpp/sbsim/<layer> (the include is the file's path from
# cpp/); the build reaches it through a link build/…/layers/<layer>/sbsim/<layer> → cpp/sbsim/<layer>,
# one include folder per layer.

set(SBSIM_LAYER_ROOT "${PROJECT_BINARY_DIR}/layers")

# sbsim_add_layer(<layer> [FOLDER dir] SOURCES file... [LINK target...])
# Adds the object library sbsim_<layer>. Its objects are compiled once and go into libsbsim (with
# hidden symbols, see kernel/Export.h); tests link them directly.
function(sbsim_add_layer layer)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "FOLDER" "SOURCES;LINK")
  if(NOT arg_FOLDER)
    set(arg_FOLDER "${layer}")
  endif()
  set(stage "${SBSIM_LAYER_ROOT}/${layer}")
  file(MAKE_DIRECTORY "${stage}/sbsim")
  file(CREATE_LINK "${CMAKE_CURRENT_SOURCE_DIR}" "${stage}/sbsim/${arg_FOLDER}" SYMBOLIC)
  add_library(sbsim_${layer} OBJECT ${arg_SOURCES})
  target_include_directories(sbsim_${layer} PUBLIC "$<BUILD_INTERFACE:${stage}>")
  target_link_libraries(sbsim_${layer} PUBLIC ${arg_LINK})
  target_compile_features(sbsim_${layer} PUBLIC cxx_std_20)
  target_compile_options(sbsim_${layer} PRIVATE -Wall -Wextra -Wpedantic)
  set_target_properties(sbsim_${layer} PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  # Nobody interposes sbsim's own symbols: calls inside the library are bound directly and may be
  # inlined instead of going through the PLT (the per-vehicle code calls its helpers often).
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(sbsim_${layer} PRIVATE -fno-semantic-interposition)
  endif()
  set_property(GLOBAL APPEND PROPERTY SBSIM_LAYER_INCLUDE_DIRS "${stage}")
endfunction()
