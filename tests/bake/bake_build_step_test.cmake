# The bake as a build step (cmake/BounceBake.cmake), on a scratch project baking a copy of
# point_over_plane with a copy of bounce-bake:
#   1. the first build bakes; 2. a rebuild with nothing changed does not; 3. touching the scene
#   rebakes; 4. touching the baker rebakes.
# Run as: cmake -DBAKER=<bounce-bake> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P this file.
foreach(var BAKER SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "bake_build_step_test: -D${var}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/project/scene")
file(COPY "${SOURCE_DIR}/content/point_over_plane/point_over_plane.gltf"
     DESTINATION "${WORK_DIR}/project/scene")
file(COPY "${BAKER}" DESTINATION "${WORK_DIR}/tools")
get_filename_component(bakerName "${BAKER}" NAME)
file(WRITE "${WORK_DIR}/project/CMakeLists.txt" "
cmake_minimum_required(VERSION 3.25)
project(scratch NONE)
include(\"${SOURCE_DIR}/cmake/BounceBake.cmake\")
bounce_bake(scene/point_over_plane.gltf BAKER \"${WORK_DIR}/tools/${bakerName}\"
            OPTIONS --texel-budget 256 --spp 16 --denoise off --threads 1)
")

function(run what)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(output "${out}${err}" PARENT_SCOPE)
endfunction()

set(manifest "${WORK_DIR}/build/scene/point_over_plane.bake/bake.json")
function(build expectBake why)
  run("build" "${CMAKE_COMMAND}" --build "${WORK_DIR}/build")
  string(FIND "${output}" "Baking the lightmap" found)
  if(expectBake AND found EQUAL -1)
    message(FATAL_ERROR "FAILED: ${why}: expected a bake, the build did not bake:\n${output}")
  elseif(NOT expectBake AND NOT found EQUAL -1)
    message(FATAL_ERROR "FAILED: ${why}: expected no bake, the build baked:\n${output}")
  endif()
  if(NOT EXISTS "${manifest}")
    message(FATAL_ERROR "FAILED: ${why}: ${manifest} missing")
  endif()
  message(STATUS "ok: ${why}")
endfunction()

# Timestamps: wait past the file system's resolution before touching.
function(pause)
  execute_process(COMMAND "${CMAKE_COMMAND}" -E sleep 1.1)
endfunction()

run("configure" "${CMAKE_COMMAND}" -S "${WORK_DIR}/project" -B "${WORK_DIR}/build")
build(TRUE "first build bakes")
build(FALSE "rebuild with nothing changed does not rebake")
pause()
file(TOUCH "${WORK_DIR}/project/scene/point_over_plane.gltf")
build(TRUE "touching the scene rebakes")
build(FALSE "and then it is up to date again")
pause()
file(TOUCH "${WORK_DIR}/tools/${bakerName}")
build(TRUE "a newer baker rebakes")
file(REMOVE_RECURSE "${WORK_DIR}")
