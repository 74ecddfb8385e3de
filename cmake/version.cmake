# SPDX-License-Identifier: MIT
# Stamps the version and git commit into every run summary (provenance, STYLE R12).
execute_process(COMMAND git rev-parse --short=10 HEAD WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                OUTPUT_VARIABLE HS_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
execute_process(COMMAND git status --porcelain --untracked-files=no WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                OUTPUT_VARIABLE HS_GIT_STATUS OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT HS_GIT_COMMIT)
  set(HS_GIT_COMMIT "unknown")
endif()
if(HS_GIT_STATUS)
  set(HS_GIT_DIRTY true)
else()
  set(HS_GIT_DIRTY false)
endif()
configure_file(${PROJECT_SOURCE_DIR}/src/common/build_info.hpp.in ${PROJECT_BINARY_DIR}/generated/build_info.hpp @ONLY)
