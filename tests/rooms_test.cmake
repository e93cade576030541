# cmake -DCXX=compiler -DINCLUDES=dir|dir... -DALLOWED=header -DFORBIDDEN=header -DWORK=dir -P rooms_test.cmake
# Compiles a file that includes ALLOWED with a room's include directories (it must compile: the
# setup is right), then one that includes FORBIDDEN too (it must fail, and because that header is
# not found, not for any other reason).
cmake_minimum_required(VERSION 3.25)
string(REPLACE "|" ";" directories "${INCLUDES}")
set(flags -std=c++20 -fsyntax-only)
foreach(directory ${directories})
  if(directory)
    list(APPEND flags -I${directory})
  endif()
endforeach()
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/allowed.cpp "#include \"${ALLOWED}\"\n")
file(WRITE ${WORK}/forbidden.cpp "#include \"${ALLOWED}\"\n#include \"${FORBIDDEN}\"\n")
execute_process(COMMAND ${CXX} ${flags} ${WORK}/allowed.cpp RESULT_VARIABLE result ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${ALLOWED} does not compile with the room's include directories (${directories}):\n${error}")
endif()
execute_process(COMMAND ${CXX} ${flags} ${WORK}/forbidden.cpp RESULT_VARIABLE result ERROR_VARIABLE error)
if(result EQUAL 0)
  message(FATAL_ERROR "${FORBIDDEN} compiles with the room's include directories (${directories}): the rooms are not apart")
endif()
# GCC says "No such file or directory", clang "'HEADER' file not found".
if(NOT error MATCHES "${FORBIDDEN}: No such file or directory" AND NOT error MATCHES "'${FORBIDDEN}' file not found")
  message(FATAL_ERROR "${FORBIDDEN} fails for another reason than not being found:\n${error}")
endif()
message(STATUS "${FORBIDDEN} is not found from the room of ${ALLOWED}, as it should be")
