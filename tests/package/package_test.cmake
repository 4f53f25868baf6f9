# The Debian package, built and installed into a clean root, works:
#   cpack -> fogbench_<version>_amd64.deb with the runtime dependencies and
#   the desktop files; dpkg -x into an empty folder; the installed
#   fogbench-cli prints its version and runs a short simulated plan; the
#   installed GUI prints its version.
#   -DBUILD=build dir -DVERSION=x.y.z -DDIR=scratch folder
#   -DEXPECTED_DEPENDS=comma-separated packages Depends must name
#   -DOTHER_QT=prefix of the other Qt major's packages (libqt5 / libqt6),
#    which Depends must not name
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})

# The text as a regular expression that matches it literally.
function(escape_regex out_var text)
  string(REGEX REPLACE "([][+.*()^$?|\\\\])" "\\\\\\1" escaped "${text}")
  set(${out_var} "${escaped}" PARENT_SCOPE)
endfunction()

function(run_ok out_var)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT c EQUAL 0)
    message(FATAL_ERROR "'${ARGN}' failed (${c}):\n${o}\n${e}")
  endif()
  set(${out_var} "${o}" PARENT_SCOPE)
endfunction()

run_ok(out ${CMAKE_CPACK_COMMAND} --config ${BUILD}/CPackConfig.cmake -B ${DIR}/out)
set(deb ${DIR}/out/fogbench_${VERSION}_amd64.deb)
if(NOT EXISTS ${deb})
  file(GLOB made ${DIR}/out/*.deb)
  message(FATAL_ERROR "expected ${deb}, cpack made: ${made}")
endif()

# Correct runtime dependencies: every Debian package that provides a shared
# library the installed programs load is in Depends.
run_ok(depends dpkg-deb -f ${deb} Depends)
string(REPLACE "," ";" expected "${EXPECTED_DEPENDS}")
foreach(lib ${expected})
  if(NOT depends MATCHES "${lib}")
    message(FATAL_ERROR "Depends lacks ${lib}: ${depends}")
  endif()
endforeach()
if(OTHER_QT AND depends MATCHES "${OTHER_QT}")
  message(FATAL_ERROR "Depends names the other Qt (${OTHER_QT}): ${depends}")
endif()
message(STATUS "Depends: ${depends}")
foreach(program fogbench-cli fogbench)
  # The libraries the program itself names (NEEDED), found where ldd finds them.
  run_ok(ldd_out ldd ${BUILD}/app/${program})
  run_ok(dynamic readelf -d ${BUILD}/app/${program})
  string(REGEX MATCHALL "Shared library: \\[[^]]+\\]" needed "${dynamic}")
  set(paths)
  foreach(n ${needed})
    string(REGEX REPLACE "Shared library: \\[([^]]+)\\]" "\\1" soname "${n}")
    escape_regex(soname_re "${soname}")
    string(REGEX MATCH "${soname_re} => (/[^ ]+)" found "${ldd_out}")
    if(CMAKE_MATCH_1)
      list(APPEND paths ${CMAKE_MATCH_1})
    endif()
  endforeach()
  foreach(p ${paths})
    execute_process(COMMAND dpkg -S ${p} RESULT_VARIABLE c OUTPUT_VARIABLE owner ERROR_QUIET)
    if(NOT c EQUAL 0)  # /lib vs /usr/lib aliases: try the other spelling
      string(REGEX REPLACE "^/lib/" "/usr/lib/" p2 "${p}")
      execute_process(COMMAND dpkg -S ${p2} RESULT_VARIABLE c OUTPUT_VARIABLE owner ERROR_QUIET)
    endif()
    if(c EQUAL 0)
      string(REGEX REPLACE ":.*" "" pkg "${owner}")
      escape_regex(pkg_re "${pkg}")
      if(NOT depends MATCHES "(^|, )${pkg_re}( |,|$)")
        message(FATAL_ERROR "${program} loads ${p} from ${pkg}, which Depends lacks: ${depends}")
      endif()
    endif()
  endforeach()
endforeach()
run_ok(contents dpkg-deb -c ${deb})
foreach(f usr/bin/fogbench-cli usr/bin/fogbench usr/bin/fogbench-board-emu usr/share/man/man1/fogbench-board-emu.1
          usr/share/applications/fogbench.desktop
          usr/share/metainfo/io.github.fogbench.fogbench.metainfo.xml
          usr/share/icons/hicolor/scalable/apps/fogbench.svg usr/share/icons/hicolor/48x48/apps/fogbench.png
          usr/share/icons/hicolor/256x256/apps/fogbench.png usr/share/man/man1/fogbench-cli.1
          usr/share/man/man1/fogbench.1)
  if(NOT contents MATCHES "\\./${f}")
    message(FATAL_ERROR "the package lacks ${f}:\n${contents}")
  endif()
endforeach()

set(root ${DIR}/root)
run_ok(out dpkg -x ${deb} ${root})
run_ok(version ${root}/usr/bin/fogbench-cli --version)
if(NOT version MATCHES "^fogbench-cli ${VERSION}")
  message(FATAL_ERROR "installed fogbench-cli --version says: ${version}")
endif()
run_ok(report ${root}/usr/bin/fogbench-cli run --axis x --freq-hz 1 --amp-deg 3 --duration-s 10 --seed 2)
if(NOT report MATCHES "measured lag \\(gyro behind table\\) +0\\.46")
  message(FATAL_ERROR "the installed fogbench-cli did not measure the lag:\n${report}")
endif()
set(ENV{QT_QPA_PLATFORM} offscreen)
run_ok(gui ${root}/usr/bin/fogbench --version)
if(NOT gui MATCHES "fogbench ${VERSION}")
  message(FATAL_ERROR "installed fogbench --version says: ${gui}")
endif()
