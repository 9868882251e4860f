# Turns a text file into a C++ source defining `std::string_view lp::api::openapi_document()`.
file(READ ${INPUT} CONTENT HEX)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," CONTENT "${CONTENT}")
file(WRITE ${OUTPUT} "#include <string_view>\nnamespace lp::api {\nstatic const char kDoc[] = {${CONTENT} 0};\n"
  "std::string_view openapi_document() { return {kDoc, sizeof(kDoc) - 1}; }\n}\n")
