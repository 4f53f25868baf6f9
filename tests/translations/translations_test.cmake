# Every translation is complete and up to date with the sources: the .ts is
# refreshed from ui/ and the GUI's main as scripts/update-translations.sh
# does, into a scratch copy, and must then hold no unfinished, vanished or
# empty translation.   -DSOURCE=source dir -DDIR=scratch folder -DLUPDATE=path
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
file(GLOB ts_files ${SOURCE}/resources/translations/*.ts)
if(NOT ts_files)
  message(FATAL_ERROR "no translations in ${SOURCE}/resources/translations")
endif()
foreach(ts ${ts_files})
  get_filename_component(name ${ts} NAME)
  file(READ ${ts} text)
  string(REGEX REPLACE "<name>fog::ui::([A-Za-z]+)</name>" "<name>\\1</name>" text "${text}")
  file(WRITE ${DIR}/${name} "${text}")
  execute_process(COMMAND ${LUPDATE} -silent -no-obsolete -locations none ui app/fogbench_gui.cpp -ts ${DIR}/${name}
                  WORKING_DIRECTORY ${SOURCE} RESULT_VARIABLE c ERROR_VARIABLE e)
  if(NOT c EQUAL 0)
    message(FATAL_ERROR "lupdate failed on ${name}: ${e}")
  endif()
  file(READ ${DIR}/${name} fresh)
  string(REGEX MATCHALL "<source>[^<]*</source>[ \n]*<translation type=\"unfinished\"" unfinished "${fresh}")
  string(REGEX MATCHALL "<translation></translation>" empty "${fresh}")
  list(LENGTH unfinished n_unfinished)
  list(LENGTH empty n_empty)
  if(n_unfinished GREATER 0 OR n_empty GREATER 0)
    string(REGEX REPLACE "<translation type=\"unfinished\"" "" unfinished "${unfinished}")
    message(FATAL_ERROR "${name}: ${n_unfinished} untranslated and ${n_empty} empty strings; run "
                        "scripts/update-translations.sh and translate:\n${unfinished}")
  endif()
  string(REGEX MATCHALL "<source>" sources "${fresh}")
  list(LENGTH sources n)
  message(STATUS "${name}: all ${n} strings translated")
endforeach()
