# SPDX-License-Identifier: MIT
# Stamps the version and git commit into every run summary (provenance, STYLE R12): once now, and again at every
# build (cmake/stamp_build_info.cmake), since a commit made after configuring must show in the next binary.
set(HS_SOURCE_DIR ${PROJECT_SOURCE_DIR})
set(HS_BINARY_DIR ${PROJECT_BINARY_DIR})
include(${PROJECT_SOURCE_DIR}/cmake/stamp_build_info.cmake)
add_custom_target(hs_build_info
                  COMMAND ${CMAKE_COMMAND} -DHS_SOURCE_DIR=${PROJECT_SOURCE_DIR} -DHS_BINARY_DIR=${PROJECT_BINARY_DIR}
                          -DPROJECT_VERSION=${PROJECT_VERSION} -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}
                          -P ${PROJECT_SOURCE_DIR}/cmake/stamp_build_info.cmake
                  BYPRODUCTS ${PROJECT_BINARY_DIR}/generated/build_info.hpp
                  COMMENT "Stamping the git commit into build_info.hpp")
