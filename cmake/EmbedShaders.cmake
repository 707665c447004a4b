# Run as a script: cmake -DOUTPUT=... -DINPUTS="a|b" -P EmbedShaders.cmake
# Writes a C++ file with one `extern const char* const kShader_<name>` per GLSL file.
string(REPLACE "|" ";" INPUTS "${INPUTS}")
set(content "// Generated from shaders/ by cmake/EmbedShaders.cmake; do not edit.\nnamespace patina::shader_sources {\n")
foreach(input IN LISTS INPUTS)
  get_filename_component(name "${input}" NAME)
  string(MAKE_C_IDENTIFIER "${name}" identifier)
  file(READ "${input}" text)
  string(APPEND content "extern const char* const ${identifier};\nconst char* const ${identifier} = R\"patina_glsl(${text})patina_glsl\";\n")
endforeach()
string(APPEND content "}  // namespace patina::shader_sources\n")
file(WRITE "${OUTPUT}.tmp" "${content}")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
