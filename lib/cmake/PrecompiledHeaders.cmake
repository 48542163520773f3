# Precompiled headers: the standard library and GLM (and doctest for the tests) are parsed once
# per target instead of once per source. Parsing them is about a third of a test source's
# compile time, and the CI builds everything twice (plain and sanitized) on two cores.
#
# Opt-in: with GCC 12 at -O2 the precompiled <string> makes -Warray-bounds report std::string's
# own inlined copies (GraphCompare.cpp's substr + "..."), which -Werror turns into a failed
# build; and ccache does not cache compiles that use one without extra settings.
option(VOLSG_PCH "Precompile the standard, GLM and doctest headers" OFF)
# The tests alone: their sources are at -O0/-O1, where the warning above does not arise, and
# they are half of a cold CI build (113 sources that each parse doctest and the standard library).
option(VOLSG_TEST_PCH "Precompile the standard, GLM and doctest headers for the tests" OFF)

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
