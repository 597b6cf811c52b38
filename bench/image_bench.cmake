# Saving and loading images, side by side with ImageMagick's convert.
add_executable(bench_image_io image_io_bench.cc)
target_link_libraries(bench_image_io PRIVATE vl_image benchmark::benchmark vl_warnings)
