#pragma once
// The built-in fields, one file each (formulas in their files and in docs/refiners.md); the UGAWG
// benchmark's three 3D fields in one (ugawg.cpp).
#include "fields/registry.hpp"

namespace anisocert::fields {

FieldEntry constant_field();
FieldEntry linear_field();
FieldEntry shock_field();
FieldEntry radial_field();

FieldEntry3 constant_field3();
FieldEntry3 ugawg_linear_field();
FieldEntry3 ugawg_polar_field(int variant);  // UGAWG polar-1 or polar-2

}  // namespace anisocert::fields
