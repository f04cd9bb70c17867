# Writes the bake tests' inputs with parallax-cli itself: a height map, a flat normal map and
# keep.png with an identical twin (what failed bakes must leave alone).
foreach(args "sample;noise;--size;32;--out;h32.png" "sample;stones;--size;16;--out;keep.png"
             "sample;stones;--size;16;--out;keep-twin.png")
  execute_process(COMMAND ${CLI} ${args} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "parallax-cli ${args} failed")
  endif()
endforeach()
execute_process(COMMAND ${CLI} bake normal --height h32.png --out nz.png RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "parallax-cli bake normal failed")
endif()
