// Human-readable and machine-readable reports of a section analysis. Units are printed with
// every matrix: A in N/mm, B in N, D in N*mm, G in N/mm, F-bar in mm (membrane) and mm^2
// (bending), so that F = t F-bar for a face traction t in MPa, c_L in mm/MPa.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "section/section_properties.hpp"

namespace si {

void print_section_report(std::ostream& os, const SectionProperties& s);
nlohmann::json section_to_json(const SectionProperties& s);

// One row per section, for the lay-up sweep table (CSV header + rows, and a compact text table).
std::string section_table_csv(const std::vector<SectionProperties>& sections);
void print_section_table(std::ostream& os, const std::vector<SectionProperties>& sections);

}  // namespace si
