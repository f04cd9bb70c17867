# Sources of the core's material area: the material file, loading a material's maps, and importing
# a texture set.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/MapContent.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MapFileName.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MapKind.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MapVocabulary.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MapPaths.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MaterialAssets.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MaterialFile.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MaterialJson.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MaterialNames.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MaterialValidate.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ReliefReading.cpp
  ${CMAKE_CURRENT_LIST_DIR}/SurfaceFactors.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TextureSet.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TextureSetImport.cpp
)
