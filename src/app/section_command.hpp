// `shellindent section`: section properties of a laminate from a case file, from command-line
// options, or (with --paper) for every lay-up of the source paper.
#pragma once

#include <ostream>
#include <string>

namespace si {

struct SectionCommandOptions {
  std::string case_file;                        // a case file, or empty
  std::string layup;                            // lay-up notation, e.g. "[45/-45]2S"
  std::string material = "paper-carbon-epoxy";  // library material for --layup
  std::string ply_thickness;                    // with unit, e.g. "0.475 mm"
  std::string reference = "mid";                // mid | bottom | top | <length from mid-surface>
  std::string json_path;                        // write the full result as JSON here
  bool paper = false;                           // the paper's lay-ups, table + files in out_dir
  std::string out_dir = "results";
  int vam_order = 4;
};

// Returns the process exit code; throws si::Error on bad input or numerical failure.
int run_section_command(const SectionCommandOptions& options, std::ostream& out);

// Names and constants of the built-in material library.
int run_materials_command(std::ostream& out);

// Expands lay-up notation ply by ply (bottom to top) and prints its compact form.
int run_layup_command(const std::string& notation, std::ostream& out);

}  // namespace si
