# Writes libcore's BuildInfo.hpp with the source tree's current `git describe`, at every build
# (not once at configure time, which left every later commit's tools and output files naming
# the commit the build directory was configured at). configure_file leaves the header alone
# when nothing changed, so an unchanged tree recompiles nothing. Invoked as:
#   cmake -DSOURCE_DIR=... -DINPUT=...in -DOUTPUT=...hpp -DPROJECT_VERSION=...
#         -DCMAKE_CXX_COMPILER_ID=... -DCMAKE_CXX_COMPILER_VERSION=... -DCMAKE_BUILD_TYPE=...
#         -P BuildInfo.cmake
execute_process(COMMAND git describe --always --dirty --tags
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE HVI_GIT_DESCRIBE OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET)
if(NOT HVI_GIT_DESCRIBE)
  set(HVI_GIT_DESCRIBE "unknown")
endif()
configure_file(${INPUT} ${OUTPUT} @ONLY)
