# Picks the Qt and Qwt pair: Qt 6 + Qwt >= 6.2 where both are installed,
# otherwise Qt 5.15 + Qwt 6.1 (Debian 12 packages Qwt only for Qt 5).
# Defines QT_VERSION_MAJOR, the Qt targets as Qt::<Module>, and Qwt::Qwt.
set(FOG_QT_COMPONENTS Core Gui Widgets Svg PrintSupport Concurrent Test SerialPort)

find_package(Qt6 QUIET COMPONENTS ${FOG_QT_COMPONENTS})
if(Qt6_FOUND)
  set(QT_VERSION_MAJOR 6)
  find_package(Qwt 6.2 QUIET)
  if(NOT Qwt_FOUND)
    message(STATUS "fogbench: Qt ${Qt6_VERSION} found but no Qwt >= 6.2 built for Qt 6; trying Qt 5")
    unset(Qwt_INCLUDE_DIR CACHE)
    unset(Qwt_LIBRARY CACHE)
    unset(Qt6_FOUND)
  endif()
endif()

if(NOT Qt6_FOUND)
  set(QT_VERSION_MAJOR 5)
  find_package(Qt5 5.15 REQUIRED COMPONENTS ${FOG_QT_COMPONENTS})
  find_package(Qwt 6.1 REQUIRED)
  set(_fog_qt_version ${Qt5_VERSION})
else()
  set(_fog_qt_version ${Qt6_VERSION})
endif()

message(STATUS "fogbench: GUI uses Qt ${_fog_qt_version} + Qwt ${Qwt_VERSION}")
