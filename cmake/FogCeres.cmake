# Ceres from Debian's libceres-dev. Its CMake config links the static
# libceres.a (with glog, gflags, SuiteSparse and LAPACK), which costs ~13 s per
# executable at link time. Debian also ships libceres.so with the same headers,
# so we link that instead: one target, fog::ceres, used by core/analysis only.
find_package(Ceres 2 REQUIRED)
get_target_property(_fog_ceres_includes Ceres::ceres INTERFACE_INCLUDE_DIRECTORIES)
find_library(FOG_CERES_SHARED NAMES libceres.so ceres
             HINTS /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE} NO_CACHE)
add_library(fog_ceres INTERFACE)
add_library(fog::ceres ALIAS fog_ceres)
if(FOG_CERES_SHARED AND FOG_CERES_SHARED MATCHES "\\.so$")
  find_package(glog QUIET)
  target_link_libraries(fog_ceres INTERFACE ${FOG_CERES_SHARED} Eigen3::Eigen)
  if(TARGET glog::glog)
    target_link_libraries(fog_ceres INTERFACE glog::glog)
  endif()
  if(_fog_ceres_includes)
    target_include_directories(fog_ceres SYSTEM INTERFACE ${_fog_ceres_includes})
  endif()
  message(STATUS "fogbench: Ceres ${Ceres_VERSION} (shared library ${FOG_CERES_SHARED})")
else()
  target_link_libraries(fog_ceres INTERFACE Ceres::ceres)
  message(STATUS "fogbench: Ceres ${Ceres_VERSION} (as its CMake package links it)")
endif()
