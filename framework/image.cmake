# vl_image: pixels and their storages, the virtual frame buffer, image files (PNM, PNG, PFM).
add_library(vl_image STATIC src/pixel.cc src/vfb.cc src/image_io.cc)
target_include_directories(vl_image PUBLIC include)
target_link_libraries(vl_image PUBLIC vl_tuples PRIVATE PkgConfig::PNG vl_warnings)
