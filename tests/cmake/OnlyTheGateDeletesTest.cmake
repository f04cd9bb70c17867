cmake_minimum_required(VERSION 3.20)
# Only the output gate renames or deletes files (core/include/parallax/io/OutputGate.h), with the
# signal handler's removal of the run's own temporaries (core/src/io/Temporaries.cpp): every other
# file of core/ and app/ calling a rename or a delete is named, with its line. The check is first
# shown to catch a planted call and to pass look-alikes (std::remove over a range, a QString's
# remove), then run on the tree.
set(_calls
    "(std::filesystem|fs)::(remove|remove_all|rename)[ ]*\\("
    "(^|[^A-Za-z0-9_.>])(unlink|unlinkat|rmdir|rename|renameat|renameat2)[ ]*\\("
    "std::(remove|rename)[ ]*\\([^,()]*\\)"
    "QFile::(remove|rename)|removeRecursively[ ]*\\(|QDir[^;]*\\.(remove|rmdir|rmpath)[ ]*\\(")
string(JOIN "|" _pattern ${_calls})
set(_allowed "core/src/io/OutputGate.cpp" "core/src/io/Temporaries.cpp")

function(px_find_deleters root out)
  file(GLOB_RECURSE _files RELATIVE ${root} ${root}/core/*.cpp ${root}/core/*.h ${root}/app/*.cpp
       ${root}/app/*.h)
  set(_found "")
  foreach(_f IN LISTS _files)
    if(_f IN_LIST _allowed)
      continue()
    endif()
    file(STRINGS ${root}/${_f} _lines REGEX "${_pattern}")
    foreach(_line IN LISTS _lines)
      string(STRIP "${_line}" _line)
      string(REPLACE ";" "," _line "${_line}") # a list item
      if(NOT _line MATCHES "^//")
        list(APPEND _found "${_f}: ${_line}")
      endif()
    endforeach()
  endforeach()
  set(${out} "${_found}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(WRITE ${WORK_DIR}/app/cli/Bad.cpp "void f() {\n    std::filesystem::remove(p, ec);\n}\n")
file(WRITE ${WORK_DIR}/core/src/x/Bad.cpp "    if (::unlink(path.c_str()) != 0)\n")
file(WRITE ${WORK_DIR}/core/src/x/Clean.cpp
     "v.erase(std::remove(v.begin(), v.end(), 0), v.end());\nline.remove(QLatin1Char('&'));\n"
     "// fs::remove(p) in a comment\nrecent->remove(file);\n")
px_find_deleters(${WORK_DIR} _planted)
list(LENGTH _planted _count)
if(NOT _count EQUAL 2 OR NOT _planted MATCHES "app/cli/Bad.cpp: std::filesystem::remove"
   OR NOT _planted MATCHES "core/src/x/Bad.cpp: if \\(::unlink")
  message(FATAL_ERROR "the check does not catch the planted calls, or flags look-alikes: ${_planted}")
endif()

px_find_deleters(${SOURCE_DIR} _found)
if(_found)
  string(JOIN "\n  " _text ${_found})
  message(FATAL_ERROR "renames or deletes outside the output gate:\n  ${_text}")
endif()
message(STATUS "only the output gate renames or deletes (the planted calls were caught)")
