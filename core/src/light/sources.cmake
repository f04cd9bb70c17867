# Sources of the core's light area: environments for image-based light.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/CubeMapSky.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Environment.cpp
  ${CMAKE_CURRENT_LIST_DIR}/EnvironmentLighting.cpp
)
