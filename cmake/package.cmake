# The Debian package: `cpack -G DEB` in the build directory makes impulse_VERSION_ARCH.deb of what
# `cmake --install` puts under /usr (the programs, the workshop header, the Python package, the
# catalogue). Its Depends: the shared libraries the programs and the module link, as
# dpkg-shlibdeps finds them, and what impulse runs or loads without linking it: Mesa's EGL and
# drivers (libglvnd loads them), LaTeX and dvisvgm (typeset equations), the fonts, the C++
# compiler a student's file is built with, and the Python the module was built for.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME impulse)
set(CPACK_PACKAGE_VERSION 0.1.0)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Rigid-body collision physics, rendered headless into teaching videos")
set(CPACK_PACKAGE_CONTACT "impulse maintainers <impulse@localhost>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libegl-mesa0, libgl1-mesa-dri, texlive-latex-base, dvisvgm, fonts-dejavu-core, fonts-noto-core, g++")
if(impulse_python_depends)
  string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", ${impulse_python_depends}")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "fonts-noto-color-emoji, python3-tqdm, python3-matplotlib, python3-pandas")
include(CPack)
