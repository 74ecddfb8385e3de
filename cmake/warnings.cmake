# SPDX-License-Identifier: MIT
# One place for compiler flags: every hemoscale target links hs_flags.
add_library(hs_flags INTERFACE)
target_compile_options(hs_flags INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion)
if(HS_WERROR)
  target_compile_options(hs_flags INTERFACE -Werror)
endif()
if(HS_NATIVE)
  target_compile_options(hs_flags INTERFACE $<$<CONFIG:Release,RelWithDebInfo>:-march=native>)
endif()
