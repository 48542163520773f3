# Every dependency comes from a Debian package (scripts/setup installs them).
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)
find_package(glm REQUIRED)
find_package(glfw3 3.3 REQUIRED)
find_package(OpenGL REQUIRED COMPONENTS EGL)
find_package(ZLIB REQUIRED)
# glTF loading: Debian's tinygltf is a shared library (target TinyGLTF::TinyGLTF), so no
# TINYGLTF_IMPLEMENTATION anywhere.
find_package(TinyGLTF REQUIRED)
# DICOM series: GDCM parses the data sets and decodes every transfer syntax (JPEG, JPEG-LS,
# JPEG 2000, RLE), which a hand-written reader could not match (lib/volsg/volumeio).
find_package(GDCM REQUIRED)
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)
# OME-Zarr chunks (lib/volsg/volumeio/OMEZARR.md): Debian's zstd and blosc are the codecs
# python-zarr itself uses (blosc with its lz4, zstd and zlib inner codecs and shuffles), so
# volsg reads what those tools write without a decompressor of its own.
pkg_check_modules(ZSTD REQUIRED IMPORTED_TARGET libzstd)
pkg_check_modules(BLOSC REQUIRED IMPORTED_TARGET blosc)
# Texture image files: libsimage is the loader Coin itself uses, so a Texture2 reads exactly
# the formats an Inventor file may name (SGI .rgb, PNG, JPEG, GIF, TIFF).
pkg_check_modules(SIMAGE REQUIRED IMPORTED_TARGET simage)
# Text: FreeType gives the glyph outlines (Text3, AsciiText) and bitmaps (Text2) of the DejaVu
# faces (fonts-dejavu-core, found at run time). GLU's polygon tessellator triangulates glyph
# outlines and trimmed NURBS cells (pure computation: no GL context, no GL call).
find_package(Freetype REQUIRED)
pkg_check_modules(GLU REQUIRED IMPORTED_TARGET glu)
# Dear ImGui for the viewer's editor panels: Debian ships a static libimgui.a with the GLFW and
# OpenGL3 backends compiled in and no CMake config.
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
if(VOLSG_BUILD_TESTS)
  find_package(doctest REQUIRED)
endif()
