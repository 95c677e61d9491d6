# The GL 3.3 core loader is generated at configure time by Debian's python3-glad, offline
# (--reproducible uses the Khronos XML bundled with the package), into the build tree.
# Only the GL layer (engine/gl) links bounce_glad.
set(BOUNCE_GLAD_DIR ${CMAKE_BINARY_DIR}/generated/glad)
set(BOUNCE_GLAD_ARGS --quiet --api gl:core=3.3 --extensions GL_KHR_debug
    --out-path ${BOUNCE_GLAD_DIR} --reproducible c)
find_program(GLAD_EXECUTABLE glad PATHS /usr/bin NO_DEFAULT_PATH REQUIRED)
if(NOT EXISTS ${BOUNCE_GLAD_DIR}/src/gl.c OR NOT "${BOUNCE_GLAD_STAMP}" STREQUAL "${BOUNCE_GLAD_ARGS}")
  message(STATUS "Generating the GL 3.3 core loader with ${GLAD_EXECUTABLE}")
  file(REMOVE_RECURSE ${BOUNCE_GLAD_DIR})
  execute_process(COMMAND ${GLAD_EXECUTABLE} ${BOUNCE_GLAD_ARGS}
                  RESULT_VARIABLE glad_result ERROR_VARIABLE glad_error)
  if(NOT glad_result EQUAL 0 OR NOT EXISTS ${BOUNCE_GLAD_DIR}/src/gl.c)
    message(FATAL_ERROR "glad failed to generate the GL loader (${glad_result}): ${glad_error}")
  endif()
  set(BOUNCE_GLAD_STAMP "${BOUNCE_GLAD_ARGS}" CACHE INTERNAL "arguments of the generated loader")
endif()
add_library(bounce_glad STATIC ${BOUNCE_GLAD_DIR}/src/gl.c)
target_include_directories(bounce_glad SYSTEM PUBLIC ${BOUNCE_GLAD_DIR}/include)
set_target_properties(bounce_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
