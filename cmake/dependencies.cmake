# Every dependency is a Debian 12 package with a CMake config (scripts/setup.sh installs them).
find_package(embree 3 REQUIRED)
find_package(OpenImageIO REQUIRED)
find_package(PNG REQUIRED)
find_package(TinyGLTF REQUIRED)
find_package(tinyobjloader REQUIRED)
find_package(TBB REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(doctest REQUIRED)
find_package(draco REQUIRED)  # KHR_draco_mesh_compression
find_package(meshoptimizer REQUIRED)  # EXT_meshopt_compression

# Debian's OpenImageIO config lists /usr/include/opencv4, which exists only with libopencv-dev;
# CMake refuses a missing include path, so drop it rather than install OpenCV.
foreach(_target OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
  if(TARGET ${_target})
    get_target_property(_dirs ${_target} INTERFACE_INCLUDE_DIRECTORIES)
    if(_dirs)
      list(FILTER _dirs EXCLUDE REGEX "opencv4")
      set_target_properties(${_target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_dirs}")
    endif()
  endif()
endforeach()

# cpp-httplib (--serve's page): Debian builds it as a shared library and ships only a pkg-config
# file, whose flags must match the library's (it was built with OpenSSL, zlib and Brotli).
find_package(PkgConfig REQUIRED)
pkg_check_modules(HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)
