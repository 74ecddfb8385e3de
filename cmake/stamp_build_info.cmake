# SPDX-License-Identifier: MIT
# Writes generated/build_info.hpp from the current git state. Run at configure time and, as `cmake -P`, before every
# build (target hs_build_info), so a rebuilt binary never carries the commit of an older configure. configure_file
# leaves the header untouched when nothing changed: no needless recompiles.
# Inputs: HS_SOURCE_DIR, HS_BINARY_DIR, PROJECT_VERSION, CMAKE_BUILD_TYPE.
execute_process(COMMAND git rev-parse --short=10 HEAD WORKING_DIRECTORY ${HS_SOURCE_DIR}
                OUTPUT_VARIABLE HS_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
execute_process(COMMAND git status --porcelain --untracked-files=no WORKING_DIRECTORY ${HS_SOURCE_DIR}
                OUTPUT_VARIABLE HS_GIT_STATUS OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT HS_GIT_COMMIT)
  set(HS_GIT_COMMIT "unknown")
endif()
if(HS_GIT_STATUS)
  set(HS_GIT_DIRTY true)
else()
  set(HS_GIT_DIRTY false)
endif()
configure_file(${HS_SOURCE_DIR}/src/common/build_info.hpp.in ${HS_BINARY_DIR}/generated/build_info.hpp @ONLY)
