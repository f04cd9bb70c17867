# Sources of the core's bake area.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/BakeControl.cpp
  ${CMAKE_CURRENT_LIST_DIR}/BakeEncoding.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MaxLevel.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MaxMipPyramid.cpp
  ${CMAKE_CURRENT_LIST_DIR}/CellPyramid.cpp
  ${CMAKE_CURRENT_LIST_DIR}/QuickConeBaker.cpp
  ${CMAKE_CURRENT_LIST_DIR}/FallPyramid.cpp
  ${CMAKE_CURRENT_LIST_DIR}/EdgeStrips.cpp
  ${CMAKE_CURRENT_LIST_DIR}/RelaxedConeBaker.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ConeMapReference.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ConeMapFinish.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ConeMapBaker.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ConeBakeInputs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ConeCacheFile.cpp
  ${CMAKE_CURRENT_LIST_DIR}/NormalMapBaker.cpp
  ${CMAKE_CURRENT_LIST_DIR}/NormalMapConversion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/HeightFromNormals.cpp
  ${CMAKE_CURRENT_LIST_DIR}/OcclusionHorizon.cpp
  ${CMAKE_CURRENT_LIST_DIR}/OcclusionBaker.cpp
)
