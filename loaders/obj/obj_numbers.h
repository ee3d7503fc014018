// The numbers of OBJ and MTL statements, checked before tinyobjloader reads them: it takes a
// word it cannot parse ("nan", "inf", "0,5") as 0 and a number too large for a float as
// infinity, without a word. These checks refuse both as `file:line:col`.
#pragma once

#include <istream>
#include <string>

namespace radiant {

// `v`, `vn` (at least three numbers each), `vt` and `vp`: every argument a number finite as a float.
// `f`, `l` and `p`: every index within a 32-bit int (tinyobjloader wraps larger ones).
void check_obj_numbers(std::istream& in, const std::string& file);

// The numeric MTL statements (Ka, Kd, Ks, Ke, Kt, Tf, Ns, Ni, d, Tr, illum and the PBR ones):
// finite numbers, and colors and emission not negative (negative radiance has no meaning).
void check_mtl_numbers(std::istream& in, const std::string& file);

}  // namespace radiant
