# The decision rule's coverage factor k is a stored setting and every report
# states the rule with it (docs/report.md, "The decision rule"):
#  1. a run stores k = 2 and its report states the rule and 2.28 %;
#  2. `analyze --coverage-k 3` stores k = 3 (settings and report) and says
#     so with 0.135 %; `report` then states k = 3 on stdout and in the PDF,
#     whose results table carries P(false accept);
#  3. `report --coverage-k` on a stored result is refused (a re-judgement),
#     and a k outside (0, 10] is refused saying what is wrong, storing nothing.
#   -DCLI=path -DDIR=scratch folder -DPDFTOTEXT=path
set(dir ${DIR}/coverage_k_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
if(NOT PDFTOTEXT OR NOT EXISTS "${PDFTOTEXT}")
  message(FATAL_ERROR "pdftotext (poppler-utils) is missing: install it (scripts/setup.sh)")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)

# 1. The default rule.
set(s ${dir}/k.fbs)
cli(o c run --axis x --freq-hz 2 --amp-deg 2 --duration-s 10 --settle-s 0.3 --out ${s})
if(NOT c EQUAL 0 OR NOT o MATCHES "\ndecision rule: PASS when IMU delay \\+ k·σ < limit \\(k = 2, one-sided guarded acceptance"
   OR NOT o MATCHES "1 − Φ\\(k\\) = 2\\.28 %" OR NOT o MATCHES "probability that the true delay is at or above the limit: ")
  message(FATAL_ERROR "run does not state the default decision rule (${c}):\n${o}")
endif()

# 2. k = 3, stored and stated.
cli(o c analyze ${s} --coverage-k 3)
if(NOT c EQUAL 0 OR NOT o MATCHES "\\(k = 3, one-sided" OR NOT o MATCHES "1 − Φ\\(k\\) = 0\\.135 %"
   OR NOT o MATCHES "guard band 3σ = " OR NOT o MATCHES "Result stored")
  message(FATAL_ERROR "analyze --coverage-k 3 does not state k = 3 (${c}):\n${o}")
endif()
cli(o c export ${s} --results-json ${dir}/results.json)
file(READ ${dir}/results.json j)
string(JSON k1 GET "${j}" stored_results 0 settings decision_rule coverage_factor_k)
string(JSON k2 GET "${j}" stored_results 1 settings decision_rule coverage_factor_k)
string(JSON k2report GET "${j}" stored_results 1 report decision_rule coverage_factor_k)
string(JSON risk GET "${j}" stored_results 1 report test_points 0 false_accept_probability)
if(NOT k1 EQUAL 2 OR NOT k2 EQUAL 3 OR NOT k2report EQUAL 3 OR NOT risk MATCHES "^[0-9]")
  message(FATAL_ERROR "the stored results do not hold k = 2 then k = 3 (${k1}, ${k2}, ${k2report}, risk ${risk}):\n${j}")
endif()
cli(o c report ${s} --pdf ${dir}/k3.pdf)
if(NOT c EQUAL 0 OR NOT o MATCHES "result shown: result 2 of 2" OR NOT o MATCHES "decision rule: [^\n]*\\(k = 3,"
   OR NOT o MATCHES "0\\.135 %")
  message(FATAL_ERROR "report does not state the stored k = 3 (${c}):\n${o}")
endif()
pdf_text(${dir}/k3.pdf text)
string(REGEX REPLACE "[ \n]+" " " flat "${text}")
if(NOT flat MATCHES "Decision rule \\(ISO/IEC 17025:2017 §7\\.8\\.6" OR NOT flat MATCHES "k = 3 standard uncertainties"
   OR NOT flat MATCHES "1 − Φ\\(k\\) = 0\\.135 %" OR NOT flat MATCHES "P\\(false accept\\)")
  message(FATAL_ERROR "the PDF does not state the decision rule with k = 3:\n${text}")
endif()

# 3. Refusals.
cli(o c report ${s} --pdf ${dir}/other.pdf --coverage-k 2)
if(NOT c EQUAL 2 OR NOT o MATCHES "--coverage-k does not apply" OR EXISTS ${dir}/other.pdf)
  message(FATAL_ERROR "report --coverage-k on a stored result was not refused (${c}):\n${o}")
endif()
foreach(bad 0 -1 10.5 nan inf)
  cli(o c analyze ${s} --coverage-k ${bad})
  if(NOT c EQUAL 2 OR NOT o MATCHES "--coverage-k")
    message(FATAL_ERROR "analyze --coverage-k ${bad} was not refused (${c}):\n${o}")
  endif()
endforeach()
cli(o c run --preset quick --coverage-k 0)
if(NOT c EQUAL 2 OR NOT o MATCHES "coverage factor k must be a finite number in \\(0, 10\\]")
  message(FATAL_ERROR "run --coverage-k 0 was not refused saying why (${c}):\n${o}")
endif()
cli(o c export ${s} --results-json ${dir}/after.json)
file(READ ${dir}/after.json j)
string(JSON n LENGTH "${j}" stored_results)
if(NOT n EQUAL 2)
  message(FATAL_ERROR "a refused k stored a result (${n} results)")
endif()
message(STATUS "coverage k: stored 2 then 3, stated in the text, JSON, stdout of report and the PDF")
