#pragma once
// A bounded pass over OBJ text before tinyobjloader sees it. The library parses integers with atoi and
// converts joint ids from float to int without range checks, and its exponent loop overflows an int
// (`v 1e2147483648 0 0`, `vw 0 1e10 1`): undefined behaviour on crafted input. Its polygon
// triangulation is quadratic in the vertices of a face (4 s for 4 MB of 1024-gons), so polygons are
// capped. We refuse what it cannot parse safely, and count the triangles a file will make before it
// allocates them.
#include <cstdint>
#include <string>
#include <string_view>

namespace lp::obj {

inline constexpr int kMaxObjFaceVertices = 256;     // more in one polygon is refused
inline constexpr int kMaxObjExponentDigits = 4;     // 1e9999 is already beyond double
inline constexpr int64_t kMaxObjJointId = 1 << 24;  // skin-weight joint ids must be exact in a float

// Returns the number of triangles the faces make. Throws lp::Error(Corrupt) naming the line, or
// TooLarge when the faces make over `max_triangles`.
int64_t check_obj_text(std::string_view text, const std::string& name, int64_t max_triangles);

// The same for a material library (.mtl), whose numbers and options go through the same parsers: every
// integer fits an int and no number has a long exponent. Throws lp::Error(Corrupt) naming the line.
void check_mtl_text(std::string_view text, const std::string& name);

}  // namespace lp::obj
