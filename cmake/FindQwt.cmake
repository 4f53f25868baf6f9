# FindQwt: locates Qwt for the Qt major version in use and defines Qwt::Qwt.
#
# Input:  QT_VERSION_MAJOR (5 or 6) must be set before find_package(Qwt).
# Output: Qwt_FOUND, Qwt_VERSION, Qwt::Qwt.
#
# Found by header and library rather than pkg-config: Debian's Qt5Qwt6.pc
# requires Qt5OpenGL, and a Qt 6 build of Qwt installs a Qt6Qwt6.pc that
# wrongly lists Qt 5 modules. A library linked against the other Qt major is
# rejected, so a Qt 5 Qwt is never mixed into a Qt 6 build.
if(NOT QT_VERSION_MAJOR)
  message(FATAL_ERROR "FindQwt: set QT_VERSION_MAJOR before find_package(Qwt)")
endif()

if(QT_VERSION_MAJOR EQUAL 5)
  set(_qwt_names qwt-qt5 qwt)
  set(_qwt_suffixes qwt-qt5 qwt)
else()
  set(_qwt_names qwt-qt6 qwt)
  set(_qwt_suffixes qwt-qt6 qwt6 qwt)
endif()

# Where to look first: QWT_ROOT (CMake or environment), then for Qt 6 the
# prefixes scripts/setup-qwt-qt6.sh builds into. Header and library come from
# the same prefix when one has both; the system's paths are searched after.
set(_qwt_roots ${QWT_ROOT} $ENV{QWT_ROOT})
if(QT_VERSION_MAJOR EQUAL 6)
  list(APPEND _qwt_roots $ENV{FOG_QWT_QT6_PREFIX} /opt/fogbench-qwt-qt6 $ENV{HOME}/.cache/fogbench/qwt-qt6)
endif()
if(DEFINED CACHE{_Qwt_QT_MAJOR} AND NOT _Qwt_QT_MAJOR EQUAL QT_VERSION_MAJOR)
  unset(Qwt_INCLUDE_DIR CACHE)  # found for the other Qt major
  unset(Qwt_LIBRARY CACHE)
endif()
set(_Qwt_QT_MAJOR ${QT_VERSION_MAJOR} CACHE INTERNAL "")
if(NOT Qwt_LIBRARY)
  foreach(_qwt_root ${_qwt_roots})
    if(EXISTS ${_qwt_root}/include/qwt_global.h)
      find_library(Qwt_LIBRARY NAMES ${_qwt_names} PATHS ${_qwt_root}/lib NO_DEFAULT_PATH)
      if(Qwt_LIBRARY)
        set(Qwt_INCLUDE_DIR ${_qwt_root}/include CACHE PATH "Qwt headers" FORCE)
        break()
      endif()
    endif()
  endforeach()
endif()
find_path(Qwt_INCLUDE_DIR NAMES qwt_global.h
          HINTS ${QWT_ROOT}/include ${QWT_ROOT}/lib/qwt.framework/Headers
          PATH_SUFFIXES ${_qwt_suffixes})
find_library(Qwt_LIBRARY NAMES ${_qwt_names} HINTS ${QWT_ROOT}/lib)

if(Qwt_INCLUDE_DIR AND EXISTS "${Qwt_INCLUDE_DIR}/qwt_global.h")
  file(STRINGS "${Qwt_INCLUDE_DIR}/qwt_global.h" _qwt_line REGEX "#define[ \t]+QWT_VERSION_STR")
  string(REGEX REPLACE ".*\"([0-9.]+)\".*" "\\1" Qwt_VERSION "${_qwt_line}")
endif()

# Reject a library built against the other Qt major version: a shared one by
# the Qt it loads, a static one from setup by the stamp file beside it.
get_filename_component(_qwt_prefix "${Qwt_LIBRARY}" DIRECTORY)
if(Qwt_LIBRARY MATCHES "\\.a$" AND EXISTS ${_qwt_prefix}/../fogbench-qwt.txt)
  file(STRINGS ${_qwt_prefix}/../fogbench-qwt.txt _qwt_qt REGEX "^qt=")
  if(NOT _qwt_qt MATCHES "^qt=${QT_VERSION_MAJOR}\\.")
    message(STATUS "FindQwt: ${Qwt_LIBRARY} was built against ${_qwt_qt}; not usable with Qt ${QT_VERSION_MAJOR}")
    set(Qwt_LIBRARY Qwt_LIBRARY-NOTFOUND)
  endif()
endif()
if(Qwt_LIBRARY AND UNIX AND NOT APPLE)
  find_program(_qwt_objdump NAMES objdump)
  if(_qwt_objdump)
    execute_process(COMMAND ${_qwt_objdump} -p ${Qwt_LIBRARY}
                    OUTPUT_VARIABLE _qwt_deps ERROR_QUIET)
    if(QT_VERSION_MAJOR EQUAL 5 AND _qwt_deps MATCHES "libQt6Core")
      message(STATUS "FindQwt: ${Qwt_LIBRARY} is linked to Qt 6; not usable with Qt 5")
      set(Qwt_LIBRARY Qwt_LIBRARY-NOTFOUND)
    elseif(QT_VERSION_MAJOR EQUAL 6 AND _qwt_deps MATCHES "libQt5Core")
      message(STATUS "FindQwt: ${Qwt_LIBRARY} is linked to Qt 5; not usable with Qt 6")
      set(Qwt_LIBRARY Qwt_LIBRARY-NOTFOUND)
    endif()
  endif()
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Qwt REQUIRED_VARS Qwt_LIBRARY Qwt_INCLUDE_DIR
                                  VERSION_VAR Qwt_VERSION)

if(Qwt_FOUND AND NOT TARGET Qwt::Qwt)
  add_library(Qwt::Qwt UNKNOWN IMPORTED)
  set_target_properties(Qwt::Qwt PROPERTIES IMPORTED_LOCATION "${Qwt_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${Qwt_INCLUDE_DIR}")
endif()
mark_as_advanced(Qwt_INCLUDE_DIR Qwt_LIBRARY)
