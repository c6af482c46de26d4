# Writes version.cpp (the project version and the source tree's git commit) from its
# template, run by the build at every build (src/core/CMakeLists.txt):
#   cmake -DSOURCE_DIR=<repo> -DTEMPLATE=<version.cpp.in> -DOUTPUT=<version.cpp>
#         -DSOFTGRAIN_VERSION=<x.y.z> -P write_version.cmake
# configure_file rewrites OUTPUT only when its content changes, so an unchanged commit
# recompiles nothing. The commit is "unknown" without git or outside a checkout, and gets
# "-dirty" when tracked files differ from it (untracked files do not count, as for
# `git describe --dirty`).
set(SOFTGRAIN_COMMIT "unknown")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} rev-parse --short=12 HEAD
                  OUTPUT_VARIABLE commit RESULT_VARIABLE failed
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT failed AND commit)
    set(SOFTGRAIN_COMMIT ${commit})
    execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} status --porcelain
                            --untracked-files=no
                    OUTPUT_VARIABLE changes RESULT_VARIABLE failed ERROR_QUIET)
    if(failed OR NOT changes STREQUAL "")
      string(APPEND SOFTGRAIN_COMMIT "-dirty")
    endif()
  endif()
endif()
configure_file(${TEMPLATE} ${OUTPUT} @ONLY)
