# sbsim_add_service_module(NAME SOURCES file...)
# Builds service classes (registered with SBSIM_REGISTER_SERVICE) into lib<NAME>.so, a plugin
# that `sbsim --plugin lib<NAME>.so` loads. Works in sbsim's own tree and, through
# find_package(sbsim), outside it.
function(sbsim_add_service_module name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SOURCES")
  if(NOT arg_SOURCES)
    message(FATAL_ERROR "sbsim_add_service_module(${name}): no SOURCES given")
  endif()
  add_library(${name} MODULE ${arg_SOURCES})
  # sbsim itself provides libsbsim at run time; the plugin only needs its symbols.
  target_link_libraries(${name} PRIVATE sbsim::core)
  target_compile_features(${name} PRIVATE cxx_std_20)
  set_target_properties(${name} PROPERTIES PREFIX "lib" CXX_VISIBILITY_PRESET default)
endfunction()
