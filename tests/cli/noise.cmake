# fogbench-cli noise end to end (docs/noise.md):
#   run --preset noise --out S.fbs gives a delay and lists the static segment;
#   noise S.fbs prints the Allan table, terms, bias and swing prediction;
#   noise --json has the documented keys; a plan file with static segments
#   runs to a raw stream that noise analyses per axis; a session without a
#   static segment exits 1 with one line.
#   -DCLI=path -DDIR=scratch folder -DPLAN=tests/data/noise_plan.json
set(dir ${DIR}/noise_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})

include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)

run_expect(0 run run --preset noise --seed 3 --out ${dir}/noise.fbs)
expect_match("${run}" "static segment, X axis, 600\\.0 s at rest: no delay" "run --preset noise")
expect_match("${run}" "measured lag \\(gyro behind table\\) +0\\.46" "run --preset noise still gives the swing's delay")

run_expect(0 text noise ${dir}/noise.fbs)
expect_match("${text}" "Static segment 1: X gyro, 600\\.0 s at rest" "noise text")
expect_match("${text}" "Earth-corrected bias" "noise text")
expect_match("${text}" "tau s +adev deg/h +low deg/h +high deg/h +EDF" "noise text")
expect_match("${text}" "angle random walk: [0-9.e-]+ ± [0-9.e-]+ deg/sqrt\\(h\\)" "noise text")
expect_match("${text}" "Swing test with this gyro: 0\\.1 Hz / 10 deg for 294 s gives a lag sigma of [0-9.]+ us" "noise text")

# Every term in SI units too.
expect_match("${text}" "angle random walk: [0-9.e-]+ ± [0-9.e-]+ deg/sqrt\\(h\\) = [0-9.e-]+ ± [0-9.e-]+ rad/s/sqrt\\(Hz\\)" "noise text in SI")

# kalibr / OpenVINS's IMU file: the angle random walk in rad/s/sqrt(Hz), the
# JSON's deg/sqrt(h) converted here by hand; never over an existing file
# without --overwrite.
run_expect(0 yaml noise ${dir}/noise.fbs --kalibr-yaml ${dir}/imu.yaml)
file(READ ${dir}/imu.yaml imu)
expect_match("${imu}" "\ngyroscope_noise_density: [0-9.e-]+  # rad/s/sqrt\\(Hz\\)" "kalibr yaml")
expect_match("${imu}" "\nupdate_rate: 500  # Hz" "kalibr yaml")
expect_match("${imu}" "\naccelerometer_noise_density: \\.nan  # not measured" "kalibr yaml")
expect_match("${imu}" "noise\\.fbs" "kalibr yaml names the session")
string(REGEX MATCH "\ngyroscope_noise_density: ([0-9.e-]+)" _ "${imu}")
set(density ${CMAKE_MATCH_1})
run_expect(2 again noise ${dir}/noise.fbs --kalibr-yaml ${dir}/imu.yaml)
expect_match("${again_err}" "--kalibr-yaml.*--overwrite" "kalibr yaml not overwritten silently")
run_expect(0 over noise ${dir}/noise.fbs --kalibr-yaml ${dir}/imu.yaml --overwrite)

run_expect(0 json noise ${dir}/noise.fbs --json)
string(JSON axis GET "${json}" segments 0 axis)
string(JSON bias GET "${json}" segments 0 earth_corrected_bias_deg_h)
string(JSON tau0 GET "${json}" segments 0 allan 0 tau_s)
string(JSON lo GET "${json}" segments 0 allan 0 low_deg_h)
string(JSON hi GET "${json}" segments 0 allan 0 high_deg_h)
string(JSON edf GET "${json}" segments 0 allan 0 edf)
string(JSON term GET "${json}" segments 0 terms 0 term)
string(JSON lag GET "${json}" swing_predictions 0 lag_std_us)
if(NOT axis STREQUAL "x" OR tau0 LESS 0.00199 OR tau0 GREATER 0.00201 OR NOT lo LESS hi OR NOT edf GREATER 1 OR term STREQUAL ""
   OR NOT lag GREATER 0)
  message(FATAL_ERROR "noise --json: unexpected values axis=${axis} tau0=${tau0} ci=${lo}..${hi} edf=${edf} term=${term} lag=${lag}")
endif()
# The YAML's density is the JSON's angle random walk (deg/sqrt(h)) / 60 * pi / 180.
string(JSON nterms LENGTH "${json}" segments 0 terms)
math(EXPR last "${nterms} - 1")
set(arw "")
foreach(i RANGE ${last})
  string(JSON key GET "${json}" segments 0 terms ${i} term)
  if(key STREQUAL "angle_random_walk")
    string(JSON arw GET "${json}" segments 0 terms ${i} value)
    string(JSON arw_si GET "${json}" segments 0 terms ${i} value_si)
    string(JSON arw_unit GET "${json}" segments 0 terms ${i} unit_si)
  endif()
endforeach()
if(arw STREQUAL "" OR NOT arw_unit STREQUAL "rad/s/sqrt(Hz)")
  message(FATAL_ERROR "noise --json: no angle random walk with its SI value: ${json}")
endif()
# CMake's math() is integer only: compare in units of 1e-12 rad/s/sqrt(Hz)
# through the decimal text (the density has 9 significant digits).
execute_process(COMMAND /usr/bin/python3 -c
  "import math,sys; a=float(sys.argv[1])/60*math.pi/180; y=float(sys.argv[2]); s=float(sys.argv[3]); sys.exit(0 if abs(y-a)<=1e-8*a and abs(s-a)<=1e-12*a else 1)"
  ${arw} ${density} ${arw_si} RESULT_VARIABLE conv)
if(NOT conv EQUAL 0)
  message(FATAL_ERROR "kalibr yaml density ${density} and JSON value_si ${arw_si} are not the JSON's ARW ${arw} deg/sqrt(h) / 60 * pi / 180")
endif()
# The simulator's X gyro: bias 0.3 deg/h, Earth rate 0 on the east axis.
if(bias LESS -1.5 OR bias GREATER 2.1)
  message(FATAL_ERROR "noise --json: Earth-corrected bias ${bias} deg/h is far from the simulated 0.3 deg/h")
endif()

# A plan file: static on Y, a swing, static on Z; --axis picks the gyro.
run_expect(0 planrun run --plan ${PLAN} --seed 4 --save-raw ${dir}/plan.bin)
run_expect(0 perAxis noise ${dir}/plan.bin --axis z)
expect_match("${perAxis}" "Static segment 1: Z gyro, 120\\.0 s at rest.*Static segment 3: Z gyro, 60\\.0 s at rest" "noise --axis z")

# No static segment: one line, exit 1.
run_expect(0 swing run --preset paper-fast --out ${dir}/swing.fbs)
run_expect(1 none noise ${dir}/swing.fbs)
string(STRIP "${none_err}" none_err)
string(FIND "${none_err}" "\n" newline)
if(NOT newline EQUAL -1 OR NOT none_err MATCHES "no static segment")
  message(FATAL_ERROR "noise without a static segment: expected one line saying so, got:\n${none_err}")
endif()
