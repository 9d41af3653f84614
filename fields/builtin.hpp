#pragma once
// The built-in fields, one file each (formulas in their files and in docs/refiners.md).
#include "fields/registry.hpp"

namespace anisocert::fields {

FieldEntry constant_field();
FieldEntry linear_field();
FieldEntry shock_field();
FieldEntry radial_field();

}  // namespace anisocert::fields
