# After a failed import onto keep.json: it equals its twin byte for byte and no temporary file is
# left beside it.
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files keep.json keep-twin.json RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "keep.json changed")
endif()
file(GLOB left .keep.json* *.tmp* .px-tmp-*)
if(left)
  message(FATAL_ERROR "left behind: ${left}")
endif()
