# Whether the conformance tests on third-party data are registered: core.bake.ConeMapConformance
# (graphics-snippets' example_1), core.material.TextureSetConformance and
# cli.import.learnopengl-* (LearnOpenGL's bricks2 and toy_box sets). The data has no
# redistribution licence, so it is not in the repository; it is looked for in
# PX_SHARED_DIR/testdata (docs/development.md, "Conformance data"). All of them or none: a test
# whose files are missing is never left out on its own.
#
#   PX_CONFORMANCE  AUTO (default): registered where all the data is found, else left out with a
#                   configure message; ON: the data is required (CI), configuring fails without
#                   any of it; OFF: left out.
#
#   px_conformance_decision(<mode> <shared dir> <out: REGISTER|SKIP|ERROR> <out: message>)
# decides, with no side effects (tests/cmake runs it in script mode).

set(PX_CONFORMANCE_DATA testdata/graphics-snippets/example_1_conemap.png
    testdata/graphics-snippets/example_1_heightmap.png
    testdata/graphics-snippets/example_1_texture.png
    testdata/learnopengl/bricks2.jpg testdata/learnopengl/bricks2_disp.jpg
    testdata/learnopengl/bricks2_normal.jpg testdata/learnopengl/toy_box_diffuse.png
    testdata/learnopengl/toy_box_disp.png testdata/learnopengl/toy_box_normal.png
    testdata/learnopengl/wood.png)
string(CONCAT PX_CONFORMANCE_TESTS "core.bake.ConeMapConformance, "
       "core.material.TextureSetConformance and cli.import.learnopengl-*")

function(px_conformance_decision mode dir out_decision out_message)
  string(TOUPPER "${mode}" mode)
  set(missing "")
  foreach(file ${PX_CONFORMANCE_DATA})
    if(NOT EXISTS "${dir}/${file}")
      list(APPEND missing "${dir}/${file}")
    endif()
  endforeach()
  if(mode STREQUAL "OFF")
    set(decision SKIP)
    set(message "${PX_CONFORMANCE_TESTS} left out: PX_CONFORMANCE is OFF")
  elseif(NOT mode MATCHES "^(AUTO|ON)$")
    set(decision ERROR)
    set(message "PX_CONFORMANCE is \"${mode}\": expected AUTO, ON or OFF")
  elseif(NOT missing)
    set(decision REGISTER)
    set(message "${PX_CONFORMANCE_TESTS} run on the third-party data in ${dir}/testdata")
  elseif(mode STREQUAL "ON")
    list(JOIN missing ", " missing)
    set(decision ERROR)
    set(message "PX_CONFORMANCE is ON but the conformance data is missing: ${missing} (set "
                "PX_SHARED_DIR to the folder that holds testdata/)")
  else()
    set(decision SKIP)
    list(LENGTH missing count)
    list(GET missing 0 first)
    set(message "${PX_CONFORMANCE_TESTS} left out: ${count} of their third-party data files are "
                "not in ${dir}/testdata (the first: ${first}: set PX_SHARED_DIR to the folder that "
                "holds testdata/, or PX_CONFORMANCE=ON to require it as CI does)")
  endif()
  string(CONCAT message ${message})
  set(${out_decision} ${decision} PARENT_SCOPE)
  set(${out_message} "${message}" PARENT_SCOPE)
endfunction()
