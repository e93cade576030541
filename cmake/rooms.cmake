# The rooms of the repository (physics/, render/, demos/) include only what they may: physics/
# nothing but physics/, so that the engine builds, tests and reads without the renderer or the
# program. Every library's sources share the repository root as include root (its headers are
# named "physics/world.h" from everywhere), so the include path alone cannot keep a room out; this
# check can: it runs before the library compiles, whenever one of its files changes, and fails the
# build naming the file and the line.
#
# impulse_keep_room(TARGET DIR ALLOWED room...): TARGET's sources in DIR may include, in quotes or
# angle brackets, headers of the ALLOWED rooms and outside headers (<vector>, <Eigen/Core>), never
# those of another room of the repository, nor anything through "..".
set(IMPULSE_ROOMS physics render demos tests)

function(impulse_keep_room target dir)
  cmake_parse_arguments(PARSE_ARGV 2 ROOM "" "" "ALLOWED")
  file(GLOB_RECURSE room_files CONFIGURE_DEPENDS ${dir}/*.h ${dir}/*.cpp)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${target}_rooms.stamp)
  add_custom_command(
    OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} "-DDIR=${dir}" "-DALLOWED=${ROOM_ALLOWED}" "-DROOMS=${IMPULSE_ROOMS}" "-DSTAMP=${stamp}"
            -P ${PROJECT_SOURCE_DIR}/cmake/check_room.cmake
    DEPENDS ${room_files} ${PROJECT_SOURCE_DIR}/cmake/check_room.cmake
    COMMENT "Checking that ${dir} includes only ${ROOM_ALLOWED}"
    VERBATIM)
  add_custom_target(${target}_rooms DEPENDS ${stamp})
  add_dependencies(${target} ${target}_rooms)
endfunction()
