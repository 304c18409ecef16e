# Runs `maris ARGS` without a display and checks that it refuses them with exit code 1 (a usage
# error) and a message on stderr matching EXPECT (the option's name and what is allowed).
separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY ${MARIS} ${args}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
if(NOT result EQUAL 1)
  message(FATAL_ERROR "maris ${ARGS} exited with ${result}, expected 1\n${out}\n${err}")
endif()
if(NOT err MATCHES "${EXPECT}")
  message(FATAL_ERROR "maris ${ARGS}: the message does not match '${EXPECT}':\n${err}")
endif()
message(STATUS "maris ${ARGS}: ${err}")
