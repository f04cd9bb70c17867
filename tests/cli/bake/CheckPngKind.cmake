# Checks a PNG's bit depth and colour type (IHDR) and that it carries no colour chunk (sRGB, gAMA,
# cHRM, iCCP): cmake -DPNG=file -DDEPTH=16 -DCOLOUR=0 (grey) -P CheckPngKind.cmake
file(READ ${PNG} hex HEX)
string(SUBSTRING "${hex}" 48 2 depth)
string(SUBSTRING "${hex}" 50 2 colour)
math(EXPR depth "0x${depth}")
math(EXPR colour "0x${colour}")
if(NOT depth EQUAL DEPTH OR NOT colour EQUAL COLOUR)
  message(FATAL_ERROR "${PNG}: bit depth ${depth}, colour type ${colour}; expected ${DEPTH}, ${COLOUR}")
endif()
# sRGB, gAMA, cHRM, iCCP as hex.
foreach(chunk 73524742 67414d41 6348524d 69434350)
  string(FIND "${hex}" "${chunk}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "${PNG}: has a colour chunk (${chunk})")
  endif()
endforeach()
