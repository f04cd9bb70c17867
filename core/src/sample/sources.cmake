# Sources of the core's sample area.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/ProceduralMaps.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ProceduralAlbedo.cpp
  ${CMAKE_CURRENT_LIST_DIR}/AdversarialMaps.cpp
)
