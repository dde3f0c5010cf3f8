# Writes OUT, a header with the source tree's git commit (FP_GIT_COMMIT: a short hash, "-dirty" when
# tracked files differ from it, "unknown" outside a git checkout), for `fragpath --version`. Run at every
# build; OUT is rewritten only when the text changes, so nothing recompiles otherwise.
# safe.directory: a checkout owned by another user (a CI runner's) is still read, not refused.
execute_process(COMMAND git -c safe.directory=${SRC} -C ${SRC} rev-parse --short=12 HEAD OUTPUT_VARIABLE commit
                OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR commit STREQUAL "")
  set(commit "unknown")
else()
  execute_process(COMMAND git -c safe.directory=${SRC} -C ${SRC} status --porcelain --untracked-files=no OUTPUT_VARIABLE changes
                  ERROR_QUIET)
  if(NOT changes STREQUAL "")
    set(commit "${commit}-dirty")
  endif()
endif()
set(text "#pragma once\n#define FP_GIT_COMMIT \"${commit}\"\n")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT "${old}" STREQUAL "${text}")
  file(WRITE ${OUT} "${text}")
endif()
