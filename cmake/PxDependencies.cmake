# Every third-party package the project uses, found once (docs/platform.md). A new one is also
# added to the package list in setup.sh.
find_package(OpenImageIO CONFIG REQUIRED)
# Debian 12's OpenImageIO config names a non-existent /usr/include/opencv4: drop it.
foreach(_t OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
  if(TARGET ${_t})
    get_target_property(_inc ${_t} INTERFACE_INCLUDE_DIRECTORIES)
    if(_inc)
      list(FILTER _inc EXCLUDE REGEX "opencv4")
      set_target_properties(${_t} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_inc}")
    endif()
  endif()
endforeach()
find_package(glm CONFIG REQUIRED)
find_package(nlohmann_json 3.10 CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(TBB CONFIG REQUIRED)
find_package(Threads REQUIRED)
# Assimp reads the artist's meshes (OBJ, glTF 2.0) for the preview (core/src/mesh).
find_package(assimp CONFIG REQUIRED)
# Intel Embree 3 traces the rays of the mesh bake (core/src/meshbake): Debian's libembree-dev.
find_package(embree 3 REQUIRED)
# libpng: the core checks a PNG's data with its own error handler; the tests decode exported PNGs
# the way engines do (gamma-aware).
find_package(PNG REQUIRED)
# KISS FFT (BSD-3-Clause): its header-only C++ template solves the Poisson problem of a height map
# made from a normal map in double precision (core/src/bake/HeightFromNormals.cpp).
find_path(PX_KISSFFT_INCLUDE kissfft/kissfft.hh)
if(NOT PX_KISSFFT_INCLUDE)
  message(FATAL_ERROR "kissfft/kissfft.hh not found: install Debian's libkissfft-dev (./setup.sh)")
endif()
find_package(Qt6 6.4 REQUIRED COMPONENTS Core Gui Widgets OpenGL OpenGLWidgets Test Concurrent Svg)
find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL)
find_package(benchmark CONFIG)
# PLplot draws the bench's work-precision plot. Its CMake config names Tcl libraries Debian does
# not install, so it is found through pkg-config.
find_package(PkgConfig REQUIRED)
pkg_check_modules(PLPLOT REQUIRED IMPORTED_TARGET plplot)
