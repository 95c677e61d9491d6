# Bake as a build step.
#
#   bounce_bake(<scene> [OUTPUT <dir>] [TARGET <name>] [BAKER <executable>]
#               [DEPENDS <file>...] [OPTIONS <bounce-bake flag>...])
#
# Adds a custom command that runs bounce-bake on <scene> (relative to the current source dir)
# into <dir> (default: <current binary dir>/<scene's folder>/<scene name>.bake) and a target
# (default bake_<scene name>, built by ALL) that needs it. The command's output (the folder's
# bake.json, written last, whole or not at all) depends on the scene file, the files a .gltf
# refers to (buffers and images with file URIs), any DEPENDS, and the baker: a rebuild with
# nothing changed does not rebake; touching the scene or rebuilding the baker does.
# BAKER defaults to the bounce-bake target of this build.
function(bounce_bake scene)
  cmake_parse_arguments(arg "" "OUTPUT;TARGET;BAKER" "OPTIONS;DEPENDS" ${ARGN})
  get_filename_component(path "${scene}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  get_filename_component(dir "${path}" DIRECTORY)
  get_filename_component(name "${path}" NAME_WE)
  if(NOT EXISTS "${path}")
    message(FATAL_ERROR "bounce_bake: scene ${path} does not exist")
  endif()
  if(NOT arg_OUTPUT)
    file(RELATIVE_PATH rel "${CMAKE_CURRENT_SOURCE_DIR}" "${dir}")
    set(arg_OUTPUT "${CMAKE_CURRENT_BINARY_DIR}/${rel}/${name}.bake")
  endif()
  if(NOT arg_TARGET)
    set(arg_TARGET "bake_${name}")
  endif()
  if(arg_BAKER)
    set(baker "${arg_BAKER}")
    set(bakerDependency "${arg_BAKER}")
  else()
    set(baker "$<TARGET_FILE:bounce-bake>")
    set(bakerDependency bounce-bake)
  endif()

  # Files a .gltf refers to: its buffers and images with file (not data:) URIs.
  set(deps "${path}")
  if(path MATCHES "\\.gltf$")
    file(READ "${path}" json)
    foreach(kind buffers images)
      string(JSON count ERROR_VARIABLE missing LENGTH "${json}" ${kind})
      if(missing OR count EQUAL 0)
        continue()
      endif()
      math(EXPR last "${count} - 1")
      foreach(i RANGE ${last})
        string(JSON uri ERROR_VARIABLE noUri GET "${json}" ${kind} ${i} uri)
        if(NOT noUri AND NOT uri MATCHES "^data:")
          list(APPEND deps "${dir}/${uri}")
        endif()
      endforeach()
    endforeach()
    # A changed list of referenced files needs a new configure.
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${path}")
  endif()

  add_custom_command(
    OUTPUT "${arg_OUTPUT}/bake.json"
    COMMAND "${baker}" "${path}" -o "${arg_OUTPUT}" --quiet ${arg_OPTIONS}
    DEPENDS ${deps} ${arg_DEPENDS} ${bakerDependency}
    COMMENT "Baking the lightmap of ${scene} into ${arg_OUTPUT}"
    VERBATIM)
  add_custom_target(${arg_TARGET} ALL DEPENDS "${arg_OUTPUT}/bake.json")
endfunction()
