#include "io/result_fields.hpp"

#include "model/nodal_resultants.hpp"

namespace si {

VtuFields resultant_fields(const Mesh& mesh, const Assembler& assembler,
                           const ShellElement& element, const ShellLaw& law,
                           const std::vector<NodeState>& state) {
  const Eigen::MatrixXd strains = nodal_strains(mesh, assembler, element, state);
  const Eigen::MatrixXd resultants = nodal_resultants(strains, law);
  VtuFields fields;
  fields.point_data["membrane_strain"] = strains.leftCols(3);
  fields.point_data["curvature"] = strains.middleCols(3, 3);
  fields.point_data["shear_strain_13"] = strains.col(6);
  fields.point_data["shear_strain_23"] = strains.col(7);
  fields.point_data["N"] = resultants.leftCols(3);
  fields.point_data["M"] = resultants.middleCols(3, 3);
  fields.point_data["Q1"] = resultants.col(6);
  fields.point_data["Q2"] = resultants.col(7);
  for (const char* tensor : {"membrane_strain", "curvature", "N", "M"})
    fields.kinds[tensor] = FieldKind::kInPlaneTensor;
  fields.kinds["shear_strain_13"] = fields.kinds["Q1"] = FieldKind::kAlongT1;
  fields.kinds["shear_strain_23"] = fields.kinds["Q2"] = FieldKind::kAlongT2;
  return fields;
}

}  // namespace si
