# Sources of the core's trace area.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/Technique.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Tracer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TraceScene.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ParallaxBound.cpp
)
