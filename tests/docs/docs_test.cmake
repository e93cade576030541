# The README is a front page (at most 300 lines), and every file the manual names is there: each
# markdown link, and each `path/like/this.md` in backquotes (from the repository's root, or from
# the naming file's folder), in README.md, docs/*.md and each folder's README.md. Paths that name
# outputs (out/, build/), places outside the repository (../, /) or placeholders (NAME, DIR, *)
# are left alone, as are include names (`impulse/workshop.h`) and a course's own repository's
# folders (`.github/workflows/`).
#   cmake -DSOURCE=<repository> -P docs_test.cmake
cmake_minimum_required(VERSION 3.25)
file(READ ${SOURCE}/README.md readme)
string(REGEX MATCHALL "\n" readme_lines "${readme}")
list(LENGTH readme_lines readme_length)
set(problems "")
if(readme_length GREATER 300)
  string(APPEND problems "README.md has ${readme_length} lines: at most 300 (move the detail to docs/)\n")
endif()

file(GLOB pages ${SOURCE}/README.md ${SOURCE}/docs/*.md ${SOURCE}/*/README.md ${SOURCE}/*/*/README.md)
set(extensions "md|h|cpp|toml|sh|py|json|yml|yaml|cmake|txt|ipynb|csv|cfg|html|supp")
foreach(page ${pages})
  get_filename_component(folder ${page} DIRECTORY)
  file(RELATIVE_PATH name ${SOURCE} ${page})
  file(READ ${page} text)
  string(REGEX MATCHALL "\\]\\([^)# ]+" links "${text}")
  string(REGEX MATCHALL "`[A-Za-z0-9_.-]+/[A-Za-z0-9_./-]*(\\.(${extensions})|/)`" quoted "${text}")
  foreach(entry ${links} ${quoted})
    string(REGEX REPLACE "^(\\]\\(|`)" "" path "${entry}")
    string(REGEX REPLACE "`$" "" path "${path}")
    if(path MATCHES "^(https?:|mailto:|out/|build|\\.\\./|/|impulse/|\\.github/)" OR path MATCHES "(NAME|DIR|FILE|SCENE|\\*|<|\\{)")
      continue()
    endif()
    if(NOT EXISTS ${SOURCE}/${path} AND NOT EXISTS ${folder}/${path})
      string(APPEND problems "${name} names ${path}, which is not there\n")
    endif()
  endforeach()
endforeach()
if(problems)
  message(FATAL_ERROR "${problems}")
endif()
