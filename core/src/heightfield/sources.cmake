# Sources of the core's heightfield area.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/HeightField.cpp
  ${CMAKE_CURRENT_LIST_DIR}/HeightFieldLoader.cpp
)
