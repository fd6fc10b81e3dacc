# All dependencies come from Debian 12 packages (tools/install-deps.sh installs them).
find_package(fmt REQUIRED)
find_package(TBB REQUIRED)
find_package(embree 3 REQUIRED)   # target: embree (no namespace)
find_package(OpenImageIO REQUIRED)
find_package(CLI11 REQUIRED)
find_package(Threads REQUIRED)
find_package(PNG REQUIRED)        # PNG output without loading OpenImageIO (src/snell/io/png_writer.hpp)
find_package(Freetype REQUIRED)  # text { ttf ... } glyph outlines
find_package(SDL2 QUIET)           # optional: the +D render window (src/cli/preview/); without it +D warns
find_package(assimp REQUIRED)     # mesh { "file.obj" } model import (src/plugins/assimp_plugin.cpp)
find_package(ZLIB REQUIRED)        # tests: builds a palette PNG byte by byte (tests/sdl)

# Debian's OpenImageIO target names /usr/include/opencv4, which does not exist without OpenCV's headers;
# wrap it in a target of our own with the missing folder filtered out.
add_library(snell_oiio INTERFACE)
get_target_property(_oiio_includes OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
list(FILTER _oiio_includes EXCLUDE REGEX "opencv")
set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_oiio_includes}"
  INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "")
target_link_libraries(snell_oiio INTERFACE OpenImageIO::OpenImageIO)

function(snell_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-unused-parameter)
  if(SNELL_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
