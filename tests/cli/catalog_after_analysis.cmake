# A single analysis reaches the catalog (docs/catalog.md, "After each
# analysis"): run --out and analyze re-index their session into the folder's
# catalog when it has one (or --db), without another `catalog index`; a
# catalog that cannot be reached never fails the analysis: the result is
# stored and stderr says the catalog was not updated and how to catch up; a
# shared catalog that does not answer leaves the rows pending in the
# folder's own catalog.
#   -DCLI=path -DDIR=scratch folder
set(dir ${DIR}/catalog_after_analysis)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir}/sessions ${dir}/other)
set(s ${dir}/sessions)
include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)

# The number of results `catalog unit SERIAL --db DB` lists.
function(results_in_catalog out serial db)
  run_expect(0 o catalog unit ${serial} --db ${db} --json)
  string(JSON n LENGTH "${o}" history)
  set(${out} ${n} PARENT_SCOPE)
endfunction()
# The number of results stored in a session (`sessions DIR --json`).
function(results_in_session out folder name)
  run_expect(0 o sessions ${folder} --json)
  string(JSON count LENGTH "${o}" sessions)
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    string(JSON f GET "${o}" sessions ${i} file)
    if(f STREQUAL name)
      string(JSON n GET "${o}" sessions ${i} results)
      set(${out} ${n} PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(FATAL_ERROR "sessions ${folder}: no ${name}:\n${o}")
endfunction()
set(quick --preset quick --speed 0)

# No catalog in the folder: nothing said, none made.
run_expect(0 o run ${quick} --seed 1 --out ${s}/a.fbs --imu-serial SN-A --lot L1)
if(o MATCHES "Catalog" OR o_err MATCHES "catalog" OR EXISTS ${s}/fogbench-catalog.sqlite)
  message(FATAL_ERROR "run --out into a folder without a catalog spoke of one or made one:\n${o}\n${o_err}")
endif()
run_expect(0 o catalog index ${s})

# The folder has its catalog now: each stored result reaches it.
run_expect(0 o run ${quick} --seed 2 --out ${s}/b.fbs --imu-serial SN-B --lot L1)
expect_match("${o}" "Catalog updated: SQLite catalog [^\n]*sessions/fogbench-catalog.sqlite" "run --out")
results_in_catalog(n SN-B ${s})
if(NOT n EQUAL 1)
  message(FATAL_ERROR "run --out: SN-B has ${n} results in the catalog, expected 1")
endif()
run_expect(0 o analyze ${s}/a.fbs --read-delay-ms 0.06)
expect_match("${o}" "Result stored in session.*Catalog updated: SQLite catalog" "analyze")
results_in_catalog(n SN-A ${s})
if(NOT n EQUAL 2)
  message(FATAL_ERROR "analyze: SN-A has ${n} results in the catalog, expected 2 (its re-analysis)")
endif()
# --json: stdout stays one JSON document.
run_expect(0 o analyze ${s}/a.fbs --json)
string(JSON verdict ERROR_VARIABLE bad GET "${o}" verdict)
if(bad OR o MATCHES "Catalog updated")
  message(FATAL_ERROR "analyze --json: stdout is not the report alone:\n${o}")
endif()
results_in_catalog(n SN-A ${s})
if(NOT n EQUAL 3)
  message(FATAL_ERROR "analyze --json: SN-A has ${n} results in the catalog, expected 3")
endif()

# --db names another catalog (made when new, like batch's).
run_expect(0 o analyze ${s}/b.fbs --db ${dir}/lab.sqlite)
expect_match("${o}" "Catalog updated: SQLite catalog [^\n]*lab.sqlite" "analyze --db FILE")
results_in_catalog(n SN-B ${dir}/lab.sqlite)
if(NOT n EQUAL 2)
  message(FATAL_ERROR "analyze --db: SN-B has ${n} results in lab.sqlite, expected 2")
endif()
run_expect(2 o run ${quick} --db ${dir}/lab.sqlite)
expect_match("${o_err}" "give --out" "run --db without --out")

# A catalog that cannot be reached: the analysis stands, stderr says so.
run_expect(0 o analyze ${s}/b.fbs --db ${dir}/no/such/folder/cat.sqlite)
expect_match("${o_err}" "catalog was not updated .*the result is stored in the session; catch up with: fogbench-cli catalog index [^\n]*sessions --db [^\n]*cat.sqlite"
             "an unreachable --db")
results_in_session(n ${s} b.fbs)
if(NOT n EQUAL 3)
  message(FATAL_ERROR "analyze with an unreachable catalog: b.fbs holds ${n} results, expected 3")
endif()
# A damaged catalog in the session's folder: the same.
run_expect(0 o run ${quick} --seed 3 --out ${dir}/other/c.fbs --imu-serial SN-C)
file(WRITE ${dir}/other/fogbench-catalog.sqlite "not a catalog")
run_expect(0 o analyze ${dir}/other/c.fbs)
expect_match("${o_err}" "catalog was not updated \\(.*not a readable SQLite database.*catch up with: fogbench-cli catalog index [^\n]*other"
             "a damaged folder catalog")
results_in_session(n ${dir}/other c.fbs)
if(NOT n EQUAL 2)
  message(FATAL_ERROR "analyze with a damaged catalog: c.fbs holds ${n} results, expected 2")
endif()
run_expect(0 o run ${quick} --seed 4 --out ${dir}/other/d.fbs --imu-serial SN-D)
expect_match("${o_err}" "catalog was not updated" "run --out with a damaged folder catalog")
if(NOT EXISTS ${dir}/other/d.fbs)
  message(FATAL_ERROR "run --out with a damaged catalog stored no session")
endif()

# A shared catalog that does not answer: the folder's own catalog takes the
# result and keeps it pending; the analysis stands.
set(offline "postgresql://fogbench@127.0.0.1:1/none?connect_timeout=2")
run_expect(0 o analyze ${s}/b.fbs --db ${offline})
expect_match("${o}" "Catalog updated: SQLite catalog [^\n]*sessions/fogbench-catalog.sqlite" "analyze --db offline server")
expect_match("${o_err}" "shared catalog was not updated: cannot reach the PostgreSQL catalog postgresql://fogbench@127.0.0.1:1/none[^\n]*; [0-9]+ results pending in the SQLite catalog [^\n]*: the next catalog index, batch or catalog push sends them\n$"
             "analyze --db offline server")
results_in_catalog(n SN-B ${s})
if(NOT n EQUAL 4)
  message(FATAL_ERROR "analyze --db offline server: SN-B has ${n} results in the folder's catalog, expected 4")
endif()

# CSV: text that looks like a formula is written as text (a single quote
# first), numbers as numbers (docs/catalog.md, "CSV").
file(MAKE_DIRECTORY ${dir}/csv)
run_expect(0 o run ${quick} --seed 6 --out ${dir}/csv/x.fbs --imu-serial "=1+2" --lot "+L9" --bench-id "-B2" --operator "@ann")
run_expect(0 o catalog index ${dir}/csv)
run_expect(0 o catalog unit "=1+2" --db ${dir}/csv --csv)
expect_match("${o}" "\n'=1\\+2,,'\\+L9,'-B2,'@ann,[0-9T:-]+Z,1,[0-9T:-]+Z,1,[0-9.]+,pass,0.8,0,x,1,pass,0\\.[0-9]+,[0-9.e-]+,,"
             "unit --csv: formula-like text quoted, numbers bare")
run_expect(0 o catalog units --db ${dir}/csv --csv)
expect_match("${o}" "\n'=1\\+2,,'\\+L9,'-B2,1,1," "units --csv")
run_expect(0 o catalog lot "+L9" --db ${dir}/csv --csv)
expect_match("${o}" "\n'\\+L9,1,1,1,0,0,0,0,0,1,1,0.8,stored,x,1,0\\.[0-9]+,,\n" "lot --csv")
