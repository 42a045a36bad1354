#pragma once
// The per-format parsers behind parse_triangle_mesh; each throws located MeshErrors.

#include <string>
#include <string_view>

#include "petersen/dualize/mesh.hpp"

namespace petersen {

TriangleMesh parse_off(std::string_view bytes, const std::string& source);
TriangleMesh parse_obj(std::string_view bytes, const std::string& source);
TriangleMesh parse_ply(std::string_view bytes, const std::string& source);

}  // namespace petersen
