# Warnings, sanitizers, fuzzing and ccache, in one place.
include_guard(GLOBAL)

find_program(NCBRIDGE_CCACHE ccache)
if(NCBRIDGE_CCACHE)
  set(CMAKE_C_COMPILER_LAUNCHER "${NCBRIDGE_CCACHE}")
  set(CMAKE_CXX_COMPILER_LAUNCHER "${NCBRIDGE_CCACHE}")
endif()

add_library(ncbridge_warnings INTERFACE)
target_compile_options(ncbridge_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow
  -Wno-missing-field-initializers)

if(NCBRIDGE_SANITIZE)
  list(JOIN NCBRIDGE_SANITIZE "," _san)
  add_compile_options(-fsanitize=${_san} -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=${_san})
endif()

if(NCBRIDGE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "NCBRIDGE_FUZZ needs clang (libFuzzer): use the 'fuzz' preset")
  endif()
  # Instrument everything for coverage + ASan/UBSan; fuzz targets add -fsanitize=fuzzer at link.
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
