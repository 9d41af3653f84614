#pragma once
// Shared by `anisocert refine` and `anisocert demo`: the refiner's summary and mesh conversion.
#include "io/mesh_output.hpp"
#include "refiners/star/star_refiner.hpp"

#include <string>

namespace anisocert::cli {

std::string lu_conditions_text(const refiners::star::RefineParameters& p);
std::string refine_summary(const refiners::star::RefineResult& r, const refiners::star::RefineParameters& p);
io::MeshData mesh_data(const refiners::star::RefineResult& r);

}  // namespace anisocert::cli
