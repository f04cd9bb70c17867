# px_conformance_decision: the conformance test is registered where its data is, left out with a
# message where it is not, and a configure error where it is required (CI) but missing.
include(${PX_MODULES}/PxConformance.cmake)

file(REMOVE_RECURSE ${WORK_DIR})
set(full ${WORK_DIR}/full)
set(half ${WORK_DIR}/half) # the cone map without its height map
set(none ${WORK_DIR}/none)
foreach(file ${PX_CONFORMANCE_DATA})
  file(WRITE ${full}/${file} "x")
endforeach()
# Every file but the height map of example_1: one missing file is enough to refuse.
foreach(file ${PX_CONFORMANCE_DATA})
  if(NOT file MATCHES "example_1_heightmap")
    file(WRITE ${half}/${file} "x")
  endif()
endforeach()
file(MAKE_DIRECTORY ${none})

set(failures 0)
function(expect mode dir decision pattern)
  px_conformance_decision("${mode}" "${dir}" got message)
  if(NOT got STREQUAL decision OR NOT message MATCHES "${pattern}")
    message(SEND_ERROR "mode ${mode}, ${dir}: expected ${decision} matching '${pattern}', "
                       "got ${got}: ${message}")
  else()
    message(STATUS "mode ${mode}, ${dir}: ${got}: ${message}")
  endif()
endfunction()

expect(AUTO ${full} REGISTER "^core.bake.ConeMapConformance, core.material.TextureSetConformance and cli.import.learnopengl-\\* run on the third-party data in ${full}/testdata")
expect(ON ${full} REGISTER "run on the third-party data")
expect(auto ${full} REGISTER "run on") # case-insensitive, as CMake's booleans
list(LENGTH PX_CONFORMANCE_DATA all)
expect(AUTO ${none} SKIP "TextureSetConformance and cli.import.learnopengl-\\* left out: ${all} of their third-party data files are not in ${none}/testdata \\(the first: ${none}/testdata/graphics-snippets/example_1_conemap.png: set PX_SHARED_DIR to the folder that holds testdata/, or PX_CONFORMANCE=ON to require it as CI does\\)$")
expect(AUTO ${half} SKIP "left out: 1 of their third-party data files")
expect(ON ${none} ERROR "PX_CONFORMANCE is ON but the conformance data is missing: ${none}/testdata/graphics-snippets/example_1_conemap.png, ${none}/testdata/graphics-snippets/example_1_heightmap.png")
expect(ON ${half} ERROR "missing: ${half}/testdata/graphics-snippets/example_1_heightmap.png \\(set PX_SHARED_DIR to the folder that holds testdata/\\)$")
expect(OFF ${full} SKIP "left out: PX_CONFORMANCE is OFF")
expect(maybe ${full} ERROR "PX_CONFORMANCE is \"MAYBE\": expected AUTO, ON or OFF")
file(REMOVE_RECURSE ${WORK_DIR})
