#include "app/section_command.hpp"

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/units.hpp"
#include "io/case_file.hpp"
#include "io/laminate_reader.hpp"
#include "io/section_report.hpp"
#include "material/material_library.hpp"
#include "section/layup_notation.hpp"

namespace si {
namespace {

const Where kCommandLine{"command line", "", "", 0};

Where option_where(const char* option, const std::string& value) {
  return Where{"command line", option, value, 0};
}

Laminate laminate_from_notation(const std::string& notation, const Material& material,
                                double ply_thickness) {
  Laminate lam;
  for (double angle : parse_layup(notation))
    lam.plies.push_back(Ply{material, ply_thickness, angle});
  return lam;
}

SectionProperties section_from_options(const SectionCommandOptions& o) {
  if (o.layup.empty())
    throw_input("give a case file, or --layup with --ply-thickness (see --help)", kCommandLine);
  if (o.ply_thickness.empty())
    throw_input("--layup needs --ply-thickness, e.g. --ply-thickness \"0.475 mm\"", kCommandLine);
  Material material = [&] {
    try {
      return library_material(o.material);
    } catch (const Error& e) {
      throw e.within(option_where("--material", o.material));
    }
  }();
  double t = 0;
  try {
    t = parse_quantity(o.ply_thickness, Dimension::kLength);
  } catch (const Error& e) {
    throw e.within(option_where("--ply-thickness", o.ply_thickness));
  }
  if (!(t > 0))
    throw_input("ply thickness must be positive", option_where("--ply-thickness", o.ply_thickness));
  Laminate lam;
  try {
    lam = laminate_from_notation(o.layup, material, t);
  } catch (const Error& e) {
    throw e.within(option_where("--layup", o.layup));
  }
  try {
    lam.reference_offset = parse_reference_surface(o.reference, lam.thickness());
  } catch (const Error& e) {
    throw e.within(option_where("--reference", o.reference));
  }
  return analyze_section(lam, o.layup, VamOptions{o.vam_order, 1});
}

std::vector<SectionProperties> paper_sections(int vam_order) {
  // Source paper, Results: [theta/-theta]2S for theta = 0, 15, ..., 90 and [0/90]2S, carbon/epoxy
  // of Table 1, 3.8 mm in 8 plies.
  const Material material = library_material("paper-carbon-epoxy");
  const double ply_thickness = 3.8 / 8.0;
  std::vector<std::string> layups;
  for (int theta = 0; theta <= 90; theta += 15) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "[%d/-%d]2S", theta, theta);
    layups.emplace_back(theta == 0 ? "[0/0]2S" : buf);
  }
  layups.emplace_back("[0/90]2S");
  std::vector<SectionProperties> out;
  for (const auto& l : layups)
    out.push_back(analyze_section(laminate_from_notation(l, material, ply_thickness), l,
                                  VamOptions{vam_order, 1}));
  return out;
}

int run_paper(const SectionCommandOptions& o, std::ostream& out) {
  const auto sections = paper_sections(o.vam_order);
  out << "Section properties of the source paper's lay-ups (carbon/epoxy of its Table 1, 8 plies "
         "of 0.475 mm, mid-surface reference; VAM stiffness, Yu order)\n";
  print_section_table(out, sections);
  nlohmann::json all = nlohmann::json::array();
  for (const auto& s : sections) all.push_back(section_to_json(s));
  // Everything is computed before anything is written: no half-written results on failure.
  const std::string csv = o.out_dir + "/paper_sections.csv";
  const std::string json = o.out_dir + "/paper_sections.json";
  write_file_atomically(csv, section_table_csv(sections));
  write_file_atomically(json, all.dump(2) + "\n");
  out << "wrote " << csv << " and " << json << "\n";
  return 0;
}

}  // namespace

int run_section_command(const SectionCommandOptions& o, std::ostream& out) {
  if (o.vam_order < 2 || o.vam_order > 8)
    throw_input("VAM element order must be between 2 and 8",
                option_where("--vam-order", std::to_string(o.vam_order)));
  if (o.paper) {
    if (!o.case_file.empty() || !o.layup.empty())
      throw_input("--paper takes no case file and no --layup", kCommandLine);
    return run_paper(o, out);
  }
  SectionProperties s = [&] {
    if (!o.case_file.empty()) {
      if (!o.layup.empty())
        throw_input("give either a case file or --layup, not both", kCommandLine);
      const CaseFile c = read_case_file(o.case_file);
      return analyze_section(c.laminate, describe_laminate(c.laminate), VamOptions{o.vam_order, 1});
    }
    return section_from_options(o);
  }();
  print_section_report(out, s);
  if (!o.json_path.empty()) {
    write_file_atomically(o.json_path, section_to_json(s).dump(2) + "\n");
    out << "\nwrote " << o.json_path << "\n";
  }
  return 0;
}

namespace {

// "      strengths (MPa): X_T 1500, ...; toughness (N/mm): G_Ic 0.277, ..." or nothing.
std::string failure_properties_line(const Material& m) {
  std::ostringstream os;
  auto list = [&](const char* title, auto keys, auto get) {
    std::string items;
    for (auto key : keys)
      if (const auto v = get(key)) {
        std::ostringstream item;
        item << key_name(key) << ' ' << *v;
        items += (items.empty() ? "" : ", ") + item.str();
      }
    if (!items.empty()) os << (os.tellp() > 0 ? "; " : "      ") << title << items;
  };
  std::vector<StrengthKey> strengths;
  for (int k = 0; k < kStrengthKeys; ++k) strengths.push_back(StrengthKey(k));
  std::vector<ToughnessKey> toughness;
  for (int k = 0; k < kToughnessKeys; ++k) toughness.push_back(ToughnessKey(k));
  list("strengths (MPa): ", strengths, [&](StrengthKey k) { return m.strengths().get(k); });
  list("toughness (N/mm): ", toughness, [&](ToughnessKey k) { return m.toughness().get(k); });
  return os.tellp() > 0 ? os.str() + "\n" : "";
}

}  // namespace

int run_materials_command(std::ostream& out) {
  out << "Built-in materials (moduli in GPa):\n";
  for (const auto& name : library_material_names()) {
    const Material m = library_material(name);
    const auto& c = m.constants();
    char line[320];
    if (m.is_isotropic()) {
      std::snprintf(line, sizeof line, "  %-22s isotropic    E = %.4g, nu = %.4g\n", name.c_str(),
                    c.E1 / 1e3, c.nu12);
    } else {
      std::snprintf(line, sizeof line,
                    "  %-22s orthotropic  E1 = %.4g, E2 = %.4g, E3 = %.4g, G12 = %.4g, G13 = %.4g, "
                    "G23 = %.4g, nu12 = %.4g, nu13 = %.4g, nu23 = %.4g\n",
                    name.c_str(), c.E1 / 1e3, c.E2 / 1e3, c.E3 / 1e3, c.G12 / 1e3, c.G13 / 1e3,
                    c.G23 / 1e3, c.nu12, c.nu13, c.nu23);
    }
    out << line << failure_properties_line(m);
  }
  return 0;
}

int run_layup_command(const std::string& notation, std::ostream& out) {
  std::vector<double> angles;
  try {
    angles = parse_layup(notation);
  } catch (const Error& e) {
    throw e.within(option_where("LAYUP", notation));
  }
  out << notation << ": " << angles.size() << " plies, bottom to top:";
  for (double a : angles) out << ' ' << a;
  out << "\ncompact form: " << format_layup(angles) << "\n";
  return 0;
}

}  // namespace si
