# SPDX-License-Identifier: MIT
# Every dependency is a Debian package (scripts/setup.sh installs them); nothing is vendored.
find_package(MPI REQUIRED COMPONENTS CXX)
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(tomlplusplus REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(fmt REQUIRED)
find_package(GTest REQUIRED)
find_package(benchmark REQUIRED)
find_package(Threads REQUIRED)

# hypre (Debian libhypre-dev) ships neither a CMake config nor a pkg-config file.
find_path(HYPRE_INCLUDE_DIR HYPRE.h PATH_SUFFIXES hypre REQUIRED)
find_library(HYPRE_LIBRARY HYPRE REQUIRED)
add_library(hs_hypre INTERFACE)
target_include_directories(hs_hypre SYSTEM INTERFACE ${HYPRE_INCLUDE_DIR})
target_link_libraries(hs_hypre INTERFACE ${HYPRE_LIBRARY} MPI::MPI_CXX)

# Running MPI tests as root inside containers (CI) needs these flags; harmless elsewhere.
set(HS_MPIEXEC_FLAGS --oversubscribe)
execute_process(COMMAND id -u OUTPUT_VARIABLE HS_UID OUTPUT_STRIP_TRAILING_WHITESPACE)
if(HS_UID STREQUAL "0")
  list(APPEND HS_MPIEXEC_FLAGS --allow-run-as-root)
endif()
