# Whether the conformance test on third-party data is registered. The data (graphics-snippets'
# example_1 height and cone map) has no redistribution licence, so it is not in the repository;
# it is looked for in PX_SHARED_DIR/testdata (docs/development.md, "Conformance data").
#
#   PX_CONFORMANCE  AUTO (default): registered where the data is found, else left out with a
#                   configure message; ON: the data is required (CI), configuring fails without
#                   it; OFF: left out.
#
#   px_conformance_decision(<mode> <shared dir> <out: REGISTER|SKIP|ERROR> <out: message>)
# decides, with no side effects (tests/cmake runs it in script mode).

set(PX_CONFORMANCE_DATA testdata/graphics-snippets/example_1_conemap.png
    testdata/graphics-snippets/example_1_heightmap.png)

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
    set(message "core.bake.ConeMapConformance left out: PX_CONFORMANCE is OFF")
  elseif(NOT mode MATCHES "^(AUTO|ON)$")
    set(decision ERROR)
    set(message "PX_CONFORMANCE is \"${mode}\": expected AUTO, ON or OFF")
  elseif(NOT missing)
    set(decision REGISTER)
    set(message "core.bake.ConeMapConformance runs on the third-party data in ${dir}/testdata")
  elseif(mode STREQUAL "ON")
    list(JOIN missing ", " missing)
    set(decision ERROR)
    set(message "PX_CONFORMANCE is ON but the conformance data is missing: ${missing} (set "
                "PX_SHARED_DIR to the folder that holds testdata/)")
  else()
    set(decision SKIP)
    set(message "core.bake.ConeMapConformance left out: no third-party conformance data in "
                "${dir}/testdata/graphics-snippets (set PX_SHARED_DIR to the folder that holds "
                "testdata/, or PX_CONFORMANCE=ON to require it as CI does)")
  endif()
  string(CONCAT message ${message})
  set(${out_decision} ${decision} PARENT_SCOPE)
  set(${out_message} "${message}" PARENT_SCOPE)
endfunction()
