# Runs the `impulse` program as a user would and checks exit codes and files.
# Invoked by CTest with -DIMPULSE=<program> -DSOURCE=<repo> -DWORK=<scratch dir>.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

function(expect_exit code)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY ${SOURCE})
  if(NOT result EQUAL code)
    message(FATAL_ERROR "expected exit ${code}, got ${result}: ${ARGN}\n${out}\n${err}")
  endif()
  set(last_error "${err}" PARENT_SCOPE)
endfunction()

# A good scene renders to the named file.
expect_exit(0 ${IMPULSE} -q render assets/scenes/bounce.toml -o ${WORK}/bounce.mp4)
if(NOT EXISTS ${WORK}/bounce.mp4)
  message(FATAL_ERROR "render exited 0 but wrote no ${WORK}/bounce.mp4")
endif()

# An output that cannot be written (its folder would be inside a file) fails loudly and leaves
# nothing under the final name.
file(WRITE ${WORK}/a-file "not a folder\n")
expect_exit(3 ${IMPULSE} -q render assets/scenes/bounce.toml -o ${WORK}/a-file/bounce.mp4)
file(READ ${WORK}/a-file kept)
if(NOT kept STREQUAL "not a folder\n")
  message(FATAL_ERROR "a failed render changed the file in its way")
endif()
if(NOT last_error MATCHES "cannot make the folder .*a-file")
  message(FATAL_ERROR "the error does not name the path: ${last_error}")
endif()

# A malformed scene is refused with file, line and field.
file(WRITE ${WORK}/bad.toml "[[body]]\nshape = \"sphere\"\nradius = -1\n")
expect_exit(1 ${IMPULSE} check ${WORK}/bad.toml)
if(NOT last_error MATCHES "bad.toml:3: .*'radius': must be > 0")
  message(FATAL_ERROR "unhelpful error: ${last_error}")
endif()

# --help explains the subcommands.
expect_exit(0 ${IMPULSE} --help)
