# The standard plan end to end (issue 40, docs/method.md "The standard plan"):
#   run --preset response-third-octave records the 21 nominal one-third
#   octaves 0.1 .. 10 Hz and prints the response; response S.fbs states per
#   point the phase against the table's motion with its expanded uncertainty
#   U (k = 2) in degrees and ms, the table read delay's uncertainty (stored
#   with the session's constants) in the budget; --json has the same per
#   point; another read-delay uncertainty given on the command line changes U;
#   the preset is listed in the help and in the unknown-preset error.
#   -DCLI=path -DDIR=scratch folder
set(dir ${DIR}/response_third_octave_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})

include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)

run_expect(0 help --help)
expect_match("${help}" "response-third-octave: the standard plan" "--help lists the preset")
run_expect(2 unknown run --preset nonesuch)
expect_match("${unknown_err}" "response, response-third-octave\\)" "an unknown preset names it")

run_expect(0 run run --preset response-third-octave --seed 2 --read-delay-std-ms 0.01 --out ${dir}/s.fbs)
expect_match("${run}" "Frequency response, X axis \\(gyro angle / table angle\\), 21 points" "run --preset response-third-octave")
expect_match("${run}" "expanded uncertainty U \\(k = 2\\)" "run prints U")

# The session's stored constants: the read delay 0.05 +- 0.01 ms.
run_expect(0 text response ${dir}/s.fbs)
expect_match("${text}" "phase against the table's motion \\(the stamped phase corrected by the table read delay 0\\.05 ± 0\\.01 ms\\), expanded uncertainty U \\(k = 2\\):"
             "response: the budget's constants")
expect_match("${text}" "f Hz +phase deg +U deg +U ms" "response: U's header")
# 10 Hz: phase -omega (0.4658 + 0.05) ms = -1.857 deg; U = 2 sqrt(fit^2 + (omega 0.01 ms)^2) = 0.072 deg = 0.020 ms.
expect_match("${text}" "\n +(9\\.99[0-9][0-9]|10\\.0000) +-1\\.85[0-9]+ +7\\.2[0-9]e-02 +2\\.0[0-9]e-02 " "response: the 10-Hz point's U")
expect_match("${text}" "\n +0\\.1000 +-0\\.018[0-9]+ +7\\.[0-9][0-9]e-04 +2\\.0[0-9]e-02 " "response: the 0.1-Hz point's U")
if(text MATCHES "uncertainty is not stated")
  message(FATAL_ERROR "response: the stated read-delay uncertainty reads as not stated:\n${text}")
endif()

run_expect(0 json response ${dir}/s.fbs --json)
string(JSON npoints LENGTH "${json}" responses 0 points)
string(JSON k GET "${json}" responses 0 coverage_factor)
string(JSON ud GET "${json}" responses 0 table_read_delay_std_ms)
if(NOT npoints EQUAL 21 OR NOT k EQUAL 2 OR NOT ud EQUAL 0.01)
  message(FATAL_ERROR "response --json: ${npoints} points, k ${k}, read delay sigma ${ud} ms")
endif()
# The nominal frequencies are swung (0.315, not 10^-0.5 = 0.3162): each
# within 1e-4 of its nominal value (the table's frequency error is 1e-5).
set(lows 0.09999 0.124988 0.159984 0.19998 0.249975 0.314968 0.39996 0.49995 0.629937 0.79992 0.9999 1.24988 1.59984 1.9998 2.49975 3.14968 3.9996 4.9995 6.29937 7.9992 9.999)
set(highs 0.10001 0.125012 0.160016 0.20002 0.250025 0.315032 0.40004 0.50005 0.630063 0.80008 1.0001 1.25012 1.60016 2.0002 2.50025 3.15031 4.0004 5.0005 6.30063 8.0008 10.001)
foreach(i RANGE 20)
  list(GET lows ${i} lo)
  list(GET highs ${i} hi)
  string(JSON got GET "${json}" responses 0 points ${i} frequency_hz)
  string(JSON pk GET "${json}" responses 0 points ${i} coverage_factor)
  string(JSON ums GET "${json}" responses 0 points ${i} phase_expanded_uncertainty_ms)
  if(got LESS lo OR got GREATER hi)
    message(FATAL_ERROR "response --json point ${i}: ${got} Hz, not within ${lo} .. ${hi}")
  endif()
  if(NOT pk EQUAL 2 OR ums LESS 0.02 OR ums GREATER 0.0202)
    message(FATAL_ERROR "response --json point ${i} (${got} Hz): k ${pk}, U ${ums} ms (expected 2 sqrt(fit^2 + 0.01^2) ms)")
  endif()
endforeach()
string(JSON f20 GET "${json}" responses 0 points 20 frequency_hz)
string(JSON udeg GET "${json}" responses 0 points 20 phase_expanded_uncertainty_deg)
string(JSON motion GET "${json}" responses 0 points 20 phase_vs_table_motion_deg)
string(JSON stamped GET "${json}" responses 0 points 20 phase_deg)
if(f20 LESS 9.999 OR f20 GREATER 10.001 OR udeg LESS 0.0719 OR udeg GREATER 0.0725 OR motion GREATER -1.85
   OR motion LESS -1.86 OR stamped GREATER -1.67 OR stamped LESS -1.68)
  message(FATAL_ERROR "response --json 10 Hz: f ${f20}, U ${udeg} deg, phase ${stamped} against the stamps, ${motion} against the motion")
endif()

# Another uncertainty on the command line (said on stderr): U follows it.
run_expect(0 exact response ${dir}/s.fbs --read-delay-std-ms 0)
expect_match("${exact}" "table read delay 0\\.05 ± 0 ms\\), expanded uncertainty U \\(k = 2\\)" "response --read-delay-std-ms 0")
expect_match("${exact}" "the table read delay's uncertainty is not stated, 0 ms: U holds the fit's share only" "not stated")
expect_match("${exact}" "\n +(9\\.99[0-9][0-9]|10\\.0000) +-1\\.85[0-9]+ +[1-9]\\.[0-9][0-9]e-04 +" "response: U at 10 Hz from the fit alone")
run_expect(0 wide response ${dir}/s.fbs --read-delay-std-ms 0.1 --json)
string(JSON wideu GET "${wide}" responses 0 points 20 phase_expanded_uncertainty_deg)
if(wideu LESS 0.719 OR wideu GREATER 0.721)
  message(FATAL_ERROR "response --read-delay-std-ms 0.1: U at 10 Hz ${wideu} deg (expected 2 x 3.6 x 0.1 = 0.72)")
endif()

run_expect(0 yrun run --preset response-third-octave --axis y --seed 4)
expect_match("${yrun}" "Frequency response, Y axis \\(gyro angle / table angle\\), 21 points" "run --preset response-third-octave --axis y")
