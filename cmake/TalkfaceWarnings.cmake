# Warnings for talkface's own targets only (PRIVATE), never for consumers of the package.
function(talkface_set_warnings target)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
      -Wno-sign-conversion $<$<BOOL:${TALKFACE_WERROR}>:-Werror>)
  endif()
endfunction()
