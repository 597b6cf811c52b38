# Pixels, the virtual frame buffer and image files (vl_image).
vl_add_tests(image_test LABEL framework LIBS vl_image
  SOURCES pixel_test.cc vfb_test.cc image_io_test.cc bad_images_test.cc)
target_compile_definitions(image_test PRIVATE VL_TEST_IMAGES="${CMAKE_CURRENT_SOURCE_DIR}/data/images")

# Perceptual image comparison: LDR-FLIP and SSIM (vl_metrics).
vl_add_tests(image_metrics_test LABEL framework LIBS vl_metrics SOURCES image_metrics_test.cc)
target_compile_definitions(image_metrics_test PRIVATE VL_TEST_METRICS="${CMAKE_CURRENT_SOURCE_DIR}/data/metrics")

# Line charts drawn by gnuplot (vl_metrics).
vl_add_tests(chart_test LABEL framework LIBS vl_metrics SOURCES chart_test.cc)
