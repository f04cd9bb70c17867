# Sources of the core's io area.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/AtomicWrite.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Inputs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/OutputGate.cpp
  ${CMAKE_CURRENT_LIST_DIR}/OutputLock.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ShortestDecimal.cpp
  ${CMAKE_CURRENT_LIST_DIR}/StagedSet.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Temporaries.cpp
)
