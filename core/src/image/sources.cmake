# Sources of the core's image area.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/ExrHeaderCheck.cpp
  ${CMAKE_CURRENT_LIST_DIR}/FileSizeBound.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ImageFormat.cpp
  ${CMAKE_CURRENT_LIST_DIR}/JpegCheck.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Orientation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ImageBudget.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ImageFile.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ImageModule.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ImageSet.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PngCheck.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PngCodec.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PngDeflate.cpp
)
