# Warnings every certimesh target is built with; the suite builds them as errors.
option(CERTIMESH_WERROR "Treat warnings as errors" OFF)
function(certimesh_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
  if(CERTIMESH_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
