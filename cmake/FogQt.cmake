# Picks the Qt and Qwt pair for the GUI. FOG_QT_MAJOR chooses:
#   6 (default): Qt 6 + Qwt >= 6.2. Debian 12 packages Qwt only for Qt 5, so
#                scripts/setup.sh builds a static Qwt for Qt 6 into
#                /opt/fogbench-qwt-qt6 (or ~/.cache/fogbench/qwt-qt6), where
#                FindQwt looks. If Qt 6 or its Qwt is missing, the build falls
#                back to Qt 5 + Qwt 6.1 and says so.
#   5:           Qt 5.15 + Qwt 6.1 (Debian 12's libqwt-qt5-dev).
# Defines QT_VERSION_MAJOR, the Qt targets as Qt<major>::<Module>, Qwt::Qwt,
# and the LinguistTools (Qt<major>::lupdate, lrelease) for ui/ and tests/.
set(FOG_QT_MAJOR 6 CACHE STRING "Qt major version for the GUI: 6 (Qt 6 + Qwt >= 6.2, falls back to 5) or 5")
set_property(CACHE FOG_QT_MAJOR PROPERTY STRINGS 6 5)
if(NOT FOG_QT_MAJOR MATCHES "^[56]$")
  message(FATAL_ERROR "FOG_QT_MAJOR must be 6 or 5, not '${FOG_QT_MAJOR}'")
endif()
set(FOG_QT_COMPONENTS Core Gui Widgets Svg PrintSupport Concurrent Test LinguistTools)

if(FOG_QT_MAJOR EQUAL 6)
  set(QT_VERSION_MAJOR 6)
  find_package(Qt6 QUIET COMPONENTS ${FOG_QT_COMPONENTS})
  if(NOT Qt6_FOUND)
    set(_fog_qt6_missing "Qt 6 (with Svg, LinguistTools) is not installed")
  else()
    find_package(Qwt 6.2 QUIET)
    if(NOT Qwt_FOUND)
      set(_fog_qt6_missing "Qt ${Qt6_VERSION} is installed but no Qwt >= 6.2 built for Qt 6 was found")
    endif()
  endif()
  if(_fog_qt6_missing)
    message(WARNING "fogbench: ${_fog_qt6_missing}; falling back to Qt 5.15 + Qwt 6.1. "
                    "scripts/setup.sh installs Qt 6 and builds its Qwt (or pass -DQWT_ROOT=<prefix>); "
                    "-DFOG_QT_MAJOR=5 chooses Qt 5 without this warning.")
    unset(Qwt_INCLUDE_DIR CACHE)
    unset(Qwt_LIBRARY CACHE)
    unset(Qwt_FOUND)
    set(QT_VERSION_MAJOR 5)
  endif()
else()
  set(QT_VERSION_MAJOR 5)
endif()

if(QT_VERSION_MAJOR EQUAL 5)
  find_package(Qt5 5.15 REQUIRED COMPONENTS ${FOG_QT_COMPONENTS})
  find_package(Qwt 6.1 REQUIRED)
  set(_fog_qt_version ${Qt5_VERSION})
else()
  set(_fog_qt_version ${Qt6_VERSION})
endif()

# A static Qwt (the one setup builds for Qt 6) brings no link dependencies of
# its own: its users link the Qt modules it is made of.
if(Qwt_LIBRARY MATCHES "\\.a$")
  set_property(TARGET Qwt::Qwt APPEND PROPERTY INTERFACE_LINK_LIBRARIES
               Qt${QT_VERSION_MAJOR}::Widgets Qt${QT_VERSION_MAJOR}::Svg Qt${QT_VERSION_MAJOR}::PrintSupport
               Qt${QT_VERSION_MAJOR}::Concurrent)
  set(_fog_qwt_kind "static, ${Qwt_LIBRARY}")
else()
  set(_fog_qwt_kind "${Qwt_LIBRARY}")
endif()
message(STATUS "fogbench: GUI uses Qt ${_fog_qt_version} + Qwt ${Qwt_VERSION} (${_fog_qwt_kind})")
