# Sources of the core's export area: packages and engine exports of a material.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/BatchScan.cpp
  ${CMAKE_CURRENT_LIST_DIR}/EngineExport.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Exporter.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ExportFolder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ExportFormat.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ExportTextures.cpp
  ${CMAKE_CURRENT_LIST_DIR}/GltfExport.cpp
  ${CMAKE_CURRENT_LIST_DIR}/GodotExport.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PackageExport.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PackageShader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PackageUniforms.cpp
)
