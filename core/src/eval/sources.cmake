# Sources of the core's eval area: the benchmark and the stability suite.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/EvalControl.cpp
  ${CMAKE_CURRENT_LIST_DIR}/HitErrorStats.cpp
  ${CMAKE_CURRENT_LIST_DIR}/QualitySweep.cpp
  ${CMAKE_CURRENT_LIST_DIR}/RayBatch.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Bench.cpp
  ${CMAKE_CURRENT_LIST_DIR}/BenchCsv.cpp
  ${CMAKE_CURRENT_LIST_DIR}/WorkPrecision.cpp
  ${CMAKE_CURRENT_LIST_DIR}/StabilityCases.cpp
  ${CMAKE_CURRENT_LIST_DIR}/StabilitySuite.cpp
)
