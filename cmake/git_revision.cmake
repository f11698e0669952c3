## Writes the git revision of the source tree into a header, at every build
## (cmake -P): FOSLS_GIT_REVISION is `git describe --always --dirty` of
## SOURCE_DIR, or "unknown" outside a git checkout or without git. The header
## is rewritten only when the revision changes, so an unchanged revision
## recompiles nothing.
##   cmake -DSOURCE_DIR=... -DOUTPUT=.../git_revision.h -P git_revision.cmake
set(_revision "unknown")
find_program(_git NAMES git)
if(_git)
  execute_process(COMMAND ${_git} -C ${SOURCE_DIR} describe --always --dirty --abbrev=12
                  OUTPUT_VARIABLE _out RESULT_VARIABLE _result
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(_result EQUAL 0 AND NOT _out STREQUAL "")
    set(_revision "${_out}")
  endif()
endif()
set(_text "#define FOSLS_GIT_REVISION \"${_revision}\"\n")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} _old)
else()
  set(_old "")
endif()
if(NOT _old STREQUAL _text)
  file(WRITE ${OUTPUT} "${_text}")
endif()
