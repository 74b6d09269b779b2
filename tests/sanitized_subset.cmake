# The unit tests of the modules below the GPU and the studies (core, image,
# noise, filter, pattern, and the marble texture of textures): every parser, image reader and CPU kernel a user's
# input reaches. They are part of stochtex_tests and, on their own, of the
# sanitizer build that `make test` runs (tests/sanitized, docs/TESTING.md
# "Sanitizers"). Paths are relative to tests/.
set(stochtex_sanitized_test_sources
  core/atomic_file_test.cpp
  core/watchdog_test.cpp
  core/progress_test.cpp
  image/image_test.cpp
  image/image_read_test.cpp
  image/colour_space_test.cpp
  noise/spectrum_test.cpp
  noise/gaussianize_test.cpp
  noise/tiling_blending_test.cpp
  noise/tiling_blending_lanes_test.cpp
  noise/tiled_white_noise_test.cpp
  filter/filter_test.cpp
  pattern/colormap_test.cpp
  pattern/phasor_test.cpp
  pattern/pattern_spec_test.cpp
  pattern/hostile_input_test.cpp
  pattern/pattern_test.cpp
  pattern/linear_light_test.cpp
  pattern/filtered_program_test.cpp
  pattern/lean_test.cpp
  pattern/camera_test.cpp
  pattern/texture_graph_test.cpp
  pattern/graph_pattern_test.cpp
  pattern/simd_render_test.cpp
  pattern/graph_lean_test.cpp
  pattern/graph_tiled_field_test.cpp
  pattern/part_cache_test.cpp
  textures/marble_texture_test.cpp)
