# Sources of the core's engine area: models of the engines' own parallax marches.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/EngineMarch.cpp
)
