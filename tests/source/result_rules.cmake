# The verdict rule lives in core (core/analysis/verdict.h judges an analysis,
# core/session/shown_verdict.h chooses the verdict shown); views and commands
# format it and never judge (issue 39: the rule was once written five times
# in ui/). Fails on any file of ui/ or app/ that calls the judging functions
# or compares a verdict with a stored word, or that reads or stores a result
# row past the session API.
#   -DSOURCE=the repository's root
file(GLOB_RECURSE files ${SOURCE}/ui/*.cpp ${SOURCE}/ui/*.h ${SOURCE}/app/*.cpp ${SOURCE}/app/*.h)
set(found "")
foreach(f ${files})
  file(STRINGS ${f} lines REGEX "judgeReport\\(|judgePoint\\(|[Vv]erdict *[!=]= *\"")
  foreach(l ${lines})
    string(APPEND found "${f}: ${l}\n")
  endforeach()
endforeach()
if(found)
  message(FATAL_ERROR "ui/ and app/ judge a verdict themselves; call session::judgeShown (RunOutcome::shownVerdict, "
                      "ShownResult::verdict) and format its ShownVerdictKind instead:\n${found}")
endif()
# Results are reached only through the session API (session_api.h): no view
# or command reads or stores a result row itself.
foreach(f ${files})
  file(STRINGS ${f} lines REGEX "addResult\\(|readStoredResults?\\(|SessionReader::open\\(|->results\\(\\)")
  foreach(l ${lines})
    string(APPEND found "${f}: ${l}\n")
  endforeach()
endforeach()
if(found)
  message(FATAL_ERROR "ui/ and app/ read or store result rows themselves; use session::openSessionOrStream, "
                      "analyseAndStore and showResult (core/session/session_api.h):\n${found}")
endif()
list(LENGTH files n)
message(STATUS "${n} files of ui/ and app/ judge no verdict and reach results only through the session API")
