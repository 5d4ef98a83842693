# visors_library(<target>): a library of the package. Its headers are spelled
# "visors/<layer>/<file>.hpp" from src/ in the build tree and from <prefix>/include once installed;
# it is exported as visors::<name> (<target> without its "visors_" prefix) and usable under that
# alias inside the build too.
function(visors_library target)
  string(REGEX REPLACE "^visors_" "" name ${target})
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  add_library(visors::${name} ALIAS ${target})
  set_property(GLOBAL APPEND PROPERTY VISORS_LIBRARIES ${target})
endfunction()
