# Precompiled headers: the standard library and GLM (and doctest for the tests) are parsed once
# per target instead of once per source. Parsing them is about a third of a test source's
# compile time, and the CI builds everything twice (plain and sanitized) on two cores.
#
# Off by default under a compiler launcher: ccache does not cache compiles that use a
# precompiled header without extra settings, and it saves more than they do on rebuilds.
if(CMAKE_CXX_COMPILER_LAUNCHER)
  set(volsg_pch_default OFF)
else()
  set(volsg_pch_default ON)
endif()
option(VOLSG_PCH "Precompile the standard, GLM and doctest headers" ${volsg_pch_default})

set(VOLSG_PCH_HEADERS
  <algorithm> <array> <cmath> <cstddef> <cstdint> <cstdio> <cstdlib> <cstring> <filesystem>
  <fstream> <functional> <limits> <memory> <mutex> <optional> <sstream> <string>
  <string_view> <unordered_map> <utility> <vector> <glm/glm.hpp>)

# volsg_precompile(target): the shared headers, precompiled for `target`'s sources.
function(volsg_precompile target)
  if(VOLSG_PCH)
    target_precompile_headers(${target} PRIVATE ${VOLSG_PCH_HEADERS})
  endif()
endfunction()
