// One-dimensional graded node stations, shared by the mesh generators: the disk O-grid's radial
// rings and the graded rectangular plate and cylindrical panel (element size `size_center` near
// the indentation point, growing to `size_edge` beyond `refine_radius`).
#pragma once

#include <functional>
#include <vector>

namespace si {

// Stations s0 = t_0 < ... < t_m = s1 with m = round(integral of ds/size) elements (at least 1),
// placed so that each element holds the same share of that integral (equidistribution).
std::vector<double> graded_stations(double s0, double s1,
                                    const std::function<double(double)>& size);

// Target element sizes along a line through the indentation point.
struct LineGrading {
  double size_center = 0;    // mm, up to refine_radius from the centre
  double size_edge = 0;      // mm, at the far end; the size grows linearly in between
  double refine_radius = 0;  // mm
};

// Stations 0 = t_0 < ... < t_m = length measured from the centre, graded by `g`: the size is
// size_center up to refine_radius, then grows linearly to size_edge at `length` (a smooth
// grading: neighbouring elements differ by the slope (size_edge - size_center) / (length -
// refine_radius) times their size). Throws an input error naming size_apex, size_edge or
// refine_radius for sizes that are not positive, size_center > size_edge, or a size_center
// larger than the length.
std::vector<double> centred_graded_stations(double length, const LineGrading& g);

// The stations of `half` mirrored about 0: -t_m, ..., -t_1, 0, t_1, ..., t_m.
std::vector<double> mirrored(const std::vector<double>& half);

}  // namespace si
