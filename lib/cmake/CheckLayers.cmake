# The build refuses an upward include. Layers, lowest first; a source may include headers of
# its own layer and the ones below:
#   1 lib/volsg/**                        engines and GL layers (know no nodes)
#   2 nodes/volsg/{nodes,io,engines}     node types, engines and the reader that makes them
#   3 nodes/volsg/<other>                 traversals that know node types (volsg_scene)
#   4 manipulators/                       draggers and navigation
#   5 editors/                            UI-free editor models and their panels
#   6 viewer/                             programs
# Included as a project file, it adds the check to the build; run with -P (VOLSG_ROOT and
# VOLSG_STAMP set), it checks.

function(volsg_layer_of path out)
  if(path MATCHES "^lib/")
    set(layer 1)
  elseif(path MATCHES "^nodes/volsg/(nodes|io|engines)/")
    set(layer 2)
  elseif(path MATCHES "^nodes/")
    set(layer 3)
  elseif(path MATCHES "^manipulators/")
    set(layer 4)
  elseif(path MATCHES "^editors/")
    set(layer 5)
  elseif(path MATCHES "^viewer/")
    set(layer 6)
  else()
    set(layer 0)
  endif()
  set(${out} ${layer} PARENT_SCOPE)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE)
  file(GLOB_RECURSE files RELATIVE "${VOLSG_ROOT}"
    "${VOLSG_ROOT}/lib/volsg/*.h" "${VOLSG_ROOT}/lib/volsg/*.cpp"
    "${VOLSG_ROOT}/nodes/*.h" "${VOLSG_ROOT}/nodes/*.cpp"
    "${VOLSG_ROOT}/manipulators/*.h" "${VOLSG_ROOT}/manipulators/*.cpp"
    "${VOLSG_ROOT}/editors/*.h" "${VOLSG_ROOT}/editors/*.cpp"
    "${VOLSG_ROOT}/viewer/*.h" "${VOLSG_ROOT}/viewer/*.cpp")
  set(roots lib nodes manipulators editors viewer)
  set(errors "")
  foreach(file ${files})
    volsg_layer_of("${file}" own)
    file(STRINGS "${VOLSG_ROOT}/${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*<volsg/")
    foreach(line ${lines})
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*<([^>]+)>.*" "\\1" header "${line}")
      set(found "")
      foreach(root ${roots})
        if(EXISTS "${VOLSG_ROOT}/${root}/${header}")
          list(APPEND found "${root}/${header}")
        endif()
      endforeach()
      list(LENGTH found count)
      if(count GREATER 1)
        string(APPEND errors "${file}: <${header}> is in more than one layer: ${found}\n")
      elseif(count EQUAL 1)
        volsg_layer_of("${found}" theirs)
        if(theirs GREATER own)
          string(APPEND errors
            "${file}: includes <${header}> (${found}), a layer above it (docs/DESIGN.md, Layers)\n")
        endif()
      endif()
    endforeach()
  endforeach()
  if(errors)
    message(FATAL_ERROR "upward includes:\n${errors}")
  endif()
  file(TOUCH "${VOLSG_STAMP}")
  return()
endif()

file(GLOB_RECURSE VOLSG_LAYERED_FILES CONFIGURE_DEPENDS
  ${PROJECT_SOURCE_DIR}/lib/volsg/*.h ${PROJECT_SOURCE_DIR}/lib/volsg/*.cpp
  ${PROJECT_SOURCE_DIR}/nodes/*.h ${PROJECT_SOURCE_DIR}/nodes/*.cpp
  ${PROJECT_SOURCE_DIR}/manipulators/*.h ${PROJECT_SOURCE_DIR}/manipulators/*.cpp
  ${PROJECT_SOURCE_DIR}/editors/*.h ${PROJECT_SOURCE_DIR}/editors/*.cpp
  ${PROJECT_SOURCE_DIR}/viewer/*.h ${PROJECT_SOURCE_DIR}/viewer/*.cpp)
add_custom_command(OUTPUT ${PROJECT_BINARY_DIR}/layers.checked
  COMMAND ${CMAKE_COMMAND} -DVOLSG_ROOT=${PROJECT_SOURCE_DIR}
    -DVOLSG_STAMP=${PROJECT_BINARY_DIR}/layers.checked -P ${CMAKE_CURRENT_LIST_FILE}
  DEPENDS ${VOLSG_LAYERED_FILES} ${CMAKE_CURRENT_LIST_FILE}
  COMMENT "Checking that no source includes a header of a layer above it")
add_custom_target(volsg_check_layers ALL DEPENDS ${PROJECT_BINARY_DIR}/layers.checked)
add_dependencies(volsg_lib volsg_check_layers)
