# bounce_warnings(target): strict warnings for our own code only (never for Debian's headers,
# which are included as SYSTEM through their imported targets).
function(bounce_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wfloat-conversion
    -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual -Wnull-dereference)
  if(BOUNCE_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
