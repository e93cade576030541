# The rooms of the repository each compile against an include root of their own,
# build/rooms/ROOM/, holding only the room's folder (a link to it in the source tree):
#
#   impulse_physics  physics/          impulse_scene    demos/scene/
#   impulse_tex      tex/              impulse_film     demos/film/
#   impulse_render   render/           impulse_program  demos/*.h
#   the tests        tests/ (and the roots of the libraries each links)
#
# Each root is PUBLIC, so a library sees the rooms it links and no others: "physics/world.h" is
# found from physics/ and from every library that links impulse_physics, while a physics file that
# names "demos/scene/scene.h" or "render/frame.h" does not compile, for the header is not there
# (tests/rooms_test.cmake shows it). What an include root cannot stop, a path through "..", the
# check below refuses before the library compiles.

# impulse_room(TARGET ROOM PATH...): TARGET compiles against build/rooms/ROOM, which holds each
# PATH (a folder or a file, relative to the repository) as a link; PUBLIC unless TARGET is an
# executable.
function(impulse_room target room)
  set(root ${PROJECT_BINARY_DIR}/rooms/${room})
  foreach(path ${ARGN})
    set(link ${root}/${path})
    get_filename_component(parent ${link} DIRECTORY)
    file(MAKE_DIRECTORY ${parent})
    if(NOT IS_SYMLINK ${link})
      file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${path} ${link} SYMBOLIC)
    endif()
  endforeach()
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "EXECUTABLE")
    target_include_directories(${target} PRIVATE ${root})
  else()
    target_include_directories(${target} PUBLIC ${root})
  endif()
endfunction()

# impulse_no_dot_dot(TARGET DIR): fails TARGET's build, naming file and line, when a file of DIR
# includes anything through "..", which would reach past the include roots.
function(impulse_no_dot_dot target dir)
  file(GLOB_RECURSE room_files CONFIGURE_DEPENDS ${dir}/*.h ${dir}/*.cpp)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${target}_rooms.stamp)
  add_custom_command(
    OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} "-DDIR=${dir}" "-DSTAMP=${stamp}" -P ${PROJECT_SOURCE_DIR}/cmake/check_room.cmake
    DEPENDS ${room_files} ${PROJECT_SOURCE_DIR}/cmake/check_room.cmake
    COMMENT "Checking that ${dir} includes nothing through '..'"
    VERBATIM)
  add_custom_target(${target}_rooms DEPENDS ${stamp})
  add_dependencies(${target} ${target}_rooms)
endfunction()
