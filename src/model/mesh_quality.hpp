// Validation and quality measures of a shell mesh (conventions in mesh.hpp).
//
// check_mesh refuses what would make the shell elements fail or silently compute nonsense:
// dangling or repeated node indices, elements without area, elements whose node order is
// clockwise about the directors (negative Jacobian), directors that are not unit or not close
// to the element normal, neighbours with opposite orientation, nodes no element uses, and nodes
// that coincide without being merged (an unintended crack). Distortion limits (scaled Jacobian,
// aspect ratio, warp) follow the usual pre-processor checks (e.g. the Abaqus/Patran element
// quality checks): thresholds are generous on purpose, they catch broken meshes, not merely
// poor ones.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "model/mesh.hpp"

namespace si {

struct MeshQualityLimits {
  // Smallest allowed corner Jacobian scaled by the two edge lengths (sine of the corner angle
  // measured about the director): 0.05 is a corner angle of about 3 or 177 degrees.
  double min_scaled_jacobian = 0.05;
  // Smallest allowed ratio of the smallest to the largest corner Jacobian (the pre-processors'
  // "Jacobian ratio"; 1 for a parallelogram): catches strongly tapered elements.
  double min_jacobian_ratio = 0.05;
  double max_aspect_ratio = 50;        // longest edge / shortest edge
  double max_warp_deg = 30;            // angle between the normals of the two triangle halves
  double max_director_angle_deg = 45;  // director versus element normal at the centre
  double director_unit_tolerance = 1e-8;
  double coincident_tolerance = 1e-9;  // relative to the diagonal of the bounding box
  // Deliberately coincident, unconnected nodes (the lips of a slit or crack).
  bool allow_coincident_nodes = false;
};

// Quality measures of one element (for reports; check_mesh applies the limits).
struct ElementQuality {
  double area = 0;                    // mm^2, bilinear surface
  double min_scaled_jacobian = 0;     // smallest corner Jacobian / (edge length product)
  double jacobian_ratio = 0;          // smallest / largest corner Jacobian
  double aspect_ratio = 0;            // longest edge / shortest edge
  double warp_deg = 0;                // largest angle between the triangle-half normals
  double max_director_angle_deg = 0;  // largest angle director-to-element normal at a corner
};

// Requires valid node indices and one director per node.
ElementQuality element_quality(const Mesh& mesh, int e);

// Throws an input si::Error whose reason names the failing element (index and node indices)
// or node and the measure that failed. Checks, in order: one unit director per node, every
// element (check_element), consistent orientation, unused nodes, coincident nodes, node sets.
void check_mesh(const Mesh& mesh, const MeshQualityLimits& limits = {});

// The first pair of elements that traverse a shared edge in the same direction (inconsistent
// orientation, or an edge shared by more than two elements), if any.
std::optional<std::pair<int, int>> find_inconsistent_orientation(const Mesh& mesh);

// The per-element part of check_mesh: node indices in range and distinct, non-zero area, not
// inverted about the directors, directors close to the normal, then the distortion limits.
// Requires one director per node.
void check_element(const Mesh& mesh, int e, const MeshQualityLimits& limits = {});

// Throws unless every edge shared by two elements is traversed in opposite directions by them
// (consistent orientation) and no edge is shared by more than two elements.
void check_orientation_consistency(const Mesh& mesh);

// "element 3 (nodes 0 1 2 9)", the way every mesh message names an element.
std::string describe_element(const Mesh& mesh, int e);

}  // namespace si
