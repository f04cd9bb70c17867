# px_check_layers on made-up trees laid out as the real one, with the real layer table: a clean
# tree passes; an include from a layer above, one from a layer beside and an include cycle inside
# one layer are each refused, naming the file, the line and the layers (or the cycle).
cmake_minimum_required(VERSION 3.25)
include(${PX_MODULES}/PxLayerCheck.cmake)

function(write_tree dir)
  file(REMOVE_RECURSE ${dir})
  file(WRITE ${dir}/core/include/parallax/Result.h "#pragma once\n")
  file(WRITE ${dir}/core/include/parallax/heightfield/HeightField.h
       "#pragma once\n#include \"parallax/Result.h\"\n#include <vector>\n")
  file(WRITE ${dir}/core/include/parallax/material/Material.h
       "#pragma once\n#include \"parallax/heightfield/HeightField.h\"\n")
  file(WRITE ${dir}/core/src/bake/Baker.cpp
       "#include \"parallax/heightfield/HeightField.h\"\n#include \"Cells.h\"\n#include \"gen/Version.h\"\n")
  file(WRITE ${dir}/core/src/bake/Cells.h "#pragma once\n")
  file(WRITE ${dir}/app/studio/model/Document.h "#pragma once\n#include \"parallax/material/Material.h\"\n")
  file(WRITE ${dir}/app/cli/Main.cpp "#include \"parallax/material/Material.h\"\n")
endfunction()

function(expect case pattern)
  px_check_layers(ROOT ${WORK_DIR}/${case} PROBLEMS problems)
  if(NOT problems)
    message(FATAL_ERROR "${case}: accepted")
  endif()
  if(NOT problems MATCHES "${pattern}")
    message(FATAL_ERROR "${case}: the refusal does not say what is wrong where:\n${problems}")
  endif()
endfunction()

write_tree(${WORK_DIR}/clean)
px_check_layers(ROOT ${WORK_DIR}/clean PROBLEMS problems)
if(problems)
  message(FATAL_ERROR "a clean tree was refused:\n${problems}")
endif()

# A lower layer including a higher one's header (as NormalMapBaker.h once included Material.h).
write_tree(${WORK_DIR}/above)
file(APPEND ${WORK_DIR}/above/core/src/bake/Cells.h "  # include \"parallax/material/Material.h\"\n")
expect(above "core/src/bake/Cells.h: # include \"parallax/material/Material.h\": core/bake may not include core/material")

# The command line including the editor's model (a layer beside it, not below).
write_tree(${WORK_DIR}/beside)
file(APPEND ${WORK_DIR}/beside/app/cli/Main.cpp "#include \"model/Document.h\"\n")
expect(beside "app/cli/Main.cpp: #include \"model/Document.h\": app/cli may not include app/studio/model")

# Two files of one layer including each other, one through a relative path.
write_tree(${WORK_DIR}/cycle)
file(WRITE ${WORK_DIR}/cycle/core/src/bake/Cells.h "#pragma once\n#include \"../bake/Strips.h\"\n")
file(WRITE ${WORK_DIR}/cycle/core/src/bake/Strips.h "#pragma once\n#include \"bake/Cells.h\"\n")
expect(cycle "include cycle: core/src/bake/Cells.h -> core/src/bake/Strips.h -> core/src/bake/Cells.h")

message(STATUS "layering check: clean tree passed; above, beside and cycle refused")
