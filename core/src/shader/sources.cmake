# Sources of the core's shader area: variant keys, the generator, and shaders/ embedded as C++.
file(GLOB_RECURSE _px_shader_files CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/shaders/*.glsl)
set(_px_shader_embedded ${CMAKE_CURRENT_BINARY_DIR}/generated/shader/EmbeddedShaders.cpp)
add_custom_command(
  OUTPUT ${_px_shader_embedded}
  COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR}/shaders -DOUT=${_px_shader_embedded}
          -P ${CMAKE_CURRENT_LIST_DIR}/EmbedShaders.cmake
  DEPENDS ${_px_shader_files} ${CMAKE_CURRENT_LIST_DIR}/EmbedShaders.cmake
  COMMENT "Embedding shaders/*.glsl"
  VERBATIM)
target_sources(parallax-core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/VariantKey.cpp
  ${CMAKE_CURRENT_LIST_DIR}/GlslUnit.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ShaderBindings.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ShaderGenerator.cpp
  ${_px_shader_embedded}
)
target_include_directories(parallax-core PRIVATE ${CMAKE_CURRENT_LIST_DIR})
