// Sze, Liu & Lo (2004), the published paths of their benchmarks (S4R tables, copied from
// ../shared/benchmarks/csv with the source named at each table) and the exact elastica of sec.
// 3.2: shared by the library-level tests (test_nonlinear_shell_benchmarks.cpp,
// test_sze_hinged_roof.cpp) and the case-file tests (tests/app/test_sze_case_files.cpp).
#pragma once

#include <cmath>
#include <vector>

namespace si::verification {

// Sec. 3.1, cantilever under end shear (MBDyn sze31_ref.dat = csv/sze2004_3-1_*): -U_tip and
// W_tip at P/Pmax = 0.05, 0.10, ..., 1.00.
inline const std::vector<double> kSze31MinusU = {0.026, 0.103, 0.224, 0.381, 0.563, 0.763, 0.971,
                                                 1.184, 1.396, 1.604, 1.807, 2.002, 2.190, 2.370,
                                                 2.541, 2.705, 2.861, 3.010, 3.151, 3.286};
inline const std::vector<double> kSze31W = {0.663, 1.309, 1.922, 2.493, 3.015, 3.488, 3.912,
                                            4.292, 4.631, 4.933, 5.202, 5.444, 5.660, 5.855,
                                            6.031, 6.190, 6.335, 6.467, 6.588, 6.698};

// Sec. 3.2, the exact elastica of a cantilever of length L under an end moment: at the tip
// rotation theta = M L / EI, -U_tip = L (1 - sin theta / theta), W_tip = L (1 - cos theta) / theta.
inline double elastica_minus_u(double L, double theta) {
  return L * (1 - std::sin(theta) / theta);
}
inline double elastica_w(double L, double theta) {
  return L * (1 - std::cos(theta)) / theta;
}

// Sec. 3.3, slit annular plate (MBDyn sze33_ref.dat = csv/sze2004_3-3_*): W at the inner (A) and
// outer (B) corners of the loaded lip at the q/qmax below.
inline const std::vector<double> kSze33LoadFactors = {
    0.025, 0.05, 0.075, 0.10, 0.125, 0.15, 0.20, 0.25, 0.30, 0.35, 0.40, 0.45,
    0.50,  0.55, 0.60,  0.65, 0.70,  0.75, 0.80, 0.85, 0.90, 0.95, 1.00};
inline const std::vector<double> kSze33WInner = {
    1.305,  2.455,  3.435,  4.277,  5.007,  5.649,  6.725,  7.602,  8.340,  8.974,  9.529, 10.023,
    10.468, 10.876, 11.257, 11.620, 11.970, 12.310, 12.642, 12.966, 13.282, 13.590, 13.891};
inline const std::vector<double> kSze33WOuter = {
    1.789,  3.370,  4.720,  5.876,  6.872,  7.736,  9.160,  10.288, 11.213, 11.992, 12.661, 13.247,
    13.768, 14.240, 14.674, 15.081, 15.469, 15.842, 16.202, 16.550, 16.886, 17.212, 17.528};

// One tabulated point: P/Pmax and the downward centre deflection -W_C (mm).
struct RoofTablePoint {
  double load_factor;
  double deflection;
};

// Table 9(a), h = 12.7 (csv/sze2004_3-8a_hinged_roof_isotropic_h12.7.csv).
inline const std::vector<RoofTablePoint> kSze38aTable = {
    {0.0000, 0.000},  {0.0877, 0.693},  {0.1980, 1.638},  {0.3473, 3.087},  {0.4686, 4.477},
    {0.5647, 5.802},  {0.6381, 7.057},  {0.6908, 8.237},  {0.7246, 9.339},  {0.7412, 10.358},
    {0.7421, 11.293}, {0.7286, 12.141}, {0.7023, 12.903}, {0.6649, 13.583}, {0.6182, 14.188},
    {0.5643, 14.728}, {0.5055, 15.217}, {0.4442, 15.676}, {0.3830, 16.125}, {0.3245, 16.590},
    {0.2717, 17.094}, {0.2272, 17.657}, {0.1940, 18.299}, {0.1750, 19.028}, {0.1729, 19.852},
    {0.1905, 20.771}, {0.2303, 21.780}, {0.2950, 22.875}, {0.3871, 24.049}, {0.4443, 24.663},
    {0.5093, 25.293}, {0.5826, 25.940}, {0.6644, 26.601}, {0.7551, 27.276}, {0.8549, 27.964},
    {0.9643, 28.663}, {1.0835, 29.374}};

// Table 9(d), h = 6.35 (csv/sze2004_3-8d_hinged_roof_isotropic_h6.35.csv): -W_C turns back
// between 17.008 and 14.451 (snap-back).
inline const std::vector<RoofTablePoint> kSze38dTable = {
    {0.0000, 0.000},   {0.0517, 1.846},   {0.1182, 5.271},   {0.1583, 8.257},   {0.1837, 10.799},
    {0.1914, 11.904},  {0.1953, 12.892},  {0.1950, 13.752},  {0.1901, 14.472},  {0.1806, 15.050},
    {0.1671, 15.501},  {0.1323, 16.145},  {0.0923, 16.602},  {0.0504, 16.915},  {0.0083, 17.008},
    {-0.0312, 16.697}, {-0.0622, 15.780}, {-0.0739, 15.206}, {-0.0861, 14.767}, {-0.1001, 14.520},
    {-0.1142, 14.451}, {-0.1247, 14.862}, {-0.1288, 15.778}, {-0.1271, 16.961}, {-0.1196, 18.320},
    {-0.1055, 19.817}, {-0.0825, 21.420}, {-0.0484, 23.100}, {-0.0006, 24.824}, {0.0626, 26.565},
    {0.1427, 28.302},  {0.2403, 30.023},  {0.3559, 31.720},  {0.4898, 33.388},  {0.6417, 35.024},
    {0.8114, 36.626},  {1.0313, 38.450}};

}  // namespace si::verification
