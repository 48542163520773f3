# volsg_warnings(target): the project's warning set on our own code.
function(volsg_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
  if(VOLSG_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  # A unity build (CMAKE_UNITY_BUILD, as CI builds) includes each source into a batch file, so
  # GCC takes a class with an anonymous-namespace member (a pimpl's private types) for one
  # defined in a header and warns; in the sources as written the class is the file's own.
  if(CMAKE_UNITY_BUILD AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-subobject-linkage)
  endif()
endfunction()
