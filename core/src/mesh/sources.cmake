# Sources of the core's mesh area.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/GltfCheck.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MeshLoader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MeshScope.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ObjCheck.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TangentFrames.cpp
)
