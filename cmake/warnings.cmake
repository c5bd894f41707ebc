# Warnings as errors, applied to our own targets only (third-party headers are SYSTEM includes).
function(bimrock_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
    -Wno-sign-conversion -Werror)
endfunction()
