# volsg_warnings(target): the project's warning set on our own code.
function(volsg_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
  if(VOLSG_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
