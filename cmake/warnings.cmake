# SPDX-License-Identifier: MIT
# One place for compiler flags: every hemoscale target links hs_flags.
add_library(hs_flags INTERFACE)
target_compile_options(hs_flags INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion)
if(HS_WERROR)
  target_compile_options(hs_flags INTERFACE -Werror)
endif()
if(HS_NATIVE)
  target_compile_options(hs_flags INTERFACE $<$<CONFIG:Release,RelWithDebInfo>:-march=native>)
  # GCC 12.2 (Debian bookworm) with AVX-512 enabled builds std::vector<double>{1, 1, 0, 0} as {1, 1, 1, 1} at -O2
  # (found 2026-12-02 on a znver3 machine; -mavx2 builds it right). Checked here by running that line with the
  # flags a Release build uses; where it comes out wrong, AVX-512 is switched off and the configure log says so.
  include(CheckCXXSourceRuns)
  set(CMAKE_REQUIRED_FLAGS "-O2 -march=native")
  check_cxx_source_runs([=[
    #include <vector>
    int main() {
      std::vector<double> v{1, 1, 0, 0};
      int bits = 0;
      for (double x : v) bits = 2 * bits + (x != 0.0);
      return bits == 12 ? 0 : 1;   // 1100
    }
  ]=] HS_NATIVE_INITIALIZER_LIST_RIGHT)
  unset(CMAKE_REQUIRED_FLAGS)
  if(NOT HS_NATIVE_INITIALIZER_LIST_RIGHT)
    message(STATUS "hemoscale: this compiler miscompiles with -march=native's AVX-512: building with -mno-avx512f")
    target_compile_options(hs_flags INTERFACE $<$<CONFIG:Release,RelWithDebInfo>:-mno-avx512f>)
  endif()
endif()
