# vl_image: pixels and their storages, the virtual frame buffer, image files (PNM, PNG, PFM).
add_library(vl_image STATIC src/pixel.cc src/vfb.cc src/image.cc src/image_file.cc src/image_io.cc
  src/pnm.cc src/png.cc src/pfm.cc)
target_include_directories(vl_image PUBLIC include)
target_link_libraries(vl_image PUBLIC vl_tuples PRIVATE PkgConfig::PNG vl_warnings)

# vl_metrics: measures and how they are shown: perceptual image comparison, LDR-FLIP
# (flip.hh) and SSIM (ssim.hh) on vl::image, and line charts by gnuplot (chart.hh).
add_library(vl_metrics STATIC src/flip.cc src/ssim.cc src/chart.cc)
target_link_libraries(vl_metrics PUBLIC vl_image PRIVATE vl_warnings)
