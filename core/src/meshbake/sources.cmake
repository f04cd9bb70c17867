# Sources of the core's mesh bake area: sculpted tiles baked on Intel Embree (docs/bakers.md).
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/BakeMeshLoader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/EmbreeTile.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MeshBaker.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MeshSizeCheck.cpp
)
# Embree 3 (Debian's libembree-dev), found in cmake/PxDependencies.cmake.
target_link_libraries(parallax-core PRIVATE embree)
