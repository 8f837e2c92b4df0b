# Writes the version file read at run time by hair::project_version(): the project
# version and `git describe --dirty`, e.g. "0.1.0+a1b2c3d-dirty". Rewritten only when
# the text changes. It is a file beside the binaries, not compiled into them, so that
# a commit that changes no code does not change the binaries, and make (which tracks
# the binaries) does not rerun every stage.
execute_process(
  COMMAND git describe --always --dirty --tags
  WORKING_DIRECTORY ${SOURCE_DIR}
  OUTPUT_VARIABLE GIT_DESCRIBE
  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE GIT_RESULT)
if(NOT GIT_RESULT EQUAL 0 OR GIT_DESCRIBE STREQUAL "")
  set(GIT_DESCRIBE "unknown")
endif()
set(TEXT "${PROJECT_VERSION}+${GIT_DESCRIBE}\n")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} OLD)
else()
  set(OLD "")
endif()
if(NOT OLD STREQUAL TEXT)
  file(WRITE ${OUTPUT} "${TEXT}")
endif()
