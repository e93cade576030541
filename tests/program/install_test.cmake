# impulse installed as a user installs it (cmake --install into a fresh prefix), then run from a
# directory that is neither the source tree nor the prefix: it finds its catalogue, the workshop
# header and the Python package's files under the prefix, and renders a catalogue scene to an MP4.
# Invoked by CTest with -DBUILD=<build dir> -DWORK=<scratch dir> [-DPYTHON=<python3>] (the Python
# package's checks need the Python it was built for; sanitizer builds have no package).
file(REMOVE_RECURSE ${WORK})
set(prefix ${WORK}/prefix)
set(elsewhere ${WORK}/elsewhere)
file(MAKE_DIRECTORY ${elsewhere}/videos)

function(expect_in text what)  # a path in the output, matched as text
  string(FIND "${out}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${what}: no '${text}' in:\n${out}")
  endif()
endfunction()

function(run)  # run(ARGS...): exit 0 from ${elsewhere}, its output in `out`
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error
                  WORKING_DIRECTORY ${elsewhere})
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "exit ${result}: ${ARGN}\n${output}\n${error}")
  endif()
  set(out "${output}${error}" PARENT_SCOPE)
endfunction()

run(${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix})
foreach(file bin/impulse bin/impulse-respond include/impulse/workshop.h share/impulse/scenes/bounce.toml
             share/impulse/workshop/listing1_corrected.cpp share/impulse/meshes/half_pipe.obj share/impulse/web/page.js)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "cmake --install put no ${file} under the prefix")
  endif()
endforeach()

# Caches of its own: nothing typeset or built by another run is reused.
set(ENV{XDG_CACHE_HOME} ${WORK}/cache)
set(impulse ${prefix}/bin/impulse)

# The catalogue and the header it names are the prefix's, not the source tree's.
run(${impulse} catalogue --help)
expect_in("${prefix}/share/impulse/scenes" "catalogue's default scenes are not the installed ones")
run(${impulse} response --include-dir)
string(STRIP "${out}" include)
if(NOT include STREQUAL "${prefix}/include")
  message(FATAL_ERROR "response --include-dir says '${include}', not ${prefix}/include")
endif()

# A catalogue scene rendered from elsewhere: an MP4 (an ISO media file: 'ftyp' at byte 4).
run(${impulse} -q render ${prefix}/share/impulse/scenes/bounce.toml --quality low --set scene.duration=1
    -o videos/bounce.mp4)
file(SIZE ${elsewhere}/videos/bounce.mp4 size)
file(READ ${elsewhere}/videos/bounce.mp4 head LIMIT 8 HEX)
if(size LESS 1000 OR NOT head MATCHES "^........66747970$")
  message(FATAL_ERROR "videos/bounce.mp4 is not an MP4 (${size} bytes, starting ${head})")
endif()
# The page of the installed half-pipe: its mesh file found beside the installed scenes.
run(${impulse} -q export ${prefix}/share/impulse/scenes/s5_half_pipe.toml -o pages/half_pipe.html)
# Its run and viewer are packed (gzip, base64): unpacked here as the page unpacks them.
execute_process(COMMAND python3 -c [=[
import base64, gzip, re, sys
page = open(sys.argv[1], encoding="utf-8").read()
def unpacked(name):
    found = re.search('<script id="' + name + '" type="application/gzip;base64">([^<]*)</script>', page)
    return gzip.decompress(base64.b64decode(found.group(1))).decode() if found else ""
print("mesh" if '"shape":"mesh"' in unpacked("impulse-run") else "no mesh", "viewer" if "WebGLRenderer" in unpacked("impulse-viewer") else "no viewer")
]=] ${elsewhere}/pages/half_pipe.html OUTPUT_VARIABLE unpacked RESULT_VARIABLE unpacking)
if(NOT unpacking EQUAL 0 OR NOT unpacked MATCHES "^mesh viewer")
  message(FATAL_ERROR "pages/half_pipe.html holds no mesh or no viewer: ${unpacked}")
endif()
# The gallery of it, from the installed catalogue's scene files.
run(${impulse} gallery -o videos)
if(NOT out MATCHES "\\(1 videos\\)")
  message(FATAL_ERROR "the gallery did not find bounce.mp4's scene in the installed catalogue:\n${out}")
endif()

# The Python package under the prefix: imported from there, it uses the prefix's sandbox child
# and header, and loads a scene.
if(PYTHON)
  file(GLOB package_dir LIST_DIRECTORIES true ${prefix}/lib/python3*/*-packages)
  set(ENV{PYTHONPATH} ${package_dir})
  run(${PYTHON} -c "import os, impulse
print(impulse.__file__)
print(os.environ['IMPULSE_RESPOND'], os.environ['IMPULSE_WORKSHOP_INCLUDE'])
print(impulse.load('${prefix}/share/impulse/scenes/bounce.toml'))")
  expect_in("${package_dir}/impulse/__init__.py\n${prefix}/bin/impulse-respond ${prefix}/include\n"
            "the installed Python package is not the prefix's, or the files it uses are not")
endif()
