# Every third-party library littermap uses, found once, as imported targets.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(OpenCV 4 REQUIRED COMPONENTS core imgproc imgcodecs ml features2d calib3d rgbd)
find_package(SQLite3 REQUIRED)
find_package(PostgreSQL REQUIRED)  # libpq: sites in PostGIS
find_package(ZLIB REQUIRED)
find_package(PNG REQUIRED)
find_package(JPEG REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(Threads REQUIRED)
find_package(Ceres REQUIRED)
find_package(PROJ 9 REQUIRED CONFIG)
find_package(TIFF REQUIRED)
# libgeotiff 1.7 in Debian 12 ships neither a CMake config nor a pkg-config file.
find_path(GEOTIFF_INCLUDE_DIR geotiff.h PATH_SUFFIXES geotiff libgeotiff REQUIRED)
find_library(GEOTIFF_LIBRARY NAMES geotiff REQUIRED)
if(NOT TARGET GeoTIFF::GeoTIFF)
  add_library(GeoTIFF::GeoTIFF UNKNOWN IMPORTED)
  set_target_properties(GeoTIFF::GeoTIFF PROPERTIES IMPORTED_LOCATION ${GEOTIFF_LIBRARY}
                        INTERFACE_INCLUDE_DIRECTORIES ${GEOTIFF_INCLUDE_DIR})
  target_link_libraries(GeoTIFF::GeoTIFF INTERFACE TIFF::TIFF PROJ::proj)
endif()
if(LITTERMAP_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(LITTERMAP_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()

# PCL 1.13 (integral-image normals, detect/organized_cloud.cpp). Its CMake config drags in VTK,
# whose Debian 12 targets fail to configure without MPI; the libraries needed are found
# directly instead.
find_path(PCL_INCLUDE_DIR pcl/features/integral_image_normal.h PATH_SUFFIXES pcl-1.13 REQUIRED)
find_library(PCL_COMMON_LIBRARY NAMES pcl_common REQUIRED)
find_library(PCL_FEATURES_LIBRARY NAMES pcl_features REQUIRED)
find_library(PCL_SEARCH_LIBRARY NAMES pcl_search REQUIRED)
if(NOT TARGET PCL::features)
  add_library(PCL::features INTERFACE IMPORTED)
  target_include_directories(PCL::features SYSTEM INTERFACE ${PCL_INCLUDE_DIR})
  target_link_libraries(PCL::features INTERFACE ${PCL_FEATURES_LIBRARY} ${PCL_SEARCH_LIBRARY}
                                                ${PCL_COMMON_LIBRARY}
                                                Eigen3::Eigen)
endif()

# OpenNI2 2.2 (RGB-D cameras, capture/openni2_camera.cpp) ships neither a CMake config nor a
# pkg-config file; its headers are included as system headers for their warnings.
find_path(OPENNI2_INCLUDE_DIR OpenNI.h PATH_SUFFIXES openni2 REQUIRED)
find_library(OPENNI2_LIBRARY NAMES OpenNI2 REQUIRED)
if(NOT TARGET OpenNI2::OpenNI2)
  add_library(OpenNI2::OpenNI2 UNKNOWN IMPORTED)
  set_target_properties(OpenNI2::OpenNI2 PROPERTIES IMPORTED_LOCATION ${OPENNI2_LIBRARY})
  target_include_directories(OpenNI2::OpenNI2 SYSTEM INTERFACE ${OPENNI2_INCLUDE_DIR})
endif()

# yaml-cpp 0.7 in Debian 12 exports the plain target name.
if(NOT TARGET yaml-cpp::yaml-cpp)
  add_library(yaml-cpp::yaml-cpp INTERFACE IMPORTED)
  target_link_libraries(yaml-cpp::yaml-cpp INTERFACE yaml-cpp)
endif()

# zstd and LZ4 (MCAP chunk compression, bag/mcap_compression.cpp): Debian 12 ships pkg-config
# files for both, a CMake config for neither (liblz4) or an incomplete one (libzstd).
find_package(PkgConfig REQUIRED)
pkg_check_modules(ZSTD REQUIRED IMPORTED_TARGET libzstd)
pkg_check_modules(LZ4 REQUIRED IMPORTED_TARGET liblz4)
