# Sources of the core's material area: the material file and loading a material's maps.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/MaterialAssets.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MaterialFile.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MaterialJson.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MaterialNames.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MaterialValidate.cpp
)
