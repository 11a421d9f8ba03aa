#include "io/section_report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace si {
namespace {

constexpr const char* kRowNames[3] = {"11", "12", "22"};

// Entries below 1e-12 of their matrix's scale are round-off of exact zeros (e.g. D16 of a
// cross-ply stack); printing them as 0 keeps the report readable. JSON keeps the raw values.
double clean(double v, double scale) {
  return std::abs(v) < 1e-12 * scale ? 0.0 : v;
}

std::string fmt(double v, const char* spec = "%13.6g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, spec, v);
  return buf;
}

// A 3x3 block of the 6x6 ABD-type matrix with its row labels.
void print_block(std::ostream& os, const char* title, const Matrix6d& m, int r0, int c0) {
  os << "  " << title << "\n";
  for (int i = 0; i < 3; ++i) {
    os << "    " << kRowNames[i] << " ";
    for (int j = 0; j < 3; ++j) os << fmt(clean(m(r0 + i, c0 + j), m.cwiseAbs().maxCoeff()));
    os << "\n";
  }
}

void print_matrix2(std::ostream& os, const char* title, const Matrix2d& m) {
  const double scale = m.cwiseAbs().maxCoeff();
  os << "  " << title << fmt(clean(m(0, 0), scale)) << fmt(clean(m(0, 1), scale)) << " |"
     << fmt(clean(m(1, 0), scale)) << fmt(clean(m(1, 1), scale)) << "\n";
}

void print_vector6(std::ostream& os, const char* title, const Vector6d& v) {
  os << "  " << title;
  for (int i = 0; i < 6; ++i) os << fmt(clean(v(i), v.cwiseAbs().maxCoeff()), "%12.6g");
  os << "\n";
}

template <class M>
nlohmann::json to_json_matrix(const M& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < m.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
    rows.push_back(row);
  }
  return rows;
}

nlohmann::json to_json_vector(const Vector6d& v) {
  return nlohmann::json(std::vector<double>(v.data(), v.data() + 6));
}

void print_plies(std::ostream& os, const Laminate& lam) {
  const auto z = lam.interfaces();
  os << "  ply  material                 angle(deg)  thickness(mm)   z_bottom(mm)   z_top(mm)\n";
  for (size_t k = 0; k < lam.plies.size(); ++k) {
    const auto& p = lam.plies[k];
    char line[200];
    std::snprintf(line, sizeof line, "  %3zu  %-22s %11.4g %14.6g %14.6g %11.6g\n", k + 1,
                  p.material.name().c_str(), p.angle_deg, p.thickness, clean(z[k], z.back()),
                  clean(z[k + 1], z.back()));
    os << line;
  }
}

}  // namespace

void print_section_report(std::ostream& os, const SectionProperties& s) {
  const Laminate& lam = s.laminate;
  os << "Section " << s.label << ": " << lam.plies.size() << " plies, h = " << lam.thickness()
     << " mm, reference surface at z = " << lam.reference_offset
     << " mm from the mid-surface (plies bottom to top, z up)\n";
  print_plies(os, lam);
  os << "\nOrdering (Yu): R = [e11, 2e12, e22, k11, k12+k21, k22], gamma = [2g13, 2g23]\n";
  os << "VAM classical stiffness A_R (equals CLT for plies rotated about the normal)\n";
  print_block(os, "A (N/mm)       11           12           22", s.vam.A_R, 0, 0);
  print_block(os, "B (N)", s.vam.A_R, 0, 3);
  print_block(os, "D (N*mm)", s.vam.A_R, 3, 3);
  const double clt_gap = (s.vam.A_R - s.clt_abd).norm() / s.clt_abd.norm();
  os << "  |A_R - CLT ABD| / |CLT ABD| = " << fmt(clt_gap, "%.2e") << "\n";

  os << "\nTransverse shear stiffness G (N/mm), entries G11 G12 | G21 G22\n";
  print_matrix2(os, "VAM (Reissner-Mindlin fit)  ", s.vam.G);
  print_matrix2(os, "FSDT, k = 5/6               ", s.G_fsdt);
  print_matrix2(os, "equilibrium (Whitney-type)  ", s.G_equilibrium);
  os << "  VAM fit: relative residual " << fmt(s.vam.fit.relative_residual, "%.3e") << ", rank "
     << s.vam.fit.rank << " of " << s.vam.fit.unknowns << " unknowns\n";

  os << "\nLoad coupling F-bar per unit normal face traction (t along +x3; an indenter pressure p\n"
        "on the top face is t+ = -p), units [mm mm mm mm^2 mm^2 mm^2]; F = t F-bar in [N/mm, N]:\n";
  print_vector6(os, "F-bar top    ", s.vam.Fbar_top);
  print_vector6(os, "F-bar bottom ", s.vam.Fbar_bottom);
  os << "Face compliance c_L (mm/MPa): c++ = " << fmt(s.vam.c_L(0, 0), "%.6g")
     << ", c+- = " << fmt(s.vam.c_L(0, 1), "%.6g") << ", c-- = " << fmt(s.vam.c_L(1, 1), "%.6g")
     << "\n";
}

nlohmann::json section_to_json(const SectionProperties& s) {
  const Laminate& lam = s.laminate;
  nlohmann::json plies = nlohmann::json::array();
  for (const auto& p : lam.plies) {
    plies.push_back({{"material", p.material.name()},
                     {"angle_deg", p.angle_deg},
                     {"thickness_mm", p.thickness}});
  }
  const Matrix6d& abd = s.clt_abd;
  return {
      {"label", s.label},
      {"plies_bottom_to_top", plies},
      {"thickness_mm", lam.thickness()},
      {"reference_offset_mm", lam.reference_offset},
      {"ordering", {{"strains", "[e11, 2e12, e22, k11, k12+k21, k22]"}, {"shear", "[2g13, 2g23]"}}},
      {"units",
       {{"A", "N/mm"},
        {"B", "N"},
        {"D", "N*mm"},
        {"G", "N/mm"},
        {"Fbar", "[mm, mm, mm, mm^2, mm^2, mm^2]; F = t Fbar with t in MPa"},
        {"c_L", "mm/MPa"}}},
      {"clt",
       {{"A", to_json_matrix(abd.block<3, 3>(0, 0))},
        {"B", to_json_matrix(abd.block<3, 3>(0, 3))},
        {"D", to_json_matrix(abd.block<3, 3>(3, 3))}}},
      {"shear",
       {{"vam", to_json_matrix(s.vam.G)},
        {"fsdt_k5_6", to_json_matrix(s.G_fsdt)},
        {"equilibrium", to_json_matrix(s.G_equilibrium)}}},
      {"vam",
       {{"A_R", to_json_matrix(s.vam.A_R)},
        {"G", to_json_matrix(s.vam.G)},
        {"Fbar_top", to_json_vector(s.vam.Fbar_top)},
        {"Fbar_bottom", to_json_vector(s.vam.Fbar_bottom)},
        {"c_L", to_json_matrix(s.vam.c_L)},
        {"fit",
         {{"relative_residual", s.vam.fit.relative_residual},
          {"rank", s.vam.fit.rank},
          {"unknowns", s.vam.fit.unknowns}}}}},
  };
}

namespace {

struct Column {
  const char* name;
  double (*get)(const SectionProperties&);
};

// The entries a lay-up sweep is usually read for; full matrices are in the JSON.
const Column kColumns[] = {
    {"A11_N/mm", [](const SectionProperties& s) { return s.vam.A_R(0, 0); }},
    {"A22_N/mm", [](const SectionProperties& s) { return s.vam.A_R(2, 2); }},
    {"A12_N/mm", [](const SectionProperties& s) { return s.vam.A_R(0, 2); }},
    {"A66_N/mm", [](const SectionProperties& s) { return s.vam.A_R(1, 1); }},
    {"D11_Nmm", [](const SectionProperties& s) { return s.vam.A_R(3, 3); }},
    {"D22_Nmm", [](const SectionProperties& s) { return s.vam.A_R(5, 5); }},
    {"D12_Nmm", [](const SectionProperties& s) { return s.vam.A_R(3, 5); }},
    {"D66_Nmm", [](const SectionProperties& s) { return s.vam.A_R(4, 4); }},
    {"D16_Nmm", [](const SectionProperties& s) { return s.vam.A_R(3, 4); }},
    {"D26_Nmm", [](const SectionProperties& s) { return s.vam.A_R(5, 4); }},
    {"G11_vam_N/mm", [](const SectionProperties& s) { return s.vam.G(0, 0); }},
    {"G22_vam_N/mm", [](const SectionProperties& s) { return s.vam.G(1, 1); }},
    {"G12_vam_N/mm", [](const SectionProperties& s) { return s.vam.G(0, 1); }},
    {"G11_eq_N/mm", [](const SectionProperties& s) { return s.G_equilibrium(0, 0); }},
    {"G22_eq_N/mm", [](const SectionProperties& s) { return s.G_equilibrium(1, 1); }},
    {"G11_fsdt_N/mm", [](const SectionProperties& s) { return s.G_fsdt(0, 0); }},
    {"G22_fsdt_N/mm", [](const SectionProperties& s) { return s.G_fsdt(1, 1); }},
    {"Fbar_top_k11_mm2/MPa", [](const SectionProperties& s) { return s.vam.Fbar_top(3); }},
    {"Fbar_top_k22_mm2/MPa", [](const SectionProperties& s) { return s.vam.Fbar_top(5); }},
    {"cL_top_mm/MPa", [](const SectionProperties& s) { return s.vam.c_L(0, 0); }},
};

}  // namespace

std::string section_table_csv(const std::vector<SectionProperties>& sections) {
  std::ostringstream os;
  os.precision(10);
  os << "layup,thickness_mm";
  for (const auto& c : kColumns) os << ',' << c.name;
  os << '\n';
  for (const auto& s : sections) {
    os << '"' << s.label << '"' << ',' << s.laminate.thickness();
    for (const auto& c : kColumns) os << ',' << c.get(s);
    os << '\n';
  }
  return os.str();
}

void print_section_table(std::ostream& os, const std::vector<SectionProperties>& sections) {
  os << "lay-up           D11(N*mm)   D22(N*mm)   D12(N*mm)   D66(N*mm)   D16(N*mm)"
        "   G11(N/mm)   G22(N/mm)   G12(N/mm)  Fbar+k11(mm2/MPa)\n";
  for (const auto& s : sections) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "%-14s %11.5g %11.5g %11.5g %11.5g %11.5g %11.5g %11.5g %11.4g %12.6g\n",
                  s.label.c_str(), s.vam.A_R(3, 3), s.vam.A_R(5, 5), s.vam.A_R(3, 5),
                  s.vam.A_R(4, 4), clean(s.vam.A_R(3, 4), s.vam.A_R(3, 3)), s.vam.G(0, 0),
                  s.vam.G(1, 1), clean(s.vam.G(0, 1), s.vam.G(0, 0)), s.vam.Fbar_top(3));
    os << line;
  }
}

}  // namespace si
