# vl_image: pixels and their storages, the virtual frame buffer, image files (PNM, PNG, PFM).
add_library(vl_image STATIC src/pixel.cc src/vfb.cc src/image_io.cc)
target_include_directories(vl_image PUBLIC include)
target_link_libraries(vl_image PUBLIC vl_tuples PRIVATE PkgConfig::PNG vl_warnings)

# vl_metrics: perceptual image comparison, LDR-FLIP (flip.hh) and SSIM (ssim.hh), on vl::image.
add_library(vl_metrics STATIC src/flip.cc src/ssim.cc)
target_link_libraries(vl_metrics PUBLIC vl_image PRIVATE vl_warnings)
