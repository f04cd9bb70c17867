# Sources of the core's eval area: the benchmark, the stability suite and the recommendation.
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/EvalControl.cpp
  ${CMAKE_CURRENT_LIST_DIR}/HitErrorStats.cpp
  ${CMAKE_CURRENT_LIST_DIR}/WeightedErrorStats.cpp
  ${CMAKE_CURRENT_LIST_DIR}/QualitySweep.cpp
  ${CMAKE_CURRENT_LIST_DIR}/RayBatch.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Bench.cpp
  ${CMAKE_CURRENT_LIST_DIR}/BenchCsv.cpp
  ${CMAKE_CURRENT_LIST_DIR}/WorkPrecision.cpp
  ${CMAKE_CURRENT_LIST_DIR}/StabilityCases.cpp
  ${CMAKE_CURRENT_LIST_DIR}/StabilitySuite.cpp
  ${CMAKE_CURRENT_LIST_DIR}/QuantileBound.cpp
  ${CMAKE_CURRENT_LIST_DIR}/RayProbe.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ProbeRun.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Recommendation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/RecommendationText.cpp
  ${CMAKE_CURRENT_LIST_DIR}/EngineLayers.cpp
  ${CMAKE_CURRENT_LIST_DIR}/AutoTechnique.cpp
  # The peers' occlusion methods (PeerOcclusion.h) and the occlusion bench.
  ${CMAKE_CURRENT_LIST_DIR}/peers/PeerSurface.cpp
  ${CMAKE_CURRENT_LIST_DIR}/peers/HbaoOcclusion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/peers/MaxOfSineOcclusion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/peers/SsaoSumOcclusion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/peers/RayMarchOcclusion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/OcclusionBench.cpp
)
